#pragma once
/// \file
/// Octree with ordered parametric traversal.

#include <cstdint>
#include <span>

#include "raylab/accel/accelerator.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// Build parameters of the octree, with the defaults used by `--accel octree`.
struct OctreeConfig {
  int max_items = 8;    ///< K: a cell holding more primitives is subdivided (`--octree-max-items`)
  int max_depth = 10;   ///< L: cells at this depth are never subdivided (`--octree-max-depth`)
  bool mailbox = true;  ///< test a primitive spanning several cells once per ray
};

/// PLACEHOLDER declaration, being written.
class Octree final : public Accelerator {
 public:
  /// Builds the octree over every primitive of `geometry`, which must outlive this object.
  explicit Octree(const Geometry& geometry, const OctreeConfig& config = {});
  /// Builds the octree over the primitives (or groups) `ids` of `geometry` only.
  Octree(const Geometry& geometry, std::span<const std::uint32_t> ids, const OctreeConfig& config = {});
  ~Octree() override;

  Box3 bounds() const override;
  bool intersect(Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override;
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const override;
  bool occluded_counted(const Ray& ray, TraversalStats& stats) const override;
  using Accelerator::intersect;
  using Accelerator::occluded;
  AccelInfo info() const override;
};

}  // namespace raylab
