#pragma once
/// \file
/// Procedural triangle meshes.

#include <cstdint>

#include "raylab/core/vec3.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// Adds a torus around the y axis through `center` (major radius `major`, tube radius `minor`),
/// `rings` x `sides` quads split into triangles, with smooth vertex normals. Closed mesh.
void add_torus(Geometry& g, std::uint32_t object, Vec3 center, float major, float minor, int rings, int sides);

/// Adds an icosphere: an icosahedron subdivided `level` times, projected onto the sphere
/// (20 * 4^level triangles), with smooth vertex normals. Closed mesh.
void add_icosphere(Geometry& g, std::uint32_t object, Vec3 center, float radius, int level);

}  // namespace raylab
