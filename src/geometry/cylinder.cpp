#include "raylab/geometry/cylinder.h"

#include <cmath>

namespace raylab {

CylinderFrame cylinder_frame(const Cylinder& cyl) {
  // Frame along the axis: s = height above the base, q = radial offset. The surface is
  // |q(t)| = r0 + k s(t), with k the radius change per unit height.
  CylinderFrame f;
  f.base = cyl.base;
  f.base_radius = cyl.base_radius;
  const Vec3 axis = cyl.apex - cyl.base;
  f.h = std::sqrt(double(dot(axis, axis)));
  if (f.h == 0.0) return f;
  f.wx = axis.x / f.h;
  f.wy = axis.y / f.h;
  f.wz = axis.z / f.h;
  f.k = (double(cyl.apex_radius) - cyl.base_radius) / f.h;
  return f;
}

bool intersect_cylinder(const Cylinder& cyl, const Ray& ray, float tmin, float tmax, float& t, float& height) {
  return intersect_cylinder(cylinder_frame(cyl), ray, tmin, tmax, t, height);
}

bool intersect_cylinder(const CylinderFrame& frame, const Ray& ray, float tmin, float tmax, float& t, float& height) {
  const double h = frame.h;
  if (h == 0.0) return false;
  const double wx = frame.wx, wy = frame.wy, wz = frame.wz, k = frame.k;
  const Vec3& base = frame.base;
  const double fx = double(ray.origin.x) - base.x, fy = double(ray.origin.y) - base.y,
               fz = double(ray.origin.z) - base.z;
  const double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
  const double s0 = fx * wx + fy * wy + fz * wz;
  const double ds = dx * wx + dy * wy + dz * wz;
  const double q0x = fx - s0 * wx, q0y = fy - s0 * wy, q0z = fz - s0 * wz;
  const double qdx = dx - ds * wx, qdy = dy - ds * wy, qdz = dz - ds * wz;
  const double r_at_origin = frame.base_radius + k * s0;
  const double a = qdx * qdx + qdy * qdy + qdz * qdz - k * k * ds * ds;
  const double b = 2.0 * (q0x * qdx + q0y * qdy + q0z * qdz - k * r_at_origin * ds);
  const double c = q0x * q0x + q0y * q0y + q0z * q0z - r_at_origin * r_at_origin;

  double roots[2];
  int count = 0;
  // a is quadratic in the direction, b linear, c independent of it: a is compared with |d|^2
  // alone, so that the test does not depend on the direction's length (against |b| + |c|, every
  // direction shorter than about 1e-6 counted as parallel, and got a wrong root). `<=` keeps a
  // zero direction (a = 0, b = 0) on this branch, which rejects it.
  if (std::fabs(a) <= 1e-12 * (dx * dx + dy * dy + dz * dz)) {
    if (b == 0.0) return false;
    roots[count++] = -c / b;  // ray parallel to a generating line of the cone
  } else {
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return false;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double r0 = q != 0.0 ? c / q : 0.0;
    double r1 = q / a;
    if (r0 > r1) std::swap(r0, r1);
    roots[count++] = r0;
    roots[count++] = r1;
  }
  for (int i = 0; i < count; ++i) {
    const double tr = roots[i];
    if (!(tr >= tmin && tr < tmax)) continue;
    const double s = s0 + tr * ds;
    if (s < 0.0 || s > h) continue;
    if (frame.base_radius + k * s < 0.0) continue;  // the mirror nappe of a cone
    t = static_cast<float>(tr);
    if (!(t >= tmin && t < tmax)) continue;
    height = static_cast<float>(s / h);
    return true;
  }
  return false;
}

Vec3 cylinder_normal(const Cylinder& cyl, Vec3 p) {
  const Vec3 axis = cyl.apex - cyl.base;
  const float h = length(axis);
  const Vec3 w = axis / h;
  const Vec3 rel = p - cyl.base;
  const Vec3 radial = rel - w * dot(rel, w);
  const float rl = length(radial);
  if (rl == 0.f) return w;
  // The cone's normal tilts along the axis by the slope of the radius.
  const float k = (cyl.apex_radius - cyl.base_radius) / h;
  return normalize(radial / rl - w * k);
}

Box3 cylinder_bounds(const Cylinder& cyl) {
  const Vec3 axis = cyl.apex - cyl.base;
  const float len2 = dot(axis, axis);
  Vec3 e{1.f, 1.f, 1.f};
  if (len2 > 0.f) {
    const Vec3 w = axis / std::sqrt(len2);
    e = {std::sqrt(std::max(0.f, 1.f - w.x * w.x)), std::sqrt(std::max(0.f, 1.f - w.y * w.y)),
         std::sqrt(std::max(0.f, 1.f - w.z * w.z))};
  }
  Box3 b;
  b.extend(cyl.base - e * cyl.base_radius);
  b.extend(cyl.base + e * cyl.base_radius);
  b.extend(cyl.apex - e * cyl.apex_radius);
  b.extend(cyl.apex + e * cyl.apex_radius);
  return b;
}

}  // namespace raylab
