#pragma once
/// \file
/// One cylinder's float rejection against N rays at once (N = 4, 8 or 16): the ray-parallel form
/// of `cylinder_surely_missed` (cylinder.h), for packets. Each lane does its float operations in
/// the same order, so lane i gives bit for bit the scalar answer for ray i; the rays it does not
/// turn away go to `intersect_cylinder_exact` one by one.

#include "raylab/geometry/cylinder.h"
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
  unsigned judged = lanes & less_equal_mask(F::broadcast(1e-12f), d_sq) & less_equal_mask(d_sq, F::broadcast(1e12f));
  if (judged == 0) return 0;
  const F ax = F::broadcast(frame.axis.x), ay = F::broadcast(frame.axis.y), az = F::broadcast(frame.axis.z);
  // n = cross(d, axis), component by component as Vec3's cross.
  const F nx = dy * az - dz * ay, ny = dz * ax - dx * az, nz = dx * ay - dy * ax;
  const F n_sq = nx * nx + ny * ny + nz * nz;
  judged &= less_equal_mask(F::broadcast(detail::kCylinderRejectMinSine * detail::kCylinderRejectMinSine) * d_sq, n_sq);
  if (judged == 0) return 0;
  const F fx = rays.ox - F::broadcast(frame.base.x);
  const F fy = rays.oy - F::broadcast(frame.base.y);
  const F fz = rays.oz - F::broadcast(frame.base.z);
  const F along_n = fx * nx + fy * ny + fz * nz;
  const F radius = F::broadcast(frame.reject_radius);
  const F zero = F::broadcast(0.f);  // copysign(x, +0) is |x|, as std::fabs
  const F reach = radius + F::broadcast(detail::kCylinderRejectMargin) *
                               (copysign(fx, zero) + copysign(fy, zero) + copysign(fz, zero) + radius);
  const F far_sq = along_n * along_n;
  return judged & less_mask(reach * reach * n_sq, far_sq) & less_equal_mask(F::broadcast(1e-30f), far_sq) &
         less_equal_mask(far_sq, F::broadcast(1e30f));
}

RAYLAB_ISA_END
}  // namespace raylab
