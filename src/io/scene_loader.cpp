#include "raylab/io/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "raylab/core/error.h"
#include "raylab/io/file_extension.h"
#include "raylab/io/gltf_loader.h"
#include "raylab/io/nff_loader.h"
#include "raylab/io/obj_loader.h"
#include "raylab/io/off_loader.h"
#include "raylab/io/ply_loader.h"
#include "raylab/io/read_file.h"
#include "raylab/io/scene_json.h"
#include "raylab/io/stl_loader.h"
#include "raylab/scene/builtin_scenes.h"
#include "raylab/scene/spd.h"
#include "raylab/scene/up_axis.h"

namespace raylab {

namespace {

// The directions of a mesh standing on `up`: `right`, `up` and `front` (towards the viewer of a
// front view), right-handed as +X, +Y, +Z are for a +Y-up mesh. A +Z-up mesh faces -Y, as
// Blender's and most CAD programs' front view shows it.
struct MeshFrame {
  Vec3 right, up, front;
};

MeshFrame mesh_frame(Vec3 up) {
  Vec3 front{0.f, 0.f, 1.f};
  if (up.y != 0.f) front = Vec3{0.f, 0.f, up.y};
  if (up.z != 0.f) front = Vec3{0.f, -up.z, 0.f};
  return {cross(up, front), up, front};
}

// `v` given in the frame's (right, up, front) coordinates, in world space.
Vec3 in_frame(const MeshFrame& f, Vec3 v) { return f.right * v.x + f.up * v.y + f.front * v.z; }

}  // namespace

void fit_camera_and_lights(Scene& scene, std::optional<Vec3> up) {
  const Box3 box = scene.bounds();
  Vec3 center{0.f};
  float radius = 1.f;
  if (!box.empty()) {
    center = box.center();
    radius = std::max(0.5f * length(box.extent()), 1e-6f);
  }
  const MeshFrame frame = mesh_frame(up ? *up : detect_up_axis(scene).value_or(Vec3{0.f, 1.f, 0.f}));
  CameraSpec& cam = scene.camera;
  cam = CameraSpec{};
  cam.vfov_degrees = 40.f;
  // Distance at which the bounding sphere just fills the vertical field of view: the sphere
  // around the box is loose already, so no further margin is needed.
  const float distance = 1.0f * radius / std::sin(cam.vfov_degrees * std::numbers::pi_v<float> / 360.f);
  const Vec3 view_dir = normalize(in_frame(frame, Vec3{0.35f, 0.3f, 1.f}));
  cam.at = center;
  cam.from = center + view_dir * distance;
  cam.up = frame.up;

  const Light key{.kind = Light::Kind::kPoint,
                  .position = center + normalize(in_frame(frame, Vec3{1.f, 1.5f, 1.2f})) * (distance * 1.5f),
                  .intensity = {0.8f, 0.8f, 0.8f}};
  const Light fill{.kind = Light::Kind::kDirectional,
                   .direction = normalize(in_frame(frame, Vec3{0.6f, -0.2f, -1.f})),
                   .intensity = {0.25f, 0.25f, 0.28f}};
  scene.lights = {key, fill};
  scene.camera_fitted = true;
  scene.lights_fitted = true;
  RenderSettings& s = scene.settings;
  s.background = {0.08f, 0.09f, 0.11f};
  // Whitted shading leaves what no light reaches black: a little ambient light keeps the
  // undersides and the silhouette against the dark background readable.
  s.ambient = Color{kMeshAmbient};
  // Edges of a mesh are most of what its image shows: antialiased unless the caller says
  // otherwise (the "auto" sampler jitters at more than one sample).
  s.spp = kMeshSamplesPerPixel;
}

std::span<const std::string_view> scene_file_extensions() {
  static constexpr std::string_view kExtensions[] = {".json", ".nff", ".obj", ".gltf", ".glb", ".ply", ".off", ".stl"};
  return kExtensions;
}

namespace {

Material default_mesh_material() {
  return {.name = "grey", .color = {0.75f, 0.75f, 0.75f}, .kd = 0.9f, .ks = 0.2f, .shininess = 40.f};
}

void note_dropped(Scene& scene, const std::string& path, const MeshLoadReport& report) {
  if (report.degenerate_dropped > 0) {
    scene.warnings.push_back(path + ": " + std::to_string(report.degenerate_dropped) + " zero-area triangles dropped");
  }
}

std::string extension_list() {
  std::string list;
  for (auto e : scene_file_extensions()) list += (list.empty() ? "" : " ") + std::string(e);
  return list;
}

}  // namespace

Scene load_mesh(const std::string& path, const LoadOptions& options) {
  const std::string ext = lowercase_extension(path);
  Scene scene;
  if (ext == ".gltf" || ext == ".glb") {
    GltfLoadOptions gltf;
    gltf.allow_outside_paths = options.allow_outside_paths;
    gltf.use_camera = true;
    load_gltf(path, scene, gltf);
    return scene;
  }
  const std::string name = std::filesystem::path(path).filename().string();
  if (ext == ".obj") {
    ObjLoadOptions obj;
    obj.allow_outside_paths = options.allow_outside_paths;
    const std::uint32_t object = scene.add_object(name, scene.add_material(default_mesh_material()));
    note_dropped(scene, path, load_obj(path, scene, object, obj));
    return scene;
  }
  const std::uint32_t object = scene.add_object(name, scene.add_material(default_mesh_material()));
  MeshLoadReport report;
  if (ext == ".ply") {
    report = load_ply(path, scene, object);
  } else if (ext == ".off") {
    report = load_off(path, scene, object);
  } else if (ext == ".stl") {
    report = load_stl(path, scene, object);
  } else {
    throw UsageError("cannot load '" + path + "' as a mesh: unsupported format '" + ext +
                     "' (meshes: .obj .gltf .glb .ply .off .stl)");
  }
  note_dropped(scene, path, report);
  return scene;
}

namespace {

// load_scene without the list of files read.
Scene load_scene_source(const std::string& source, const LoadOptions& options) {
  if (is_builtin_scene(source)) return make_builtin_scene(source);
  if (is_spd_source(source)) return make_spd_scene(source);
  const std::string ext = lowercase_extension(source);
  if (ext == ".json") return load_scene_json(source, options);
  if (ext == ".nff") {
    Scene scene;
    note_dropped(scene, source, load_nff(source, scene));
    if (scene.geometry.size() == 0) throw InputError(source, "the scene has no primitives");
    return scene;
  }
  const bool mesh = ext == ".obj" || ext == ".gltf" || ext == ".glb" || ext == ".ply" || ext == ".off" || ext == ".stl";
  if (mesh) {
    Scene scene = load_mesh(source, options);
    if (scene.geometry.size() == 0) throw InputError(source, "the mesh has no faces");
    const bool has_camera = scene.camera_from_file;
    const CameraSpec camera = scene.camera;
    fit_camera_and_lights(scene);
    if (has_camera) {
      scene.camera = camera;
      scene.camera_fitted = false;
    }
    return scene;
  }
  if (ext.empty() && !std::filesystem::exists(source)) {
    std::string names;
    for (auto n : builtin_scene_names()) names += (names.empty() ? "" : ", ") + std::string(n);
    throw UsageError("unknown scene '" + source + "' (built-in scenes: " + names +
                     "; SPD generators: spd:NAME, see --list-scenes; or a file: " + extension_list() + ")");
  }
  throw UsageError("cannot load '" + source + "': unsupported scene format '" + ext +
                   "' (supported: " + extension_list() + ")");
}

}  // namespace

Scene load_scene(const std::string& source, const LoadOptions& options) {
  const FileReadLog log;
  Scene scene = load_scene_source(source, options);
  scene.source_files = log.files();
  return scene;
}

}  // namespace raylab
