#pragma once
/// \file
/// Axis-aligned bounding boxes and the slab test.

#include <limits>
#include <utility>

#include "raylab/core/ray.h"
#include "raylab/core/vec3.h"

namespace raylab {

/// An axis-aligned box [lo, hi]. The default box is empty (lo = +inf, hi = -inf), so that
/// `extend` works from it without a special case.
struct Box3 {
  Vec3 lo{std::numeric_limits<float>::infinity()};
  Vec3 hi{-std::numeric_limits<float>::infinity()};

  /// Grows the box to contain point `p`.
  constexpr void extend(Vec3 p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  /// Grows the box to contain box `b`.
  constexpr void extend(const Box3& b) {
    lo = min(lo, b.lo);
    hi = max(hi, b.hi);
  }
  /// True when the box contains no point.
  constexpr bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  /// Edge lengths (negative components for an empty box).
  constexpr Vec3 extent() const { return hi - lo; }
  /// Centre point.
  constexpr Vec3 center() const { return (lo + hi) * 0.5f; }
  /// Surface area; 0 for an empty box.
  constexpr float area() const {
    if (empty()) return 0.f;
    const Vec3 e = extent();
    return 2.f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  /// True when `p` lies inside or on the boundary.
  constexpr bool contains(Vec3 p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
};

/// The union of two boxes.
constexpr Box3 merge(const Box3& a, const Box3& b) { return {min(a.lo, b.lo), max(a.hi, b.hi)}; }

/// Reciprocal ray direction for slab tests. Divisions by +0 and -0 give +inf and -inf, which the
/// slab test handles exactly (IEEE), so no epsilon is substituted.
inline Vec3 safe_reciprocal(Vec3 d) { return {1.f / d.x, 1.f / d.y, 1.f / d.z}; }

/// Slab test of a ray (origin `o`, reciprocal direction `inv_d`) against `box`, restricted to
/// [tmin, tmax]. On a hit returns true and sets `t_enter` to the entry parameter (clamped to tmin).
/// Robust for axis-parallel rays: a 0 * inf NaN (origin on a slab plane) is discarded by the
/// min/max argument order, so a ray on a face plane counts as hitting (boxes are closed).
inline bool intersect_box(const Box3& box, Vec3 o, Vec3 inv_d, float tmin, float tmax, float& t_enter) {
  for (int a = 0; a < 3; ++a) {
    float t0 = (box.lo[a] - o[a]) * inv_d[a];
    float t1 = (box.hi[a] - o[a]) * inv_d[a];
    if (inv_d[a] < 0.f) std::swap(t0, t1);
    // std::max(x, NaN) returns x: a NaN slab (0 * inf) leaves the interval unchanged.
    tmin = t0 > tmin ? t0 : tmin;
    tmax = t1 < tmax ? t1 : tmax;
  }
  t_enter = tmin;
  return tmin <= tmax;
}

}  // namespace raylab
