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
};

}  // namespace raylab
