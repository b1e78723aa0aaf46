#include "raylab/geometry/cylinder.h"

#include <algorithm>
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
  f.axis = {static_cast<float>(f.wx), static_cast<float>(f.wy), static_cast<float>(f.wz)};
  // A cone flatter than 45 degrees keeps the rejection off: the double test's root near a
  // tangency beyond the height range is only good to about 1e-8 of the scale, and the margin
  // (below) over 1 + |k| must stay far above that.
  f.reject_radius = std::fabs(f.k) <= 1.0 ? std::max(std::fabs(cyl.base_radius), std::fabs(cyl.apex_radius)) : INFINITY;
  return f;
}

bool intersect_cylinder(const Cylinder& cyl, const Ray& ray, float tmin, float tmax, float& t, float& height) {
  return intersect_cylinder(cylinder_frame(cyl), ray, tmin, tmax, t, height);
}

// The rejection, and why its margin is safe. With f = origin - base, the line's distance from the
// axis is D = |f . n| / |n|, n = d x w. In float, f carries a relative error of one rounding, and
// each component of n an absolute one of about 3 eps |d| (w itself is rounded once), so |n| is
// off by at most 5.2 eps |d|. Only lines at least kMinSine off the axis are judged, where
// |n| >= 0.1 |d|: n's relative error is then at most 52 eps, and f . n's absolute one about
// eps |f| (4 |n| + 5.2 |d|) <= 56 eps |f| |n|. So the float D is within 60 eps (|f| + D) of the
// exact one, about 3.6e-6 (|f| + D), and D <= |f| (the base lies on the axis), so within
// 7.2e-6 |f|. The margin, kMargin (|f|_1 + R) with |f|_1 >= |f|, is more than five times that.
// These bounds hold in float's normal range, which the magnitude checks keep to.
//
// A line beyond R plus the margin meets the frustum nowhere in its height range (every point
// there is farther than R from the axis, and no radius in the range exceeds R), so the exact
// answer is a miss. The double test could still accept a root of the infinite cone just outside
// the range if its own error in the height s reached the distance to the range, which is at
// least margin / |k|: with |k| <= 1 (the frame turns the rejection off otherwise) that is
// 4e-5 |f|, against the double root's error of 1e-16 of the scale, or 1.5e-8 near a tangency.
// So every ray rejected here is a ray the double test rejects: the answers are the double test's,
// bit for bit.
constexpr float kMinSine = detail::kCylinderRejectMinSine;
constexpr float kMargin = detail::kCylinderRejectMargin;

bool cylinder_surely_missed(const CylinderFrame& frame, const Ray& ray) {
  const Vec3 d = ray.direction;
  const float d_sq = dot(d, d);
  // Comparisons are false on NaN: such rays are never rejected here.
  if (!(d_sq >= 1e-12f && d_sq <= 1e12f)) return false;
  const Vec3 n = cross(d, frame.axis);
  const float n_sq = dot(n, n);
  if (!(n_sq >= kMinSine * kMinSine * d_sq)) return false;
  const Vec3 f = ray.origin - frame.base;
  const float along_n = dot(f, n);
  const float reach =
      frame.reject_radius + kMargin * (std::fabs(f.x) + std::fabs(f.y) + std::fabs(f.z) + frame.reject_radius);
  const float far_sq = along_n * along_n;
  // far_sq normal and finite: no underflow or overflow took the bounds away.
  return far_sq > reach * reach * n_sq && far_sq >= 1e-30f && far_sq <= 1e30f;
}

bool intersect_cylinder(const CylinderFrame& frame, const Ray& ray, float tmin, float tmax, float& t, float& height) {
  if (cylinder_surely_missed(frame, ray)) return false;
  return intersect_cylinder_exact(frame, ray, tmin, tmax, t, height);
}

bool intersect_cylinder_exact(const CylinderFrame& frame, const Ray& ray, float tmin, float tmax, float& t,
                              float& height) {
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
