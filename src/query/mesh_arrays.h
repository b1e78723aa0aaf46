#pragma once
// Triangles from a program's flat arrays (internal to src/query): checked, then copied into a
// Geometry with one triangle per index triple, in order.

#include <cstdint>
#include <span>

#include "raylab/geometry/geometry.h"

namespace raylab {

/// The triangles of `indices` (three vertex indices each) over `vertices` (x, y, z each), as
/// object 0. Throws std::invalid_argument naming `vertices` or `indices` when a length is not a
/// multiple of 3, a coordinate is not finite, or an index is out of range.
Geometry geometry_from_arrays(std::span<const float> vertices, std::span<const std::uint32_t> indices);

/// The same from double-precision coordinates, each rounded to the nearest float.
Geometry geometry_from_arrays(std::span<const double> vertices, std::span<const std::uint32_t> indices);

}  // namespace raylab
