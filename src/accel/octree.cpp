#include "raylab/accel/octree.h"

#include <stdexcept>

// PLACEHOLDER, being written.

namespace raylab {

Octree::Octree(const Geometry& geometry, const OctreeConfig& config)
    : Octree(geometry, geometry.primitive_ids(), config) {}
Octree::Octree(const Geometry&, std::span<const std::uint32_t>, const OctreeConfig&) {
  throw std::logic_error("octree: not written yet");
}
Octree::~Octree() = default;
Box3 Octree::bounds() const { return {}; }
bool Octree::intersect(Ray&, Hit&) const { return false; }
bool Octree::occluded(const Ray&) const { return false; }
bool Octree::intersect_counted(Ray&, Hit&, TraversalStats&) const { return false; }
bool Octree::occluded_counted(const Ray&, TraversalStats&) const { return false; }
AccelInfo Octree::info() const { return {}; }

}  // namespace raylab
