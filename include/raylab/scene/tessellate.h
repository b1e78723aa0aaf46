#pragma once
/// \file
/// Turning analytic shapes into triangles, for formats and tools that know only meshes
/// (`raylab convert` to OBJ or PLY, Embree's triangle geometry).

#include "raylab/scene/scene.h"

namespace raylab {

/// How finely analytic shapes are cut into triangles.
struct TessellationOptions {
  int segments = 32;  ///< around a sphere, cylinder or disk (at least 3)
  int rings = 16;     ///< from pole to pole of a sphere (at least 2)
};

/// A copy of `geometry` with only triangles: spheres, cylinders/cones, disks and quads are
/// tessellated (with smooth per-vertex normals on curved shapes) and keep their object ids;
/// triangles are copied unchanged, with their normals and uvs.
Geometry tessellate(const Geometry& geometry, const TessellationOptions& options = {});

}  // namespace raylab
