#include "raylab/io/gltf_loader.h"

#include <filesystem>

#include "gltf/gltf_files.h"
#include "gltf/gltf_reader.h"
#include "raylab/core/error.h"
#include "raylab/io/scene_paths.h"

// The reader is split by idea under gltf/: file access and URI sandboxing, the GLB container,
// accessors, the scene graph and camera, primitives, materials and textures. This file only
// ties them together.

namespace raylab {

void load_gltf(const std::string& path, Scene& scene, const GltfLoadOptions& options) {
  using namespace gltf_detail;
  if (!options.placement.valid()) throw UsageError("load_gltf: the placement transform is not invertible");
  CallbackContext ctx;
  std::error_code ec;
  ctx.folder = std::filesystem::absolute(folder_of(path), ec).lexically_normal().string();
  if (ctx.folder.size() > 1 && ctx.folder.ends_with('/')) ctx.folder.pop_back();
  ctx.allow_outside = options.allow_outside_paths;
  const tinygltf::Model model = parse_gltf(path, ctx);
  GltfReader(path, model, ctx, scene, options).read();
}

}  // namespace raylab
