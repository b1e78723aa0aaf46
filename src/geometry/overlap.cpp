#include "raylab/geometry/overlap.h"

// PLACEHOLDER (being replaced by exact tests): bounding-box overlap only.

namespace raylab {
namespace {
bool boxes_overlap(const Box3& a, const Box3& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}
}  // namespace

bool overlaps_box(const Geometry& geometry, std::uint32_t prim_id, const Box3& box) {
  return boxes_overlap(geometry.bounds(prim_id), box);
}

}  // namespace raylab
