#pragma once
/// \file
/// One sphere against N rays at once (N = 4, 8 or 16): the ray-parallel form of the sphere test
/// of sphere.h, for packets, as triangle_rays.h is for triangles. Each lane does
/// `intersect_sphere`'s float operations in the same order, so lane i gives bit for bit what
/// `intersect_sphere` gives for ray i.

#include <bit>
#include <cmath>

#include "raylab/geometry/ray_lanes.h"
#include "raylab/geometry/sphere.h"
#include "raylab/simd/isa_namespace.h"
#include "raylab/simd/wide_float.h"

namespace raylab {
RAYLAB_ISA_BEGIN

/// `intersect_sphere(sphere, ray_i, tmin_i, tmax_i, t)` for each lane i of `lanes`: the mask of
/// the lanes hit, and in t_out[i] each such lane's distance (the nearer root when it lies in
/// the lane's interval, else the farther). Lanes whose discriminant overflows float go to
/// intersect_sphere itself (its fallback for them is not worth a vector path). As with
/// intersect_sphere_lanes, a caller with a tie rule may pass any limit at least the one the rule
/// applies and check `t < limit` lane by lane: the answer is the same.
template <int N>
[[gnu::always_inline]] inline unsigned intersect_sphere_rays(const Sphere& sphere, const RayLanes<N>& rays,
                                                             unsigned lanes, const simd::WideFloat<N>& tmin,
                                                             const simd::WideFloat<N>& tmax, float* t_out) {
  using F = simd::WideFloat<N>;
  // A radius whose square is not positive: no hit for any ray (intersect_sphere's first test).
  if (!(sphere.radius * sphere.radius > 0.f)) return 0;
  const F zero = F::broadcast(0.f);
  const F r2 = F::broadcast(sphere.radius * sphere.radius);
  const F &dx = rays.dx, &dy = rays.dy, &dz = rays.dz;
  const F a = dx * dx + dy * dy + dz * dz;
  const F fx = rays.ox - F::broadcast(sphere.center.x);
  const F fy = rays.oy - F::broadcast(sphere.center.y);
  const F fz = rays.oz - F::broadcast(sphere.center.z);
  const F b = fx * dx + fy * dy + fz * dz;
  const F c = (fx * fx + fy * fy + fz * fz) - r2;
  const F b_over_a = b / a;
  const F lx = fx - dx * b_over_a, ly = fy - dy * b_over_a, lz = fz - dz * b_over_a;
  const F disc = a * (r2 - (lx * lx + ly * ly + lz * lz));
  // A negative (or NaN) discriminant: no hit.
  const unsigned live = lanes & less_equal_mask(zero, disc);
  if (live == 0) return 0;
  const unsigned overflow = live & equal_mask(disc, F::broadcast(INFINITY));
  // -b as b * -1, which flips the sign of a zero as negation does (0 - b would not).
  const F q = b * F::broadcast(-1.f) - copysign(sqrt(disc), b);
  const F t0 = c / q, t1 = q / a;
  // intersect_sphere's `if (t0 > t1) swap`: min and max take their second operand on NaN.
  const F near = min(t1, t0), far = max(t0, t1);
  const unsigned near_in = less_equal_mask(tmin, near) & less_mask(near, tmax);
  const unsigned far_in = less_equal_mask(tmin, far) & less_mask(far, tmax);
  unsigned hit = live & ~overflow & (near_in | far_in);
  if (hit != 0) {
    alignas(64) float near_t[N], far_t[N];
    near.store(near_t);
    far.store(far_t);
    for (unsigned m = hit; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      t_out[i] = (near_in >> i) & 1u ? near_t[i] : far_t[i];
    }
  }
  if (overflow != 0) [[unlikely]] {
    alignas(64) float lo[N], hi[N];
    tmin.store(lo);
    tmax.store(hi);
    for (unsigned m = overflow; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (intersect_sphere(sphere, rays.ray(i), lo[i], hi[i], t_out[i])) hit |= 1u << i;
    }
  }
  return hit;
}

RAYLAB_ISA_END
}  // namespace raylab
