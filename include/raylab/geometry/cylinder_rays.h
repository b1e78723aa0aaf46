#pragma once
/// \file
/// One cylinder's float rejection against N rays at once (N = 4, 8 or 16): the ray-parallel form
/// of `cylinder_surely_missed` (cylinder.h), for packets. Each lane does its float operations in
/// the same order, so lane i gives bit for bit the scalar answer for ray i; the rays it does not
/// turn away go to `intersect_cylinder_exact` one by one.

#include "raylab/geometry/cylinder.h"
#include "raylab/geometry/cylinder_lanes.h"
#include "raylab/geometry/ray_lanes.h"
#include "raylab/simd/isa_namespace.h"
#include "raylab/simd/wide_float.h"

namespace raylab {
RAYLAB_ISA_BEGIN

/// The mask of the lanes of `lanes` whose ray's line surely misses the cylinder of `frame`
/// (`cylinder_surely_missed(frame, ray_i)`). Lanes outside `lanes` are 0.
template <int N>
[[gnu::always_inline]] inline unsigned cylinders_surely_missed_by_rays(const CylinderFrame& frame,
                                                                       const RayLanes<N>& rays, unsigned lanes) {
  using F = simd::WideFloat<N>;
  const F &dx = rays.dx, &dy = rays.dy, &dz = rays.dz;
  const F d_sq = dx * dx + dy * dy + dz * dz;
  // Comparisons are false on NaN: such rays are never rejected.
  const unsigned judged =
      lanes & less_equal_mask(F::broadcast(1e-12f), d_sq) & less_equal_mask(d_sq, F::broadcast(1e12f));
  const CylinderRejectLanes<N> one{F::broadcast(frame.base.x),       F::broadcast(frame.base.y),
                                   F::broadcast(frame.base.z),       F::broadcast(frame.axis.x),
                                   F::broadcast(frame.axis.y),       F::broadcast(frame.axis.z),
                                   F::broadcast(frame.reject_radius)};
  return lines_surely_missing_cylinders<N>(rays, d_sq, one, judged);
}

RAYLAB_ISA_END
}  // namespace raylab
