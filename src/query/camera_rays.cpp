#include "raylab/query/camera_rays.h"

#include <stdexcept>
#include <string>

#include "raylab/render/camera.h"

namespace raylab {

void pinhole_rays(const CameraSpec& camera, int width, int height, std::span<float> out) {
  if (width < 1 || height < 1) {
    throw std::invalid_argument("pinhole_rays: width and height must be at least 1, got " + std::to_string(width) +
                                " x " + std::to_string(height));
  }
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (out.size() != count * 6) {
    throw std::invalid_argument("pinhole_rays: the output holds " + std::to_string(out.size()) + " floats, " +
                                std::to_string(count * 6) + " needed");
  }
  std::size_t at = 0;
  for (const Ray& ray : pixel_centre_rays(camera, width, height)) {
    for (int a = 0; a < 3; ++a) out[at + static_cast<std::size_t>(a)] = ray.origin[a];
    for (int a = 0; a < 3; ++a) out[at + 3 + static_cast<std::size_t>(a)] = ray.direction[a];
    at += 6;
  }
}

}  // namespace raylab
