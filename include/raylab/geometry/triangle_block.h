#pragma once
/// \file
/// Four triangles stored lane by lane, tested against one ray with SIMD: the leaf format of the
/// wide BVH. The test is the watertight test of triangle.h done four lanes at a time with the
/// same operations in the same order, so each lane gives bit for bit what `intersect_triangle`
/// gives for that triangle.

#include <bit>
#include <cstdint>
#include <limits>

#include "raylab/geometry/triangle.h"
#include "raylab/simd/double4.h"
#include "raylab/simd/float4.h"
#include "raylab/simd/isa_namespace.h"

namespace raylab {

/// Four triangles, structure of arrays: `p[vertex][axis][lane]`, and the primitive id of each
/// lane. An unused lane has id kNoPrimitive, which callers skip; its vertices are all at the
/// origin (a degenerate triangle, never hit) or, after `repeat_first_lane`, lane 0's triangle
/// again, which costs the test nothing extra (a lane at the origin passes the test's float
/// filter, and so sends every ray on to the exact edge functions). 160 bytes.
struct alignas(16) TriangleBlock4 {
  /// The id of an unused lane.
  static constexpr std::uint32_t kNoPrimitive = std::numeric_limits<std::uint32_t>::max();

  float p[3][3][4];
  std::uint32_t id[4];

  /// Stores `tri` with primitive id `prim_id` in lane `lane`.
  void set(int lane, const Triangle& tri, std::uint32_t prim_id) {
    const Vec3* v[3] = {&tri.p0, &tri.p1, &tri.p2};
    for (int k = 0; k < 3; ++k) {
      for (int a = 0; a < 3; ++a) p[k][a][lane] = (*v[k])[a];
    }
    id[lane] = prim_id;
  }
  /// Gives the unused lanes lane 0's vertices (their ids stay kNoPrimitive), so that the test
  /// of the block needs the exact edge functions only when lane 0 does. Lane 0 must be used.
  void repeat_first_lane() {
    for (int lane = 1; lane < 4; ++lane) {
      if (id[lane] != kNoPrimitive) continue;
      for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) p[k][a][lane] = p[k][a][0];
      }
    }
  }
  /// Triangle of lane `lane`.
  Triangle triangle(int lane) const {
    Triangle t;
    t.p0 = {p[0][0][lane], p[0][1][lane], p[0][2][lane]};
    t.p1 = {p[1][0][lane], p[1][1][lane], p[1][2][lane]};
    t.p2 = {p[2][0][lane], p[2][1][lane], p[2][2][lane]};
    return t;
  }
};
static_assert(sizeof(TriangleBlock4) == 160, "TriangleBlock4 must stay 160 bytes");

/// An empty block: every lane unused.
inline TriangleBlock4 empty_triangle_block() {
  TriangleBlock4 b{};
  for (int i = 0; i < 4; ++i) b.id[i] = TriangleBlock4::kNoPrimitive;
  return b;
}

RAYLAB_ISA_BEGIN

/// The float filter of `intersect_triangle` lane by lane, from the sheared vertices (a, b, c on
/// the permuted x and y axes): the mask of lanes whose ray surely passes beside the triangle
/// (see `beside_in_float`: it decides only from exact signs that are not zero, so it agrees with
/// the tie rule too). Shared by the block and the ray-parallel kernels.
template <class F>
inline auto lanes_beside(const F& ax, const F& ay, const F& bx, const F& by, const F& cx, const F& cy) {
  const F p0 = cx * by, q0 = cy * bx, p1 = ax * cy, q1 = ay * cx, p2 = bx * ay, q2 = by * ax;
  const auto negative = less_mask(p0, q0) | less_mask(p1, q1) | less_mask(p2, q2);
  const auto positive = less_mask(q0, p0) | less_mask(q1, p1) | less_mask(q2, p2);
  return negative & positive;
}

/// The lanes among `lanes` for which `test(lane)` holds, in scalar code.
template <class Mask, class Test>
inline Mask lanes_where(Mask lanes, const Test& test) {
  Mask result = 0;
  for (unsigned m = static_cast<unsigned>(lanes); m != 0; m &= m - 1) {
    const int i = std::countr_zero(m);
    if (test(i)) result |= Mask(1) << i;
  }
  return result;
}

