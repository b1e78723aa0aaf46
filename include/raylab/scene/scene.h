#pragma once
/// \file
/// The scene model: plain data shared by loaders, accelerators and the renderer.

#include <cstdint>
#include <string>
#include <vector>

#include "raylab/geometry/geometry.h"
#include "raylab/scene/camera_spec.h"
#include "raylab/scene/light.h"
#include "raylab/scene/material.h"
#include "raylab/scene/render_settings.h"

namespace raylab {

/// A named group of primitives sharing a material (a mesh, a sphere, a floor).
struct SceneObject {
  std::string name;
  std::uint32_t material = 0;  ///< index into Scene::materials
};

/// Everything needed to render: geometry, objects, materials, lights, camera and settings.
/// Plain data: nothing here knows about threads, pixels or files.
struct Scene {
  Geometry geometry;
  std::vector<SceneObject> objects;
  std::vector<Material> materials;
  std::vector<Light> lights;
  CameraSpec camera;
  /// True when the camera came from the source itself (a scene file, or a glTF camera), false
  /// when it is a default that a loader may replace by one fitted to the scene's bounds.
  bool camera_from_file = false;
  RenderSettings settings;
  /// What loading dropped or approximated (zero-area faces, unsupported features), one line
  /// each, for the command line to show as warnings.
  std::vector<std::string> warnings;

  /// Adds a material; returns its index.
  std::uint32_t add_material(Material m);
  /// Adds an object using material `material`; returns its id (to tag primitives with).
  std::uint32_t add_object(std::string name, std::uint32_t material);
  /// Bytes held by the scene's arrays (geometry, objects, materials, lights; not textures).
  std::size_t memory_bytes() const;
  /// The material of primitive `prim_id`.
  const Material& material_of(std::uint32_t prim_id) const {
    return materials[objects[geometry.object_of(prim_id)].material];
  }
};

}  // namespace raylab
