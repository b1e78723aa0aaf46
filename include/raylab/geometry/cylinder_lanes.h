#pragma once
/// \file
/// Cylinders stored lane by lane, with what the float rejection of cylinder.h needs, so that four
/// cylinders are turned away from one ray with SIMD: how the wide BVH tests the cylinders of a
/// leaf. The rejection is `cylinder_surely_missed` done four lanes at a time with the same float
/// operations in the same order, so each lane's answer is bit for bit the scalar one; the rays
/// it does not turn away go to `intersect_cylinder_exact` one by one.

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "raylab/core/ray.h"
#include "raylab/geometry/cylinder.h"
#include "raylab/geometry/ray_lanes.h"
#include "raylab/simd/float4.h"
#include "raylab/simd/isa_namespace.h"
#include "raylab/simd/wide_float.h"

namespace raylab {

/// Where four cylinders' rejection data lie lane by lane: four floats from each pointer.
struct CylinderLanes {
  const float* base_x;         ///< the base points' x
  const float* base_y;         ///< the base points' y
  const float* base_z;         ///< the base points' z
  const float* axis_x;         ///< the unit axes in float (CylinderFrame::axis), x
  const float* axis_y;         ///< y
  const float* axis_z;         ///< z
  const float* reject_radius;  ///< CylinderFrame::reject_radius
};

/// The rejection data of cylinders at positions 0..size()-1 (a structure's list of primitive
/// ids, position by position), as structure of arrays, with 3 positions of padding at the end so
/// that four lanes load from any position. Positions that hold no cylinder hold zeros; callers
/// leave them out with their lane mask.
class CylinderLaneArrays {
 public:
  /// `positions` positions of zeros (and the padding); none for 0.
  void assign(std::size_t positions) {
    for (std::vector<float>* lane : lanes()) lane->assign(positions == 0 ? 0 : positions + 3, 0.f);
  }
  /// Puts the rejection data of `frame` at position `at`.
  void set(std::size_t at, const CylinderFrame& frame) {
    m_base_x[at] = frame.base.x;
    m_base_y[at] = frame.base.y;
    m_base_z[at] = frame.base.z;
    m_axis_x[at] = frame.axis.x;
    m_axis_y[at] = frame.axis.y;
    m_axis_z[at] = frame.axis.z;
    m_reject_radius[at] = frame.reject_radius;
  }
  /// The four lanes from position `at`.
  CylinderLanes at(std::size_t at) const {
    return {m_base_x.data() + at, m_base_y.data() + at, m_base_z.data() + at,       m_axis_x.data() + at,
            m_axis_y.data() + at, m_axis_z.data() + at, m_reject_radius.data() + at};
  }
  /// Whether nothing is stored.
  bool empty() const { return m_reject_radius.empty(); }
  /// Bytes held.
  std::size_t bytes() const { return 7 * m_reject_radius.size() * sizeof(float); }
  /// Whether position `at` holds the rejection data of `frame` bit for bit, NaN included (for
  /// structure checks).
  bool holds(std::size_t at, const CylinderFrame& frame) const {
    const auto same = [](float a, float b) {
      return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
    };
    return same(m_base_x[at], frame.base.x) && same(m_base_y[at], frame.base.y) && same(m_base_z[at], frame.base.z) &&
           same(m_axis_x[at], frame.axis.x) && same(m_axis_y[at], frame.axis.y) && same(m_axis_z[at], frame.axis.z) &&
           same(m_reject_radius[at], frame.reject_radius);
  }
  /// Positions stored, padding included.
  std::size_t size() const { return m_reject_radius.size(); }

