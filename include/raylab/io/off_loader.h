#pragma once
/// \file
/// Object File Format (OFF) meshes, ASCII, read by raylab's own parser.

#include <cstdint>
#include <string>
#include <string_view>

#include "raylab/scene/mesh_builder.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Appends the faces of OFF file `path` to `scene.geometry` as object `object`; see parse_off.
/// Throws InputError when the file cannot be read or is not valid OFF.
MeshLoadReport load_off(const std::string& path, Scene& scene, std::uint32_t object);

/// Parses the OFF file held in `bytes` (named `file` in messages) and appends its faces to
/// `geometry` as object `object`. Reads the header keyword `OFF` with the optional prefixes `ST`
/// (texture coordinates), `C` (colours, skipped) and `N` (vertex normals), or no keyword at all;
/// `#` comments; the counts line `vertices faces [edges]`; one vertex per line and one face
/// `n i0 ... i(n-1) [colour]` per line, polygons triangulated by add_polygon. Throws InputError
/// `file:line:col: ...` for an index out of range, a non-finite number, fewer vertices or faces
/// than announced, or counts that cannot fit in the file (checked before anything is allocated).
MeshLoadReport parse_off(std::string_view bytes, const std::string& file, Geometry& geometry, std::uint32_t object);

}  // namespace raylab
