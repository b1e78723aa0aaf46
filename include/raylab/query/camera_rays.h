#pragma once
/// \file
/// Camera rays as flat arrays, for programs that trace their own rays through RayQuery.

#include <span>

#include "raylab/scene/camera_spec.h"

namespace raylab {

/// The primary rays of the pinhole camera `camera` through the centre of every pixel of a
/// `width` x `height` image, row-major from the top row, exactly as the renderer generates
/// them: six floats per ray (origin x, y, z, then the unit direction x, y, z) written to `out`,
/// which must hold width * height * 6 floats. Throws std::invalid_argument for a size below 1
/// or an `out` of the wrong size.
void pinhole_rays(const CameraSpec& camera, int width, int height, std::span<float> out);

}  // namespace raylab
