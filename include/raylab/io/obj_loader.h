#pragma once
/// \file
/// Wavefront OBJ meshes through tinyobjloader, with every index checked by raylab.

#include <cstdint>
#include <string>

#include "raylab/scene/mesh_builder.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Appends the triangles of OBJ file `path` to `scene.geometry` as object `object`. Polygons are
/// triangulated by raylab (tinyobjloader's own triangulation reads vertices before any index is
/// validated). Vertex normals are used when every corner of a face has one. Throws InputError
/// `file:line:col: ...` for an index out of range (positive or negative), a non-finite
/// coordinate, or a file that cannot be read.
MeshLoadReport load_obj(const std::string& path, Scene& scene, std::uint32_t object);

}  // namespace raylab
