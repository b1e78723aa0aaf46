#pragma once
/// \file
/// The reference structure: every ray against every primitive.

#include <cstdint>
#include <span>
#include <vector>

#include "raylab/accel/traversal_accelerator.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// Tests every primitive for every ray. Slow and obviously correct: the reference every other
/// structure is checked against.
class BruteForce final : public TraversalAccelerator<BruteForce> {
 public:
  /// Keeps a reference to `geometry`, which must outlive this object.
  explicit BruteForce(const Geometry& geometry);
  /// Tests only the primitives (or groups) `ids` of `geometry`, in that order.
  BruteForce(const Geometry& geometry, std::span<const std::uint32_t> ids);

  Box3 bounds() const override { return m_bounds; }
  AccelInfo info() const override;
  /// Exact: tests every primitive once.
  void all_hits(const Ray& ray, std::vector<Hit>& hits) const override;

 private:
  friend class TraversalAccelerator<BruteForce>;
  // The kernel of every query (TraversalAccelerator).
  template <bool kAnyHit, bool kCount, class K>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;

  const Geometry& m_geometry;
  std::vector<std::uint32_t> m_ids;  ///< what to test, in ascending order
  Box3 m_bounds;
  double m_build_seconds = 0.0;
};

extern template class TraversalAccelerator<BruteForce>;

}  // namespace raylab
