#pragma once
/// \file
/// STL meshes, ASCII and binary, read by raylab's own parser.

#include <cstdint>
#include <string>
#include <string_view>

#include "raylab/scene/mesh_builder.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Appends the facets of STL file `path` to `scene.geometry` as object `object`; see parse_stl.
/// Throws InputError when the file cannot be read or is not valid STL.
MeshLoadReport load_stl(const std::string& path, Scene& scene, std::uint32_t object);

/// Parses the STL file held in `bytes` (named `file` in messages) and appends its facets to
/// `geometry` as object `object`. The file is binary (80-byte header, uint32 count, 50-byte
/// records) when its size is exactly 84 + 50 * count, even if it starts with "solid" as some
/// exporters write; otherwise it is ASCII if it starts with "solid", and binary with a short
/// count check otherwise. Facet normals are ignored (the geometric normal follows the vertex
/// order); zero-area facets are dropped and counted. Throws InputError `file:line:col: ...`
/// (ASCII) or `file: byte N: ...` (binary) for a non-finite coordinate, a misplaced keyword or
/// a file shorter than its triangle count says (checked before anything is allocated).
MeshLoadReport parse_stl(std::string_view bytes, const std::string& file, Geometry& geometry, std::uint32_t object);

}  // namespace raylab
