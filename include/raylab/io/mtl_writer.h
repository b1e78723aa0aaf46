#pragma once
/// \file
/// Wavefront MTL output of a scene's materials (the library an OBJ written by raylab names).

#include <string>
#include <vector>

#include "raylab/scene/scene.h"

namespace raylab {

/// One name per material of `scene`, usable as an MTL `newmtl`/`usemtl` name and as a key of a
/// scene file's `materials`: the material's own name with white space replaced by '_', "material"
/// when empty, and a suffix "~2", "~3", ... on repeats, so that every name is distinct.
std::vector<std::string> export_material_names(const Scene& scene);

/// MTL text of every material of `scene`, named as export_material_names() says. Per material:
/// `Kd` (the colour times kd, which is how the renderer uses both), `Ks` (ks, grey), `Ns`,
/// `d` and `Tr` (1 - transmittance and transmittance), `Ni`, `Ke` when it emits, and `illum 3`
/// (ray-traced reflection, mirror colour Ks) when reflective, else `illum 2`. What MTL cannot
/// say (checker and image textures, a reflectivity that differs from ks, fresnel off) is left
/// out; format_losses() names it.
std::string encode_mtl(const Scene& scene);

}  // namespace raylab
