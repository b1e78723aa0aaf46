#pragma once
/// \file
/// Stanford PLY meshes (ASCII, binary little- and big-endian), read by raylab's own parser.

#include <cstdint>
#include <string>
#include <string_view>

#include "raylab/scene/mesh_builder.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Appends the triangles of PLY file `path` to `scene.geometry` as object `object`; see
/// parse_ply. Header lines that start with no PLY keyword become `scene.warnings`
/// (`file:line:col: ...`). Throws InputError when the file cannot be read or is not valid PLY.
MeshLoadReport load_ply(const std::string& path, Scene& scene, std::uint32_t object);

/// Parses the PLY file held in `bytes` (named `file` in messages) and appends its faces to
/// `geometry` as object `object`. Reads vertex `x y z`, optional `nx ny nz` and `u v` (or `s t`,
/// `texture_u texture_v`), polygons from element `face` (list `vertex_indices` or
/// `vertex_index`, triangulated by add_polygon) and triangle strips from element `tristrips`
/// (list `vertex_indices`, -1 restarts a strip). Other elements and properties are skipped, and
/// so are header lines that start with no PLY keyword (exporters write `Created by ...`; load_ply
/// reports them as warnings), but not the properties after one: it may be a misspelt `element`.
/// Throws InputError `file:line:col: ...` (header, ASCII body) or `file: byte N: ...` (binary
/// body) for an index out of range, a non-finite number, data shorter than the header announces,
/// or element counts that cannot fit in the file (checked before anything is allocated).
MeshLoadReport parse_ply(std::string_view bytes, const std::string& file, Geometry& geometry, std::uint32_t object);

}  // namespace raylab
