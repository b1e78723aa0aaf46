#pragma once
/// \file
/// Shape-box overlap tests, used to insert primitives into the cells of a uniform grid or an
/// octree: a primitive goes into the cells its surface really touches, not every cell its bounding
/// box touches. Boxes are closed (touching counts). Every test is conservative against rounding:
/// it computes in double and gives the shape a relative slack of about 1e-9 or less, so it may
/// accept a box that misses the shape by that much but never rejects one that touches it.
///
/// Exact (up to that slack): triangles, quads, disks, spheres, groups. Conservative: cylinders
/// (never a false negative; see cylinder_overlaps_box).

#include <cstdint>

#include "raylab/core/box.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// True when triangle `t` has a point in the closed box `box`: the separating axis test over the
/// 3 box normals, the triangle normal and the 9 edge-axis cross products. Degenerate triangles
/// (a segment or a point) are handled exactly: an axis that comes out zero is skipped, and the
/// remaining axes are the complete set for the segment or point.
bool triangle_overlaps_box(const Triangle& t, const Box3& box);

/// True when the surface of sphere `s` has a point in `box`: the box reaches the sphere (Arvo's
/// nearest-point distance <= radius) and is not strictly inside it (farthest corner distance >=
/// radius). A cell wholly inside a sphere holds none of its surface, so rays never hit it there.
bool sphere_overlaps_box(const Sphere& s, const Box3& box);

/// True when the solid ball of `s` has a point in `box` (Arvo's test). For bounding volumes,
/// where the inside counts.
bool ball_overlaps_box(const Sphere& s, const Box3& box);

/// True when the lateral surface of cone frustum `c` may have a point in `box`. Conservative:
/// never false for a real overlap, and false for most boxes that miss. In the axis frame the
/// surface is f = 0 with f(p) = (distance of p to the axis) - (radius at p's height), which is
/// convex, so over the part of the box between the end planes: the box is rejected exactly when
/// it lies wholly inside the cone (f < 0 at every vertex, the maximum of a convex function), and
/// when a supporting plane of f certifies min f > 0 (a few Frank-Wolfe steps; if they do not
/// settle it, the box is accepted).
bool cylinder_overlaps_box(const Cylinder& c, const Box3& box);

/// True when disk `d` has a point in `box`: the box straddles the disk's plane and the nearest
/// point of the box's section by that plane lies within the radius of the centre (exact: the
/// nearest point is found as the projection of the centre onto box-and-plane).
bool disk_overlaps_box(const Disk& d, const Box3& box);

/// True when parallelogram `q` has a point in `box` (separating axis test over the box normals,
/// the quad normal and the cross products of its two edge directions with the box axes).
bool quad_overlaps_box(const Quad& q, const Box3& box);

/// True when primitive (or group) `prim_id` of `geometry` has a point in `box`: dispatches on the
/// kind. A group (id >= kGroupIdBase) is a wrapped volume, whose inside counts: its box must
/// overlap `box`, and so must its solid bounding ball when it has one. Never false for a true
/// overlap; callers that need robustness against rounding in their traversal pass a slightly
/// enlarged box.
bool overlaps_box(const Geometry& geometry, std::uint32_t prim_id, const Box3& box);

}  // namespace raylab
