// `raylab info SCENE`: what a scene holds, how long it took to load and what it occupies.

#include <fmt/core.h>

#include <chrono>
#include <memory>
#include <string>

#include "command_setup.h"
#include "commands.h"
#include "raylab/core/byte_size.h"
#include "raylab/core/stopwatch.h"
#include "raylab/io/scene_loader.h"
#include "raylab/scene/scene_memory.h"

namespace raylab::cli {
namespace {

struct InfoArgs {
  std::string scene;
  bool allow_outside_paths = false;
};

std::string vec(Vec3 v) { return fmt::format("({:g}, {:g}, {:g})", v.x, v.y, v.z); }

const char* light_kind(Light::Kind k) {
  switch (k) {
    case Light::Kind::kPoint:
      return "point";
    case Light::Kind::kDirectional:
      return "directional";
    case Light::Kind::kSphere:
      return "sphere";
    case Light::Kind::kQuad:
      return "quad";
    case Light::Kind::kSpot:
      return "spot";
  }
  return "?";
}

// What the scene's data occupies (info builds no accelerator, so none is counted): the bytes in
// use, exact for scripts, then by part, then what loading reserved beyond them.
void print_memory(const SceneMemory& m) {
  fmt::print("memory      {} in use ({} bytes; no accelerator built)\n", human_bytes(m.used()), m.used());
  fmt::print("            geometry {}, normals and uvs {}, objects {}, materials {}, lights {}, textures {}\n",
             human_bytes(m.geometry), human_bytes(m.shading), human_bytes(m.objects), human_bytes(m.materials),
             human_bytes(m.lights), human_bytes(m.textures));
  if (m.reserved > 0) fmt::print("            {} more allocated but unused\n", human_bytes(m.reserved));
}

int run(const InfoArgs& args) {
  LoadOptions load;
  load.allow_outside_paths = args.allow_outside_paths;
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = load_scene(args.scene, load);
  const double seconds = seconds_since(start);
  for (const std::string& w : scene.warnings) fmt::print(stderr, "warning: {}\n", w);

  const Geometry& g = scene.geometry;
  fmt::print("scene       {}\n", args.scene);
  fmt::print("load time   {:.3f} s\n", seconds);
  print_memory(scene_memory(scene));
  fmt::print("primitives  {}\n", scene.primitive_count());
  if (!scene.instances.empty()) {
    std::uint64_t stored = 0;
    for (const Geometry& p : scene.prototypes) stored += p.size();
    fmt::print("  instances {} of {} meshes ({} primitives stored once; {} placed directly)\n", scene.instances.size(),
               scene.prototypes.size(), stored, g.size());
  }
  fmt::print("  triangles {}{}\n", g.triangles.size(), g.triangle_normals.empty() ? "" : " (with shading normals)");
  fmt::print("  spheres   {}\n  cylinders {} (cylinders and cones)\n  disks     {}\n  quads     {}\n", g.spheres.size(),
             g.cylinders.size(), g.disks.size(), g.quads.size());
  const Box3 b = scene.bounds();
  if (!b.empty()) fmt::print("bounds      {} .. {}\n", vec(b.lo), vec(b.hi));
  fmt::print("objects     {}\n", scene.objects.size());
  fmt::print("materials   {}\n", scene.materials.size());
  for (std::size_t i = 0; i < scene.materials.size() && i < 20; ++i) {
    const Material& m = scene.materials[i];
    fmt::print("  {:<16} color {} kd {:g} ks {:g} shine {:g} reflect {:g} transmit {:g} ior {:g}\n", m.name,
               vec(m.color), m.kd, m.ks, m.shininess, m.reflectivity, m.transmittance, m.ior);
  }
  if (scene.materials.size() > 20) fmt::print("  ... and {} more\n", scene.materials.size() - 20);
  fmt::print("lights      {}\n", scene.lights.size());
  for (std::size_t i = 0; i < scene.lights.size() && i < 20; ++i) {
    const Light& l = scene.lights[i];
    fmt::print("  {:<11} {} intensity {}\n", light_kind(l.kind),
               vec(l.kind == Light::Kind::kDirectional ? l.direction : l.position), vec(l.intensity));
  }
  if (scene.lights.size() > 20) fmt::print("  ... and {} more\n", scene.lights.size() - 20);
  const CameraSpec& c = scene.camera;
  fmt::print("camera      from {} at {} up {}\n", vec(c.from), vec(c.at), vec(c.up));
  fmt::print("            vertical angle {:g} degrees ({}), hither {:g}\n", c.vfov_degrees,
             c.fov_span == CameraSpec::FovSpan::kImageEdges ? "edge to edge" : "between pixel centres", c.hither);
  const RenderSettings& s = scene.settings;
  fmt::print("settings    {}x{}, {} spp ({}), depth {}, background {}\n", s.width, s.height, s.spp, s.sampler,
             s.max_depth, vec(s.background));
  return 0;
}

void add_options(CLI::App& cmd, InfoArgs& args) {
  cmd.option_defaults()->group("Scene");
  cmd.add_option("scene", args.scene, "Scene: built-in name, spd:NAME[?size=N], or a scene or mesh file")->required();
  add_allow_outside_paths_flag(cmd, args.allow_outside_paths);
}

}  // namespace

CommandRunner add_info_command(CLI::App& app) {
  return add_command<InfoArgs>(app, "info", "Describe a scene: primitives, bounds, materials, lights, camera",
                               add_options, run);
}

}  // namespace raylab::cli
