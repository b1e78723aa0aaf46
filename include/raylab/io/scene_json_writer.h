#pragma once
/// \file
/// A Scene written back as a raylab scene file (docs/scene-format.md), for `raylab convert`.

#include <string>
#include <vector>

#include "raylab/scene/scene.h"

namespace raylab {

/// A file that a scene file refers to, written beside it.
struct SidecarFile {
  std::string name;   ///< file name, relative to the scene file's folder
  std::string bytes;  ///< contents
};

/// A scene file and the mesh files it refers to.
struct SceneJsonFiles {
  std::string json;                   ///< the scene file's text
  std::vector<SidecarFile> meshes;    ///< binary PLY files named by its `mesh` objects
  std::vector<SidecarFile> textures;  ///< PNG files of its image textures and maps, PFM of its environment image
};

/// `scene` as a raylab scene file that reads back to the same scene: camera (and camera path),
/// every render setting, lights, materials, spheres, cylinders and cones, disks and quads as
/// analytic objects, with every float written so that it reads back bit for bit
/// (float_text()). Triangles go to binary PLY sidecars named `<stem>.<k>.ply`, one per run of
/// consecutive triangles of one object, placed without a transform: PLY keeps float32 vertices,
/// shading normals and texture coordinates exactly, where the scene format's `triangle` objects
/// carry no normals, and the runs keep the triangles in their order, which the structures
/// built over them and so the image depend on. Image textures go to PNG sidecars
/// `<stem>.tex<k>.png`, one per image, when 8 bits give their texels back exactly
/// (encode_texture_png()), material maps likewise, and an environment image to `<stem>.env.pfm`
/// (float, exact). What the format cannot carry is left out (other image textures,
/// zone plates; format_losses() names them). `scene` must hold no instances
/// (bake_instances() first); throws UsageError otherwise.
SceneJsonFiles encode_scene_json(const Scene& scene, const std::string& stem);

}  // namespace raylab