 private:
  std::vector<std::vector<float>*> lanes() {
    return {&m_base_x, &m_base_y, &m_base_z, &m_axis_x, &m_axis_y, &m_axis_z, &m_reject_radius};
  }
  std::vector<float> m_base_x, m_base_y, m_base_z, m_axis_x, m_axis_y, m_axis_z, m_reject_radius;
};

RAYLAB_ISA_BEGIN

/// What the float rejection needs of cylinders, lane by lane (broadcast where the lanes share one).
template <int N>
struct CylinderRejectLanes {
  simd::WideFloat<N> base_x, base_y, base_z;  ///< the base points
  simd::WideFloat<N> axis_x, axis_y, axis_z;  ///< the unit axes in float (CylinderFrame::axis)
  simd::WideFloat<N> reject_radius;           ///< CylinderFrame::reject_radius
};

/// `cylinder_surely_missed`'s rule lane by lane, each lane a (ray, cylinder) pair: the mask of
/// the lanes of `judged` whose line surely misses the cylinder. `d_sq` is each lane's squared
/// direction length, and `judged` holds only lanes where it lies in [1e-12, 1e12] (the caller
/// tests that, once for a ray or lane by lane). The float operations and their order are the
/// scalar rule's (the cross product and dot products component by component as Vec3's, |x| as
/// copysign(x, +0)), so each lane's answer is the scalar one bit for bit. The one rule of both
/// forms: four cylinders against one ray, and one cylinder against N rays (cylinder_rays.h).
template <int N>
[[gnu::always_inline]] inline unsigned lines_surely_missing_cylinders(const RayLanes<N>& rays,
                                                                      const simd::WideFloat<N>& d_sq,
                                                                      const CylinderRejectLanes<N>& cylinders,
                                                                      unsigned judged) {
  using F = simd::WideFloat<N>;
  if (judged == 0) return 0;
  const F &dx = rays.dx, &dy = rays.dy, &dz = rays.dz;
  const F &ax = cylinders.axis_x, &ay = cylinders.axis_y, &az = cylinders.axis_z;
  // n = cross(d, axis), component by component as Vec3's cross.
  const F nx = dy * az - dz * ay, ny = dz * ax - dx * az, nz = dx * ay - dy * ax;
  const F n_sq = nx * nx + ny * ny + nz * nz;
  // Comparisons are false on NaN: such lanes are never rejected.
  judged &= less_equal_mask(F::broadcast(detail::kCylinderRejectMinSine * detail::kCylinderRejectMinSine) * d_sq, n_sq);
  if (judged == 0) return 0;
  const F fx = rays.ox - cylinders.base_x;
  const F fy = rays.oy - cylinders.base_y;
  const F fz = rays.oz - cylinders.base_z;
  const F along_n = fx * nx + fy * ny + fz * nz;
  const F& radius = cylinders.reject_radius;
  const F zero = F::broadcast(0.f);  // copysign(x, +0) is |x|, as std::fabs
  const F reach = radius + F::broadcast(detail::kCylinderRejectMargin) *
                               (copysign(fx, zero) + copysign(fy, zero) + copysign(fz, zero) + radius);
  const F far_sq = along_n * along_n;
  return judged & less_mask(reach * reach * n_sq, far_sq) & less_equal_mask(F::broadcast(1e-30f), far_sq) &
         less_equal_mask(far_sq, F::broadcast(1e30f));
}

/// `cylinder_surely_missed` on the lanes `lanes` of `cylinders`: the mask of the lanes whose
/// cylinder the line of `ray` surely misses. Lanes outside `lanes` are 0.
[[gnu::always_inline]] inline int cylinders_surely_missed(const CylinderLanes& cylinders, int lanes, const Ray& ray) {
  using simd::Float4;
  const Vec3 d = ray.direction;
  const float d_sq = dot(d, d);
  // Comparisons are false on NaN: such rays are never rejected.
  if (!(d_sq >= 1e-12f && d_sq <= 1e12f)) return 0;
  const RayLanes<4> line{Float4::broadcast(ray.origin.x), Float4::broadcast(ray.origin.y),
                         Float4::broadcast(ray.origin.z), Float4::broadcast(d.x),
                         Float4::broadcast(d.y),          Float4::broadcast(d.z)};
  const CylinderRejectLanes<4> four{Float4::load(cylinders.base_x),       Float4::load(cylinders.base_y),
                                    Float4::load(cylinders.base_z),       Float4::load(cylinders.axis_x),
                                    Float4::load(cylinders.axis_y),       Float4::load(cylinders.axis_z),
                                    Float4::load(cylinders.reject_radius)};
  return static_cast<int>(
      lines_surely_missing_cylinders<4>(line, Float4::broadcast(d_sq), four, static_cast<unsigned>(lanes)));
}

RAYLAB_ISA_END
}  // namespace raylab
