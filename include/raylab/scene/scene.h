#pragma once
/// \file
/// The scene model: plain data shared by loaders, accelerators and the renderer.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "raylab/core/box.h"
#include "raylab/geometry/geometry.h"
#include "raylab/geometry/instance.h"
#include "raylab/geometry/shading.h"
#include "raylab/scene/camera_path.h"
#include "raylab/scene/camera_spec.h"
#include "raylab/scene/light.h"
#include "raylab/scene/material.h"
#include "raylab/scene/render_settings.h"

namespace raylab {

struct Environment;

/// A named group of primitives sharing a material (a mesh, a sphere, a floor).
struct SceneObject {
  std::string name;
  std::uint32_t material = 0;  ///< index into Scene::materials
};

/// Everything needed to render: geometry, objects, materials, lights, camera and settings.
/// Plain data: nothing here knows about threads, pixels or files.
struct Scene {
  /// The scene's own primitives, in world space (global ids 0 .. geometry.size() - 1).
  Geometry geometry;
  /// Meshes stored once in their own space, placed by `instances` (object ids in a prototype
  /// are relative: instance.first_object + id).
  std::vector<Geometry> prototypes;
  /// Placements of prototypes; their primitives follow the flat ones in the global id space.
  std::vector<Instance> instances;
  std::vector<SceneObject> objects;
  std::vector<Material> materials;
  std::vector<Light> lights;
  /// The light arriving from everywhere (a constant colour or a lat-long image, environment.h):
  /// the path integrator lights the scene with it and shows it behind everything. Null: the
  /// background of `settings` (its colour or sky gradient) stands for it.
  std::shared_ptr<const Environment> environment;
  /// The camera of a still image (and of a scene file's `camera` object, path or not).
  CameraSpec camera;
  /// The camera of an animation, frame by frame; empty when the scene is a still.
  CameraPath camera_path;
  /// True when the camera came from the source itself (a scene file, or a glTF camera), false
  /// when it is a default that a loader may replace by one fitted to the scene's bounds.
  bool camera_from_file = false;
  /// True when fit_camera_and_lights placed the camera (a bare mesh, a scene file without a
  /// camera), so that a caller may place it again for another up axis.
  bool camera_fitted = false;
  /// True when fit_camera_and_lights placed the lights too (the scene gave none).
  bool lights_fitted = false;
  RenderSettings settings;
  /// What loading dropped or approximated (zero-area faces, unsupported features), one line
  /// each, for the command line to show as warnings.
  std::vector<std::string> warnings;
  /// The files the scene was read from (the scene file, meshes, material libraries, textures,
  /// glTF buffers and images), as the loaders opened them; empty for built-in and SPD scenes.
  /// What an output must never overwrite (check_not_an_input).
  std::vector<std::string> source_files;

  /// Adds a material; returns its index.
  std::uint32_t add_material(Material m);
  /// Adds an object using material `material`; returns its id (to tag primitives with).
  std::uint32_t add_object(std::string name, std::uint32_t material);
  /// Bytes of the scene's data in use, textures included: scene_memory(*this).used() (see
  /// scene_memory.h for the parts and the capacity reserved beyond them).
  std::size_t memory_bytes() const;
  /// Places prototype `prototype` under `to_world` (invertible), its objects starting at
  /// `first_object`; returns the instance index. Throws UsageError when the global id space
  /// (2^31 primitives) would overflow.
  std::uint32_t add_instance(std::uint32_t prototype, const Transform& to_world, std::uint32_t first_object);
  /// Primitives in total: flat ones plus every instance's.
  std::uint64_t primitive_count() const;
  /// Bounds of everything, instances included.
  Box3 bounds() const;
  /// The object of global primitive `prim_id`.
  std::uint32_t object_of(std::uint32_t prim_id) const;
  /// The material of global primitive `prim_id`.
  const Material& material_of(std::uint32_t prim_id) const { return materials[objects[object_of(prim_id)].material]; }
};

/// Surface data for `hit` (global primitive id) on `ray`, instances included: the hit is
/// recomputed in the prototype's space and carried back to world space.
SurfaceInteraction surface_at(const Scene& scene, const Ray& ray, const Hit& hit);

/// surface_at, but a sphere's surface coordinates are computed only where the hit's material
/// reads them (reads_surface_coordinates), u = v = 0 elsewhere: what the integrators shade
/// with. An untextured sphere's coordinates (an arc tangent and an arc cosine) cost more than
/// the rest of its hit; other shapes' cost less than asking the material.
SurfaceInteraction shading_surface_at(const Scene& scene, const Ray& ray, const Hit& hit);

}  // namespace raylab
