#include "shape_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace raylab::detail {

namespace {
constexpr float kPi = std::numbers::pi_v<float>;
}  // namespace

Vec3 point_on_sphere(Vec3 center, float radius, float u, float v) {
  const float z = 1.f - 2.f * u;
  const float r = std::sqrt(std::max(0.f, 1.f - z * z));
  const float phi = 6.2831853f * v;
  return center + Vec3{r * std::cos(phi), r * std::sin(phi), z} * radius;
}

SurfacePoint sample_triangle(const Triangle& t, Sample2 u) {
  // The square folded onto the triangle along its diagonal: uniform, and cheaper than the
  // square-root warp.
  float b1 = u.x, b2 = u.y;
  if (b1 + b2 > 1.f) {
    b1 = 1.f - b1;
    b2 = 1.f - b2;
  }
  const Vec3 e1 = t.p1 - t.p0, e2 = t.p2 - t.p0;
  return {t.p0 + e1 * b1 + e2 * b2, normalize(cross(e1, e2))};
}

SurfacePoint sample_sphere(const Sphere& s, Sample2 u) {
  const Vec3 p = point_on_sphere(s.center, s.radius, u.x, u.y);
  return {p, normalize(p - s.center)};
}

SurfacePoint sample_disk(const Disk& d, Sample2 u) {
  Vec3 t, b;
  orthonormal_basis(d.normal, t, b);
  const float r = d.radius * std::sqrt(u.x);
  const float phi = 2.f * kPi * u.y;
  return {d.center + (t * std::cos(phi) + b * std::sin(phi)) * r, d.normal};
}

SurfacePoint sample_quad(const Quad& q, Sample2 u) {
  return {q.corner + q.edge_u * u.x + q.edge_v * u.y, normalize(cross(q.edge_u, q.edge_v))};
}

SurfacePoint sample_cylinder(const Cylinder& c, Sample2 u) {
  const Vec3 axis = c.apex - c.base;
  const float h = length(axis);
  const Vec3 w = axis / h;
  Vec3 t, b;
  orthonormal_basis(w, t, b);
  // The area between heights 0 and s (as fractions of h) grows as 2 r0 s + (r1 - r0) s^2: its
  // inverse, written with the conjugate so that it stays exact when r0 = r1 (a cylinder).
  const float r0 = c.base_radius, r1 = c.apex_radius;
  const float sum = r0 + r1;
  const float s = u.x * sum / (r0 + std::sqrt(std::max(0.f, r0 * r0 + u.x * (r1 * r1 - r0 * r0))));
  const float r = r0 + (r1 - r0) * s;
  const float phi = 2.f * kPi * u.y;
  const Vec3 p = c.base + w * (h * s) + (t * std::cos(phi) + b * std::sin(phi)) * r;
  return {p, cylinder_normal(c, p)};
}

float triangle_area(const Triangle& t) { return 0.5f * length(cross(t.p1 - t.p0, t.p2 - t.p0)); }
float sphere_area(const Sphere& s) { return 4.f * kPi * s.radius * s.radius; }
float disk_area(const Disk& d) { return kPi * d.radius * d.radius; }
float quad_area(const Quad& q) { return length(cross(q.edge_u, q.edge_v)); }
float cylinder_area(const Cylinder& c) {
  const float h = length(c.apex - c.base);
  const float dr = c.apex_radius - c.base_radius;
  return kPi * (c.base_radius + c.apex_radius) * std::sqrt(h * h + dr * dr);
}

}  // namespace raylab::detail
