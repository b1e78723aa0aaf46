#pragma once
/// \file
/// Pinhole camera: maps image positions to primary rays.

#include <vector>

#include "raylab/core/ray.h"
#include "raylab/scene/camera_spec.h"

namespace raylab {

/// A pinhole camera for an image of a given size. Image coordinates are continuous pixel units:
/// (0, 0) is the top-left corner of the top-left pixel, (width, height) the bottom-right corner.
class Camera {
 public:
  /// Builds the camera frame from `spec` for a `width` x `height` image.
  Camera(const CameraSpec& spec, int width, int height);

  /// The primary ray through image position (x, y), with a unit direction (t is distance).
  Ray generate(float x, float y) const;

  /// The image position (x, y) where world point `p` appears; false when `p` is not in front
  /// of the eye (then x and y are untouched).
  bool project(Vec3 p, float& x, float& y) const;

 private:
  Vec3 m_origin;
  Vec3 m_top_left;  ///< image plane point of image position (0, 0)
  Vec3 m_dx;        ///< image plane step of one pixel to the right
  Vec3 m_dy;        ///< image plane step of one pixel down
  Vec3 m_forward;   ///< unit viewing direction (for the hither plane)
  float m_hither;   ///< distance of the near plane along m_forward
};

/// The rays of `spec`'s camera through the centre of every pixel of a `width` x `height`
/// image (both at least 1), row-major from the top row: the primary rays of one sample per pixel.
std::vector<Ray> pixel_centre_rays(const CameraSpec& spec, int width, int height);

}  // namespace raylab
