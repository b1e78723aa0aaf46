#pragma once
/// \file
/// Wavefront OBJ output of a scene's triangles (for `raylab convert`).

#include <string>

#include "raylab/scene/scene.h"

namespace raylab {

/// OBJ text of the triangles of `scene.geometry` (analytic shapes must have been tessellated;
/// throws UsageError otherwise): one `o` group per object, `v`/`vn`/`vt` per triangle corner and
/// numbers that read back to the same floats. Materials are named with `usemtl`, as
/// export_material_names() names them; a non-empty `mtl_file` (a name relative to the OBJ's
/// folder, e.g. from encode_mtl()) is named by an `mtllib` line.
std::string encode_obj(const Scene& scene, const std::string& mtl_file = {});

}  // namespace raylab
