#pragma once
/// \file
/// The pinhole camera as a scene describes it.

#include "raylab/core/vec3.h"

namespace raylab {

/// A pinhole camera: eye position, look-at point, up vector and vertical field of view.
/// The aspect ratio comes from the image size.
struct CameraSpec {
  Vec3 from{0.f, 0.f, 5.f};
  Vec3 at{0.f, 0.f, 0.f};
  Vec3 up{0.f, 1.f, 0.f};
  float vfov_degrees = 45.f;
  /// What `vfov_degrees` spans vertically: the whole image from top edge to bottom edge, or, as
  /// NFF defines its `angle`, from the centre of the top pixel row to the centre of the bottom row.
  enum class FovSpan { kImageEdges, kPixelCentres } fov_span = FovSpan::kImageEdges;
  /// Distance of the near (hither) plane from the eye, along the viewing direction: eye rays
  /// start there (NFF `hither`).
  float hither = 0.f;
  /// The width / height ratio the field of view was chosen for; 0 for the image's own. An image
  /// narrower than this widens its vertical view so that the horizontal extent framed for this
  /// ratio stays in the picture (set by set_image_size, raylab/render/image_size.h): a change of
  /// image shape never crops the subject.
  float framed_aspect = 0.f;
};

/// Why a camera cannot render, if it cannot: its eye is the point it looks at (no viewing
/// direction), or its up is zero or along the viewing direction (no sideways direction).
enum class CameraFault { kNone, kEyeAtTarget, kUpAlongView };

/// The one test of a camera that cannot render, for every reader of cameras (scene files, the
/// command line's camera flags) to word in its own terms.
inline CameraFault camera_fault(const CameraSpec& c) {
  const Vec3 forward = c.at - c.from;
  if (!(dot(forward, forward) > 0.f)) return CameraFault::kEyeAtTarget;
  const Vec3 side = cross(forward, c.up);
  return dot(side, side) > 0.f ? CameraFault::kNone : CameraFault::kUpAlongView;
}

}  // namespace raylab
