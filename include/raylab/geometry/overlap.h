#pragma once
/// \file
/// Exact shape-box overlap tests, used to insert primitives into the cells of a uniform grid or
/// an octree: a primitive goes into the cells it really touches, not every cell its bounding box
/// touches.

#include <cstdint>

#include "raylab/core/box.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// True when triangle `t` has a point in the closed box `box` (separating axis test).
bool triangle_overlaps_box(const Triangle& t, const Box3& box);
/// True when sphere `s` (the solid ball) has a point in `box`.
bool sphere_overlaps_box(const Sphere& s, const Box3& box);
/// True when the lateral surface of cone frustum `c` may have a point in `box`.
bool cylinder_overlaps_box(const Cylinder& c, const Box3& box);
/// True when disk `d` has a point in `box`.
bool disk_overlaps_box(const Disk& d, const Box3& box);
/// True when quad `q` has a point in `box`.
bool quad_overlaps_box(const Quad& q, const Box3& box);

/// True when primitive (or group) `prim_id` of `geometry` has a point in `box`: dispatches on the
/// kind. Never false for a true overlap; callers that need robustness against rounding in their
/// traversal pass a slightly enlarged box.
bool overlaps_box(const Geometry& geometry, std::uint32_t prim_id, const Box3& box);

}  // namespace raylab
