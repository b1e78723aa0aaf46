#include "raylab/io/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "raylab/core/error.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/obj_loader.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {

void fit_camera_and_lights(Scene& scene) {
  const Box3 box = scene.geometry.bounds();
  Vec3 center{0.f};
  float radius = 1.f;
  if (!box.empty()) {
    center = box.center();
    radius = std::max(0.5f * length(box.extent()), 1e-6f);
  }
  CameraSpec& cam = scene.camera;
  cam.vfov_degrees = 40.f;
  // Distance at which the bounding sphere just fills the vertical field of view: the sphere
  // around the box is loose already, so no further margin is needed.
  const float distance = 1.0f * radius / std::sin(cam.vfov_degrees * std::numbers::pi_v<float> / 360.f);
  const Vec3 view_dir = normalize(Vec3{0.35f, 0.3f, 1.f});
  cam.at = center;
  cam.from = center + view_dir * distance;
  cam.up = {0.f, 1.f, 0.f};

  Light key;
  key.kind = Light::Kind::kPoint;
  key.position = center + normalize(Vec3{1.f, 1.5f, 1.2f}) * (distance * 1.5f);
  key.intensity = {0.8f, 0.8f, 0.8f};
  Light fill;
  fill.kind = Light::Kind::kDirectional;
  fill.direction = normalize(Vec3{0.6f, -0.2f, -1.f});
  fill.intensity = {0.25f, 0.25f, 0.28f};
  scene.lights = {key, fill};
  scene.settings.background = {0.08f, 0.09f, 0.11f};
}

Scene load_scene(const std::string& source) {
  if (is_builtin_scene(source)) return make_builtin_scene(source);
  const std::string ext = lowercase_extension(source);
  if (ext == ".obj") {
    Scene scene;
    Material grey;
    grey.name = "grey";
    grey.color = {0.75f, 0.75f, 0.75f};
    grey.kd = 0.9f;
    grey.ks = 0.2f;
    grey.shininess = 40.f;
    const std::uint32_t mat = scene.add_material(grey);
    const std::uint32_t obj = scene.add_object(std::filesystem::path(source).filename().string(), mat);
    load_obj(source, scene, obj);
    if (scene.geometry.size() == 0) throw InputError(source, "the mesh has no faces");
    fit_camera_and_lights(scene);
    return scene;
  }
  if (ext.empty() && !std::filesystem::exists(source)) {
    std::string names;
    for (auto n : builtin_scene_names()) names += (names.empty() ? "" : ", ") + std::string(n);
    throw UsageError("unknown scene '" + source + "' (built-in scenes: " + names + "; or a .obj file)");
  }
  throw UsageError("cannot load '" + source + "': unsupported scene format '" + ext + "' (supported: .obj)");
}

}  // namespace raylab
