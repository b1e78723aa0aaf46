// The first image every user sees: Whitted's 1980 scene (a checkered floor, a mirror ball and a
// glass ball under a blue sky) with the rest of what raylab renders around it.

#include "raylab/scene/builtin_scenes.h"
#include "raylab/scene/mesh_generators.h"
#include "whitted_look.h"

namespace raylab {

Scene make_demo_scene() {
  Scene scene;
  scene.settings.width = 800;
  scene.settings.height = 450;
  scene.settings.spp = 4;
  scene.settings.max_depth = 5;
  whitted_detail::set_whitted_sky(scene.settings);
  scene.settings.ambient = {0.07f, 0.08f, 0.1f};

  scene.camera.from = {0.5f, 3.4f, 7.8f};
  scene.camera.at = {0.f, 0.55f, -0.6f};
  scene.camera.vfov_degrees = 38.f;

  const Material floor{.name = "checker floor",
                       .color = {0.93f, 0.86f, 0.62f},
                       .kd = 0.85f,
                       .reflectivity = 0.08f,
                       .texture = {Texture::Kind::kChecker, {0.72f, 0.1f, 0.08f}, 1.f}};
  const auto floor_obj = scene.add_object("floor", scene.add_material(floor));
  scene.geometry.add(Quad{{-30.f, 0.f, 30.f}, {60.f, 0.f, 0.f}, {0.f, 0.f, -60.f}}, floor_obj);

  const auto mirror_obj = scene.add_object("mirror sphere", scene.add_material(whitted_detail::whitted_mirror(0.6f)));
  scene.geometry.add(Sphere{{-1.55f, 1.f, -0.9f}, 1.f}, mirror_obj);

  const auto glass_obj = scene.add_object("glass sphere", scene.add_material(whitted_detail::whitted_glass(0.8f)));
  scene.geometry.add(Sphere{{0.95f, 0.85f, 1.35f}, 0.85f}, glass_obj);

  const Material plastic{
      .name = "blue plastic", .color = {0.12f, 0.3f, 0.85f}, .kd = 0.8f, .ks = 0.7f, .shininess = 80.f};
  const auto plastic_obj = scene.add_object("phong sphere", scene.add_material(plastic));
  scene.geometry.add(Sphere{{2.35f, 0.6f, -1.1f}, 0.6f}, plastic_obj);

  const Material gold{
      .name = "gold", .color = {0.95f, 0.68f, 0.22f}, .kd = 0.7f, .ks = 0.6f, .shininess = 120.f, .reflectivity = 0.2f};
  const auto torus_obj = scene.add_object("torus mesh", scene.add_material(gold));
  add_torus(scene.geometry, torus_obj, {-0.35f, 0.34f, -3.4f}, 1.1f, 0.34f, 72, 36);  // 5,184 triangles

  const Material copper{
      .name = "copper cone", .color = {0.8f, 0.38f, 0.25f}, .kd = 0.75f, .ks = 0.5f, .shininess = 60.f};
  const auto cone_obj = scene.add_object("cone", scene.add_material(copper));
  scene.geometry.add(Cylinder{{-3.3f, 0.f, 0.8f}, 0.45f, {-3.3f, 1.3f, 0.8f}, 0.05f}, cone_obj);

  const Light key{.kind = Light::Kind::kPoint, .position = {5.f, 8.f, 6.f}, .intensity = {0.62f, 0.6f, 0.56f}};
  const Light rim{.kind = Light::Kind::kPoint, .position = {-7.f, 5.f, 2.f}, .intensity = {0.22f, 0.24f, 0.3f}};
  const Light area{.kind = Light::Kind::kQuad,
                   .position = {-1.5f, 7.f, -1.f},
                   .edge_u = {3.f, 0.f, 0.f},
                   .edge_v = {0.f, 0.f, 3.f},
                   .intensity = {0.34f, 0.34f, 0.32f},
                   .samples = 16};
  scene.lights = {key, rim, area};
  return scene;
}

}  // namespace raylab
