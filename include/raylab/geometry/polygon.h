#pragma once
/// \file
/// Triangulation of simple planar polygons (mesh faces with more than three corners).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "raylab/core/vec3.h"

namespace raylab {

/// Triangulates a simple planar polygon (convex or not, either winding) given by its vertices in order,
/// by ear clipping in the polygon's dominant plane (project by dropping the axis of the largest
/// component of the Newell normal). Returns triangles as index triples into `vertices`, with the same
/// winding as the input. Collinear / repeated vertices are tolerated; degenerate polygons (fewer than 3
/// distinct vertices, zero area) give an empty result. Falls back to a fan for the remaining vertices if
/// no ear is found (self-intersecting input), so it always terminates and never indexes out of range.
/// A polygon with m distinct consecutive vertices gives m - 2 triangles; O(n^2) time at worst, and
/// about O(n) where an ear's bounding box holds few other corners (a grid of the corners). A strictly convex
/// polygon without repeats gives exactly the fan (0, k, k + 1), k = 1 .. n - 2, in that order.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const Vec3> vertices);

namespace detail {
/// Polygons with at least this many distinct corners test ears against a grid of their points
/// (on star-shaped polygons the grid's set-up and the full scan cost the same at about 16
/// corners; at 144 the grid is 5x faster).
inline constexpr std::size_t kPointGridFrom = 16;
/// triangulate_polygon with the grid used from `grid_from` corners on (SIZE_MAX: never), for
/// tests that check the grid changes no answer.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const Vec3> vertices, std::size_t grid_from);
}  // namespace detail

/// Newell normal of a polygon (unnormalised; length = twice the area for a planar polygon).
/// Points to the side from which the vertices are seen counter-clockwise; zero for fewer than 3 vertices.
Vec3 polygon_normal(std::span<const Vec3> vertices);

}  // namespace raylab
