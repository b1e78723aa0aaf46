#include "raylab/render/camera.h"

#include <cmath>
#include <numbers>

namespace raylab {

Camera::Camera(const CameraSpec& spec, int width, int height) : m_origin(spec.from) {
  const Vec3 forward = normalize(spec.at - spec.from);
  const Vec3 right = normalize(cross(forward, spec.up));
  const Vec3 up = cross(right, forward);
  const float half_height = std::tan(spec.vfov_degrees * std::numbers::pi_v<float> / 360.f);
  const float half_width = half_height * static_cast<float>(width) / static_cast<float>(height);
  m_dx = right * (2.f * half_width / static_cast<float>(width));
  m_dy = up * (-2.f * half_height / static_cast<float>(height));
  m_top_left = forward - right * half_width + up * half_height;
}

Ray Camera::generate(float x, float y) const {
  Ray r;
  r.origin = m_origin;
  r.direction = normalize(m_top_left + m_dx * x + m_dy * y);
  r.tmin = 0.f;
  return r;
}

}  // namespace raylab
