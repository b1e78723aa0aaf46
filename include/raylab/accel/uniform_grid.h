#pragma once
/// \file
/// Uniform grid walked with Cleary & Wyvill's incremental traversal.

#include <cstdint>
#include <span>

#include "raylab/accel/accelerator.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// Build parameters of the uniform grid, with the defaults used by `--accel grid`.
struct GridConfig {
  float density = 2.f;  ///< cells per primitive (`--grid-density`)
  bool mailbox = true;  ///< test a primitive spanning several cells once per ray
};

/// PLACEHOLDER declaration, being written.
class UniformGrid final : public Accelerator {
 public:
  /// Builds the grid over every primitive of `geometry`, which must outlive this object.
  explicit UniformGrid(const Geometry& geometry, const GridConfig& config = {});
  /// Builds the grid over the primitives (or groups) `ids` of `geometry` only.
  UniformGrid(const Geometry& geometry, std::span<const std::uint32_t> ids, const GridConfig& config = {});
  ~UniformGrid() override;

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
