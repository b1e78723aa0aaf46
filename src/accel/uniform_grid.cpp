#include "raylab/accel/uniform_grid.h"

#include <stdexcept>

// PLACEHOLDER, being written.

namespace raylab {

UniformGrid::UniformGrid(const Geometry& geometry, const GridConfig& config)
    : UniformGrid(geometry, geometry.primitive_ids(), config) {}
UniformGrid::UniformGrid(const Geometry&, std::span<const std::uint32_t>, const GridConfig&) {
  throw std::logic_error("uniform_grid: not written yet");
}
UniformGrid::~UniformGrid() = default;
Box3 UniformGrid::bounds() const { return {}; }
bool UniformGrid::intersect(Ray&, Hit&) const { return false; }
bool UniformGrid::occluded(const Ray&) const { return false; }
bool UniformGrid::intersect_counted(Ray&, Hit&, TraversalStats&) const { return false; }
bool UniformGrid::occluded_counted(const Ray&, TraversalStats&) const { return false; }
AccelInfo UniformGrid::info() const { return {}; }

}  // namespace raylab
