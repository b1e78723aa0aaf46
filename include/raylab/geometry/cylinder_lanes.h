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
#include "raylab/simd/float4.h"
#include "raylab/simd/isa_namespace.h"

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

/// `cylinder_surely_missed` on the lanes `lanes` of `cylinders`: the mask of the lanes whose
/// cylinder the line of `ray` surely misses. Lanes outside `lanes` are 0.
[[gnu::always_inline]] inline int cylinders_surely_missed(const CylinderLanes& cylinders, int lanes, const Ray& ray) {
  using simd::Float4;
  const Vec3 d = ray.direction;
  const float d_sq = dot(d, d);
  // Comparisons are false on NaN: such rays are never rejected.
  if (!(d_sq >= 1e-12f && d_sq <= 1e12f)) return 0;
  const Float4 dx = Float4::broadcast(d.x), dy = Float4::broadcast(d.y), dz = Float4::broadcast(d.z);
  const Float4 ax = Float4::load(cylinders.axis_x), ay = Float4::load(cylinders.axis_y),
               az = Float4::load(cylinders.axis_z);
  // n = cross(d, axis), component by component as Vec3's cross.
  const Float4 nx = dy * az - dz * ay, ny = dz * ax - dx * az, nz = dx * ay - dy * ax;
  const Float4 n_sq = nx * nx + ny * ny + nz * nz;
  const int judged =
      lanes &
      less_equal_mask(Float4::broadcast(detail::kCylinderRejectMinSine * detail::kCylinderRejectMinSine * d_sq), n_sq);
  if (judged == 0) return 0;
  const Float4 fx = Float4::broadcast(ray.origin.x) - Float4::load(cylinders.base_x);
  const Float4 fy = Float4::broadcast(ray.origin.y) - Float4::load(cylinders.base_y);
  const Float4 fz = Float4::broadcast(ray.origin.z) - Float4::load(cylinders.base_z);
  const Float4 along_n = fx * nx + fy * ny + fz * nz;
  const Float4 radius = Float4::load(cylinders.reject_radius);
  const Float4 zero = Float4::broadcast(0.f);  // copysign(x, +0) is |x|, as std::fabs
  const Float4 reach = radius + Float4::broadcast(detail::kCylinderRejectMargin) *
                                    (copysign(fx, zero) + copysign(fy, zero) + copysign(fz, zero) + radius);
  const Float4 far_sq = along_n * along_n;
  return judged & less_mask(reach * reach * n_sq, far_sq) & less_equal_mask(Float4::broadcast(1e-30f), far_sq) &
         less_equal_mask(far_sq, Float4::broadcast(1e30f));
}

RAYLAB_ISA_END
}  // namespace raylab
