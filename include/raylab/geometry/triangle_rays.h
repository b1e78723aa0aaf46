#pragma once
/// \file
/// One triangle against N rays at once (N = 8 or 16): the ray-parallel form of the watertight
/// test of triangle.h, for packets whose rays share the test's axis permutation. Each lane does
/// the scalar test's operations in the same order, so lane i gives bit for bit what
/// `intersect_triangle(tri, WatertightRay(ray_i), ...)` gives.

#include "raylab/geometry/triangle_block.h"
#include "raylab/simd/isa_namespace.h"
#include "raylab/simd/wide_float.h"

namespace raylab {
RAYLAB_ISA_BEGIN

/// The watertight constants of N rays that share one axis permutation (kx, ky, kz), lane by
/// lane: the origins' coordinates on the permuted axes and the shears.
template <int N>
struct WatertightRays {
  using F = simd::WideFloat<N>;
  int kx = 0, ky = 1, kz = 2;
  F ox, oy, oz;  ///< origin[kx], origin[ky], origin[kz]
  F sx, sy, sz;  ///< as WatertightRay::sx, sy, sz
};

/// The constants of the N rays `r[0..N)` as lanes. They must share r[0]'s axis permutation.
template <int N>
inline WatertightRays<N> watertight_rays(const WatertightRay* r) {
  using F = simd::WideFloat<N>;
  alignas(64) float lanes[6][N];
  for (int i = 0; i < N; ++i) {
    lanes[0][i] = r[i].origin[r[0].kx];
    lanes[1][i] = r[i].origin[r[0].ky];
    lanes[2][i] = r[i].origin[r[0].kz];
    lanes[3][i] = r[i].sx;
    lanes[4][i] = r[i].sy;
    lanes[5][i] = r[i].sz;
  }
  WatertightRays<N> w;
  w.kx = r[0].kx;
  w.ky = r[0].ky;
  w.kz = r[0].kz;
  w.ox = F::load(lanes[0]);
  w.oy = F::load(lanes[1]);
  w.oz = F::load(lanes[2]);
  w.sx = F::load(lanes[3]);
  w.sy = F::load(lanes[4]);
  w.sz = F::load(lanes[5]);
  return w;
}

/// Ray `i` of `rays` on its own, as `WatertightRay(ray_i)` gives it (bit for bit, so the scalar
/// code of the tie rule sees what the lanes see).
template <int N>
inline WatertightRay watertight_ray(const WatertightRays<N>& rays, int i) {
  alignas(64) float lanes[6][N];
  rays.ox.store(lanes[0]);
  rays.oy.store(lanes[1]);
  rays.oz.store(lanes[2]);
  rays.sx.store(lanes[3]);
  rays.sy.store(lanes[4]);
  rays.sz.store(lanes[5]);
  WatertightRay r;
  r.kx = rays.kx;
  r.ky = rays.ky;
  r.kz = rays.kz;
  r.origin[r.kx] = lanes[0][i];
  r.origin[r.ky] = lanes[1][i];
  r.origin[r.kz] = lanes[2][i];
  r.sx = lanes[3][i];
  r.sy = lanes[4][i];
  r.sz = lanes[5][i];
  return r;
}

/// The rays among `ties` of `rays` for which the tie rule rejects triangle `lane` of `block`, for
/// `finish_watertight`.
template <int N>
[[gnu::noinline]] unsigned rays_rejected_by_ties(unsigned ties, const TriangleBlock4& block, int lane,
                                                 const WatertightRays<N>& rays) {
  const Triangle tri = block.triangle(lane);
  return lanes_where(ties, [&](int i) { return tie_rule_rejects(tri, watertight_ray(rays, i)); });
}

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
  // The float filter, one lane per ray: when it rejects every ray (the common case), the
  // triangle is done.
  if ((lanes_beside(ax, ay, bx, by, cx, cy) & kAll) == kAll) return 0;
  // Edge functions with exact products, rounded once to float, as in intersect_triangle.
  const F e0 = difference_of_products(cx, by, cy, bx);
  const F e1 = difference_of_products(ax, cy, ay, cx);
  const F e2 = difference_of_products(bx, ay, by, ax);
  return finish_watertight(kAll, e0, e1, e2, rays.sz * akz, rays.sz * bkz, rays.sz * ckz, tmin, tmax, t_out, u_out,
                           v_out, [&](unsigned ties) { return rays_rejected_by_ties(ties, block, lane, rays); });
}

RAYLAB_ISA_END
}  // namespace raylab
