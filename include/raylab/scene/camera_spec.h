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

}  // namespace raylab
