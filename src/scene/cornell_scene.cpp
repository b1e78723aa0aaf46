// The Cornell box as the Cornell University Program of Computer Graphics published it
// ("Cornell Box Data", measured geometry in millimetres, camera with a 35 mm lens on a
// 25 mm x 25 mm film), with the usual RGB reductions of its measured reflectance spectra.

#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "raylab/scene/builtin_scenes.h"
#include "raylab/scene/mesh_builder.h"

namespace raylab {
namespace {

using Face = std::array<Vec3, 4>;

// Published quadrilaterals, in the published vertex order.
constexpr Face kFloor{{{552.8f, 0.f, 0.f}, {0.f, 0.f, 0.f}, {0.f, 0.f, 559.2f}, {549.6f, 0.f, 559.2f}}};
constexpr Face kCeiling{{{556.f, 548.8f, 0.f}, {556.f, 548.8f, 559.2f}, {0.f, 548.8f, 559.2f}, {0.f, 548.8f, 0.f}}};
constexpr Face kBackWall{{{549.6f, 0.f, 559.2f}, {0.f, 0.f, 559.2f}, {0.f, 548.8f, 559.2f}, {556.f, 548.8f, 559.2f}}};
constexpr Face kRightWall{{{0.f, 0.f, 559.2f}, {0.f, 0.f, 0.f}, {0.f, 548.8f, 0.f}, {0.f, 548.8f, 559.2f}}};
constexpr Face kLeftWall{{{552.8f, 0.f, 0.f}, {549.6f, 0.f, 559.2f}, {556.f, 548.8f, 559.2f}, {556.f, 548.8f, 0.f}}};
constexpr std::array<Face, 5> kShortBlock{{
    {{{130.f, 165.f, 65.f}, {82.f, 165.f, 225.f}, {240.f, 165.f, 272.f}, {290.f, 165.f, 114.f}}},
    {{{290.f, 0.f, 114.f}, {290.f, 165.f, 114.f}, {240.f, 165.f, 272.f}, {240.f, 0.f, 272.f}}},
    {{{130.f, 0.f, 65.f}, {130.f, 165.f, 65.f}, {290.f, 165.f, 114.f}, {290.f, 0.f, 114.f}}},
    {{{82.f, 0.f, 225.f}, {82.f, 165.f, 225.f}, {130.f, 165.f, 65.f}, {130.f, 0.f, 65.f}}},
    {{{240.f, 0.f, 272.f}, {240.f, 165.f, 272.f}, {82.f, 165.f, 225.f}, {82.f, 0.f, 225.f}}},
}};
constexpr std::array<Face, 5> kTallBlock{{
    {{{423.f, 330.f, 247.f}, {265.f, 330.f, 296.f}, {314.f, 330.f, 456.f}, {472.f, 330.f, 406.f}}},
    {{{423.f, 0.f, 247.f}, {423.f, 330.f, 247.f}, {472.f, 330.f, 406.f}, {472.f, 0.f, 406.f}}},
    {{{472.f, 0.f, 406.f}, {472.f, 330.f, 406.f}, {314.f, 330.f, 456.f}, {314.f, 0.f, 456.f}}},
    {{{314.f, 0.f, 456.f}, {314.f, 330.f, 456.f}, {265.f, 330.f, 296.f}, {265.f, 0.f, 296.f}}},
    {{{265.f, 0.f, 296.f}, {265.f, 330.f, 296.f}, {423.f, 330.f, 247.f}, {423.f, 0.f, 247.f}}},
}};

void add_faces(Scene& scene, std::span<const Face> faces, std::uint32_t object) {
  MeshLoadReport report;
  for (const Face& f : faces) add_polygon(scene.geometry, f, {}, {}, object, report);
}

Material matte(const char* name, Color color) {
  Material m;
  m.name = name;
  m.color = color;
  m.kd = 1.f;
  return m;
}

}  // namespace

Scene make_cornell_scene() {
  Scene scene;
  const std::uint32_t white = scene.add_material(matte("white", {0.725f, 0.71f, 0.68f}));
  const std::uint32_t red = scene.add_material(matte("red", {0.63f, 0.065f, 0.05f}));
  const std::uint32_t green = scene.add_material(matte("green", {0.14f, 0.45f, 0.091f}));
  Material lamp = matte("light", {0.78f, 0.78f, 0.78f});
  lamp.emission = {1.f, 0.85f, 0.6f};
  // The path integrator's radiance: about that of the classic path-traced Cornell box's lamp
  // (luminance 12-13), which lights the box to a full exposure. Whitted shows `emission` alone.
  lamp.emission_strength = 15.f;
  const std::uint32_t light_material = scene.add_material(lamp);

  add_faces(scene, std::span<const Face>(&kFloor, 1), scene.add_object("floor", white));
  add_faces(scene, std::span<const Face>(&kCeiling, 1), scene.add_object("ceiling", white));
  add_faces(scene, std::span<const Face>(&kBackWall, 1), scene.add_object("back wall", white));
  add_faces(scene, std::span<const Face>(&kRightWall, 1), scene.add_object("right wall", green));
  add_faces(scene, std::span<const Face>(&kLeftWall, 1), scene.add_object("left wall", red));
  add_faces(scene, kShortBlock, scene.add_object("short block", white));
  add_faces(scene, kTallBlock, scene.add_object("tall block", white));

  // The published light: 130 mm x 105 mm, 0.1 mm below the ceiling so that it is not inside it.
  const Vec3 corner{343.f, 548.7f, 227.f};
  const Vec3 edge_u{-130.f, 0.f, 0.f}, edge_v{0.f, 0.f, 105.f};
  const std::uint32_t lamp_object = scene.add_object("light", light_material);
  // Edges in this order give the quad a downward normal: the side the lamp emits to under path.
  scene.geometry.add(Quad{corner, edge_v, edge_u}, lamp_object);
  Light area;
  area.object = static_cast<std::int32_t>(lamp_object);  // under path the quad itself is the light
  area.kind = Light::Kind::kQuad;
  area.position = corner;
  area.edge_u = edge_u;
  area.edge_v = edge_v;
  area.intensity = {0.95f, 0.8f, 0.55f};
  area.samples = 16;
  scene.lights = {area};
  // Whitted shading has no interreflection; a small ambient term stands in for it.
  scene.settings.ambient = {0.12f, 0.12f, 0.12f};
  scene.settings.width = 512;
  scene.settings.height = 512;
  scene.settings.spp = 4;

  // Camera at (278, 273, -800) looking along +z; 35 mm focal length, 25 mm film.
  scene.camera.from = {278.f, 273.f, -800.f};
  scene.camera.at = {278.f, 273.f, 0.f};
  scene.camera.up = {0.f, 1.f, 0.f};
  scene.camera.vfov_degrees = static_cast<float>(2.0 * std::atan(12.5 / 35.0) * 180.0 / std::numbers::pi);
  scene.camera_from_file = true;
  return scene;
}

}  // namespace raylab