/// The end of the watertight test lane by lane, shared by the block and the ray-parallel
/// kernels, with the operations of `intersect_triangle` in its order: from the exact edge
/// functions e0, e1, e2 and the sheared z of the vertices (az, bz, cz), the mask of the lanes
/// among `lanes` whose ray crosses the triangle (no two signs differ, det != 0, and the tie rule
/// does not reject it) at tmin <= t <= tmax, their t, u, v stored to t_out, u_out, v_out (other
/// lanes' too). `rejected_by_ties(ties)` gives the lanes among `ties` (lanes hit with an edge
/// function exactly zero) that the tie rule rejects: `tie_rule_rejects` lane by lane, in a
/// function that is not inlined, so that the kernels stay small enough to be inlined into the
/// traversal loops (with the loop inlined, GCC called the block test out of line: about 10% more
/// instructions in single-ray traversal).
template <class F, class Mask, class TieRule>
inline Mask finish_watertight(Mask lanes, const F& e0, const F& e1, const F& e2, const F& az, const F& bz, const F& cz,
                              const F& tmin, const F& tmax, float* t_out, float* u_out, float* v_out,
                              const TieRule& rejected_by_ties) {
  const F zero = F::broadcast(0.f);
  const Mask any_negative = less_mask(e0, zero) | less_mask(e1, zero) | less_mask(e2, zero);
  const Mask any_positive = less_mask(zero, e0) | less_mask(zero, e1) | less_mask(zero, e2);
  const F det = e0 + e1 + e2;
  Mask mask = ~(any_negative & any_positive) & ~equal_mask(det, zero) & lanes;
  if (mask == 0) return 0;
  const F rcp = F::broadcast(1.f) / det;
  const F th = (e0 * az + e1 * bz + e2 * cz) * rcp;
  // tmin <= th <= tmax, false for NaN.
  mask &= less_equal_mask(tmin, th) & less_equal_mask(th, tmax);
  if (mask == 0) return 0;
  th.store(t_out);
  (e1 * rcp).store(u_out);
  (e2 * rcp).store(v_out);
  // The tie rule, as in intersect_triangle, for lanes still hit with an edge function exactly
  // zero, found as there by a zero product of the three. It can only clear lanes, and it comes
  // after the stores so that no vector is live across its (rare) call. One compare instead of
  // three: this runs for every block a ray hits.
  const Mask ties = equal_mask(e0 * e1 * e2, zero) & mask;
  if (ties != 0) [[unlikely]]
    mask &= ~rejected_by_ties(ties);
  return mask;
}

/// The lanes among `ties` of `block` whose triangle the tie rule rejects for `wr`, for
/// `finish_watertight`.
[[gnu::noinline]] inline int block_lanes_rejected_by_ties(int ties, const TriangleBlock4& block,
                                                          const WatertightRay& wr) {
  return lanes_where(ties, [&](int lane) { return tie_rule_rejects(block.triangle(lane), wr); });
}

/// The watertight test of `intersect_triangle` on the four lanes of `block`. Returns a bit mask
/// of the lanes hit with tmin <= t <= tmax (note: `<=`, so the caller can apply the exact
/// `t < tie_limit` rule lane by lane), and their t, u, v. Degenerate lanes (unused ones at the
/// origin among them) are never set; an unused lane that repeats lane 0 answers as lane 0. Lanes
/// are not checked against their ids: the caller skips kNoPrimitive and ids of other kinds.
inline int intersect_triangle_block(const TriangleBlock4& block, const WatertightRay& wr, float tmin, float tmax,
                                    float t_out[4], float u_out[4], float v_out[4]) {
  using simd::Double4;
  using simd::Float4;
  const Float4 ox = Float4::broadcast(wr.origin[wr.kx]), oy = Float4::broadcast(wr.origin[wr.ky]),
               oz = Float4::broadcast(wr.origin[wr.kz]);
  const Float4 sx = Float4::broadcast(wr.sx), sy = Float4::broadcast(wr.sy), sz = Float4::broadcast(wr.sz);
  // Vertex k relative to the origin, on the permuted axes (as `tri.pk - wr.origin` then [k?]).
  auto rel = [&](int k, int axis, Float4 o) { return Float4::load(block.p[k][axis]) - o; };
  const Float4 akz = rel(0, wr.kz, oz), bkz = rel(1, wr.kz, oz), ckz = rel(2, wr.kz, oz);
  const Float4 ax = rel(0, wr.kx, ox) - sx * akz, ay = rel(0, wr.ky, oy) - sy * akz;
  const Float4 bx = rel(1, wr.kx, ox) - sx * bkz, by = rel(1, wr.ky, oy) - sy * bkz;
  const Float4 cx = rel(2, wr.kx, ox) - sx * ckz, cy = rel(2, wr.ky, oy) - sy * ckz;
  // The float filter, four lanes at once: lanes it rejects are rejected by the exact test too,
  // and when it rejects all four (the common case) the block is done.
  if ((lanes_beside(ax, ay, bx, by, cx, cy) & 0xF) == 0xF) return 0;
  // Edge functions with exact products, rounded once to float, as in intersect_triangle.
  const Double4 dax = Double4::from(ax), day = Double4::from(ay), dbx = Double4::from(bx), dby = Double4::from(by),
                dcx = Double4::from(cx), dcy = Double4::from(cy);
  const Float4 e0 = (dcx * dby - dcy * dbx).to_float();
  const Float4 e1 = (dax * dcy - day * dcx).to_float();
  const Float4 e2 = (dbx * day - dby * dax).to_float();
  return finish_watertight(0xF, e0, e1, e2, sz * akz, sz * bkz, sz * ckz, Float4::broadcast(tmin),
                           Float4::broadcast(tmax), t_out, u_out, v_out,
                           [&](int ties) { return block_lanes_rejected_by_ties(ties, block, wr); });
}

RAYLAB_ISA_END
}  // namespace raylab
