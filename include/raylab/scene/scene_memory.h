#pragma once
/// \file
/// The memory a scene's data really occupies, part by part.

#include <cstddef>

#include "raylab/scene/scene.h"

namespace raylab {

/// Bytes of a scene's data in use (the elements its arrays hold: size(), not capacity()), by
/// part, and apart from them the bytes its arrays have allocated beyond that. A loader that
/// reserves for the worst case shows up in `reserved`, not in what the scene holds.
struct SceneMemory {
  std::size_t geometry = 0;   ///< shapes and their object ids, prototypes' too, and instances
  std::size_t shading = 0;    ///< per-vertex shading normals and texture coordinates
  std::size_t objects = 0;    ///< objects, with their names
  std::size_t materials = 0;  ///< materials, with their names (texels counted in `textures`)
  std::size_t lights = 0;     ///< lights
  std::size_t textures = 0;   ///< decoded texels, each image once however many materials share it
  std::size_t reserved = 0;   ///< allocated by the arrays above beyond what they hold

  /// Everything in use: the sum of all parts but `reserved`.
  std::size_t used() const { return geometry + shading + objects + materials + lights + textures; }
};

/// The memory `scene` occupies, by part (see SceneMemory). The camera, settings and warnings are
/// left out (a few hundred bytes whatever the scene).
SceneMemory scene_memory(const Scene& scene);

}  // namespace raylab
