#pragma once
/// \file
/// One triangle against N rays at once (N = 8 or 16): the ray-parallel form of the watertight
/// test of triangle.h, for packets whose rays share the test's axis permutation. Each lane does
/// the scalar test's operations in the same order, so lane i gives bit for bit what
/// `intersect_triangle(tri, WatertightRay(ray_i), ...)` gives.

#include "raylab/geometry/triangle_block.h"
#include "raylab/simd/wide_float.h"

namespace raylab {

/// The watertight constants of N rays that share one axis permutation (kx, ky, kz), lane by
/// lane: the origins' coordinates on the permuted axes and the shears.
template <int N>
struct WatertightRays {
  using F = simd::WideFloat<N>;
  int kx = 0, ky = 1, kz = 2;
  F ox, oy, oz;  ///< origin[kx], origin[ky], origin[kz]
  F sx, sy, sz;  ///< as WatertightRay::sx, sy, sz
};

/// Tests triangle `lane` of `block` against the N rays of `rays`, each restricted to its own
/// [tmin, tmax] (note `<=` at both ends, as `intersect_triangle_block`: the caller applies the
/// exact `t < tie_limit` rule). Returns the mask of rays hit, and their t, u, v in lanes of
/// `t_out`, `u_out`, `v_out`. A degenerate triangle is never hit.
template <int N>
inline unsigned intersect_triangle_rays(const TriangleBlock4& block, int lane, const WatertightRays<N>& rays,
                                        simd::WideFloat<N> tmin, simd::WideFloat<N> tmax, float* t_out, float* u_out,
                                        float* v_out) {
  using F = simd::WideFloat<N>;
  // Vertex k relative to the origins, on the permuted axes (as `tri.pk - wr.origin` then [k?]).
  auto rel = [&](int k, int axis, F o) { return F::broadcast(block.p[k][axis][lane]) - o; };
  const F akz = rel(0, rays.kz, rays.oz), bkz = rel(1, rays.kz, rays.oz), ckz = rel(2, rays.kz, rays.oz);
  const F ax = rel(0, rays.kx, rays.ox) - rays.sx * akz, ay = rel(0, rays.ky, rays.oy) - rays.sy * akz;
  const F bx = rel(1, rays.kx, rays.ox) - rays.sx * bkz, by = rel(1, rays.ky, rays.oy) - rays.sy * bkz;
  const F cx = rel(2, rays.kx, rays.ox) - rays.sx * ckz, cy = rel(2, rays.ky, rays.oy) - rays.sy * ckz;
  constexpr unsigned kAll = N >= 32 ? ~0u : (1u << N) - 1u;
  const F zero = F::broadcast(0.f);
  // The float filter of intersect_triangle, one lane per ray: when it rejects every ray (the
  // common case), the triangle is done.
  {
    const F p0 = cx * by, q0 = cy * bx, p1 = ax * cy, q1 = ay * cx, p2 = bx * ay, q2 = by * ax;
    const unsigned negative = less_mask(p0, q0) | less_mask(p1, q1) | less_mask(p2, q2);
    const unsigned positive = less_mask(q0, p0) | less_mask(q1, p1) | less_mask(q2, p2);
    if ((negative & positive & kAll) == kAll) return 0;
  }
  // Edge functions with exact products, rounded once to float, as in intersect_triangle.
  const F e0 = difference_of_products(cx, by, cy, bx);
  const F e1 = difference_of_products(ax, cy, ay, cx);
  const F e2 = difference_of_products(bx, ay, by, ax);
  const unsigned any_negative = less_mask(e0, zero) | less_mask(e1, zero) | less_mask(e2, zero);
  const unsigned any_positive = less_mask(zero, e0) | less_mask(zero, e1) | less_mask(zero, e2);
  const F det = e0 + e1 + e2;
  unsigned mask = ~(any_negative & any_positive) & ~equal_mask(det, zero) & kAll;
  if (mask == 0) return 0;
  const F rcp = F::broadcast(1.f) / det;
  const F th = (e0 * (rays.sz * akz) + e1 * (rays.sz * bkz) + e2 * (rays.sz * ckz)) * rcp;
  // tmin <= th <= tmax, false for NaN.
  mask &= less_equal_mask(tmin, th) & less_equal_mask(th, tmax);
  if (mask == 0) return 0;
  th.store(t_out);
  (e1 * rcp).store(u_out);
  (e2 * rcp).store(v_out);
  return mask;
}

}  // namespace raylab
