#pragma once
/// \file
/// Triangle meshes written as binary little-endian PLY.

#include <string>

#include "raylab/geometry/geometry.h"

namespace raylab {

/// The triangles of `geometry` as a binary little-endian PLY file: element `vertex` (float
/// `x y z`, then `nx ny nz` when the geometry has shading normals, then `u v` when it has
/// texture coordinates) with three unshared vertices per triangle, so that every value comes
/// back exactly, and element `face` (list uchar int `vertex_indices`). Object ids are not
/// stored. Throws UsageError if the geometry holds primitives other than triangles (tessellate
/// them first) or more triangles than int indices can number.
std::string encode_ply(const Geometry& geometry);

}  // namespace raylab
