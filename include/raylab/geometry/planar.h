#pragma once
/// \file
/// Planar shapes for floors and area lights: disks and parallelograms ("quads").

#include <cmath>

#include "raylab/core/box.h"
#include "raylab/core/ray.h"

namespace raylab {

/// A disk by centre, unit normal and radius (28 bytes).
struct Disk {
  Vec3 center;
  Vec3 normal{0.f, 1.f, 0.f};
  float radius = 1.f;
};

/// A parallelogram `corner + s * edge_u + t * edge_v` for s, t in [0, 1] (36 bytes).
/// Its normal is cross(edge_u, edge_v).
struct Quad {
  Vec3 corner;
  Vec3 edge_u{1.f, 0.f, 0.f};
  Vec3 edge_v{0.f, 0.f, 1.f};
};

/// Hit of `ray` with disk `d` in [tmin, tmax).
inline bool intersect_disk(const Disk& d, const Ray& ray, float tmin, float tmax, float& t) {
  const float denom = dot(ray.direction, d.normal);
  if (denom == 0.f) return false;
  const float th = dot(d.center - ray.origin, d.normal) / denom;
  if (!(th >= tmin && th < tmax)) return false;
  const Vec3 r = ray.at(th) - d.center;
  // Written to reject NaN: an infinite direction component gives th = +-0 and r = NaN, and every
  // disk not parallel to such a ray was hit at t = 0, wherever it lay.
  if (!(dot(r, r) <= d.radius * d.radius)) return false;
  t = th;
  return true;
}

/// Hit of `ray` with quad `q` in [tmin, tmax); `s`, `u` receive the parametric coordinates.
inline bool intersect_quad(const Quad& q, const Ray& ray, float tmin, float tmax, float& t, float& s, float& u) {
  const Vec3 n = cross(q.edge_u, q.edge_v);
  const float denom = dot(ray.direction, n);
  if (denom == 0.f) return false;
  const float th = dot(q.corner - ray.origin, n) / denom;
  if (!(th >= tmin && th < tmax)) return false;
  const Vec3 w = n / dot(n, n);
  const Vec3 r = ray.at(th) - q.corner;
  const float a = dot(w, cross(r, q.edge_v));
  const float b = dot(w, cross(q.edge_u, r));
  if (!(a >= 0.f && a <= 1.f && b >= 0.f && b <= 1.f)) return false;
  t = th;
  s = a;
  u = b;
  return true;
}

/// Bounding box of a disk (exact per axis: radius * sqrt(1 - n_axis^2)).
inline Box3 disk_bounds(const Disk& d) {
  const Vec3 n = d.normal;
  const Vec3 e{d.radius * std::sqrt(std::max(0.f, 1.f - n.x * n.x)),
               d.radius * std::sqrt(std::max(0.f, 1.f - n.y * n.y)),
               d.radius * std::sqrt(std::max(0.f, 1.f - n.z * n.z))};
  return {d.center - e, d.center + e};
}

/// Bounding box of a quad (its four corners).
inline Box3 quad_bounds(const Quad& q) {
  Box3 b;
  b.extend(q.corner);
  b.extend(q.corner + q.edge_u);
  b.extend(q.corner + q.edge_v);
  b.extend(q.corner + q.edge_u + q.edge_v);
  return b;
}

}  // namespace raylab
