#pragma once
/// \file
/// The one way loaders add polygon faces: triangulated, validated, degenerate faces counted.

#include <cstddef>
#include <cstdint>
#include <span>

#include "raylab/geometry/geometry.h"

namespace raylab {

/// Counts of what a mesh load did.
struct MeshLoadReport {
  std::size_t vertices = 0;            ///< vertices read
  std::size_t triangles = 0;           ///< triangles added
  std::size_t degenerate_dropped = 0;  ///< zero-area triangles (or polygon parts) counted and dropped
};

/// Adds the polygon `corners` (3 or more, convex or not, either winding) to `geometry` as object
/// `object`, triangulated by ear clipping. `normals` and `uvs` are empty or one per corner. Each
/// triangle the polygon should have given but did not (repeated corners, zero area) counts in
/// `report.degenerate_dropped`; added triangles count in `report.triangles`. Corners must be
/// finite (callers check, because only they know where in the file a corner came from).
void add_polygon(Geometry& geometry, std::span<const Vec3> corners, std::span<const Vec3> normals,
                 std::span<const Vec2> uvs, std::uint32_t object, MeshLoadReport& report);

/// Adds one triangle unless it has zero area, with optional per-corner normals and uvs (nullptr
/// when absent). Returns whether it was added; updates `report` either way.
bool add_triangle(Geometry& geometry, const Triangle& triangle, const std::array<Vec3, 3>* normals,
                  const std::array<Vec2, 3>* uvs, std::uint32_t object, MeshLoadReport& report);

}  // namespace raylab
