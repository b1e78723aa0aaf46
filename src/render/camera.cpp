#include "raylab/render/camera.h"

#include <cmath>
#include <numbers>

namespace raylab {

Camera::Camera(const CameraSpec& spec, int width, int height) : m_origin(spec.from), m_hither(spec.hither) {
  const Vec3 forward = normalize(spec.at - spec.from);
  m_forward = forward;
  const Vec3 right = normalize(cross(forward, spec.up));
  const Vec3 up = cross(right, forward);
  float half_height = std::tan(spec.vfov_degrees * std::numbers::pi_v<float> / 360.f);
  // NFF's angle reaches from the centre of the top pixel row to the centre of the bottom one,
  // (height - 1) pixels; the image plane spans `height` pixels. Pixels are square.
  if (spec.fov_span == CameraSpec::FovSpan::kPixelCentres && height > 1) {
    half_height *= static_cast<float>(height) / static_cast<float>(height - 1);
  }
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  // Narrower than framed: the horizontal extent of the framed shape stays, the vertical grows.
  if (spec.framed_aspect > aspect) half_height *= spec.framed_aspect / aspect;
  const float half_width = half_height * static_cast<float>(width) / static_cast<float>(height);
  m_dx = right * (2.f * half_width / static_cast<float>(width));
  m_dy = up * (-2.f * half_height / static_cast<float>(height));
  m_top_left = forward - right * half_width + up * half_height;
}

Ray Camera::generate(float x, float y) const {
  Ray r;
  r.origin = m_origin;
  r.direction = normalize(m_top_left + m_dx * x + m_dy * y);
  // Start on the hither plane: distance along the ray to a plane `m_hither` ahead of the eye.
  r.tmin = m_hither > 0.f ? m_hither / dot(r.direction, m_forward) : 0.f;
  return r;
}

bool Camera::project(Vec3 p, float& x, float& y) const {
  const Vec3 d = p - m_origin;
  const float depth = dot(d, m_forward);
  if (!(depth > 0.f)) return false;
  // m_top_left + m_dx x + m_dy y is the point at depth 1 on the ray through (x, y), and m_dx,
  // m_dy are perpendicular to each other and to the view direction.
  const Vec3 q = d / depth - m_top_left;
  x = dot(q, m_dx) / dot(m_dx, m_dx);
  y = dot(q, m_dy) / dot(m_dy, m_dy);
  return true;
}

std::vector<Ray> pixel_centre_rays(const CameraSpec& spec, int width, int height) {
  const Camera camera(spec, width, height);
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      rays.push_back(camera.generate(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
  }
  return rays;
}

}  // namespace raylab
