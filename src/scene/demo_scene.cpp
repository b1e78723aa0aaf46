// The first image every user sees: Whitted's 1980 scene (a checkered floor, a mirror ball and a
// glass ball under a blue sky) with the rest of what raylab renders around it.

#include "raylab/scene/builtin_scenes.h"
#include "raylab/scene/mesh_generators.h"

namespace raylab {

Scene make_demo_scene() {
  Scene scene;
  scene.settings.width = 800;
  scene.settings.height = 450;
  scene.settings.spp = 4;
  scene.settings.max_depth = 5;
  scene.settings.sky_gradient = true;
  scene.settings.background = {0.22f, 0.42f, 0.78f};  // zenith
  scene.settings.horizon = {0.78f, 0.86f, 0.95f};
  scene.settings.ambient = {0.07f, 0.08f, 0.1f};

  scene.camera.from = {0.5f, 3.4f, 7.8f};
  scene.camera.at = {0.f, 0.55f, -0.6f};
  scene.camera.vfov_degrees = 38.f;

  Material floor;
  floor.name = "checker floor";
  floor.color = {0.93f, 0.86f, 0.62f};
  floor.texture = {Texture::Kind::kChecker, {0.72f, 0.1f, 0.08f}, 1.f};
  floor.kd = 0.85f;
  floor.reflectivity = 0.08f;
  const auto floor_obj = scene.add_object("floor", scene.add_material(floor));
  scene.geometry.add(Quad{{-30.f, 0.f, 30.f}, {60.f, 0.f, 0.f}, {0.f, 0.f, -60.f}}, floor_obj);

  Material mirror;
  mirror.name = "mirror";
  mirror.color = {0.9f, 0.9f, 0.95f};
  mirror.kd = 0.05f;
  mirror.ks = 0.6f;
  mirror.shininess = 400.f;
  mirror.reflectivity = 0.88f;
  const auto mirror_obj = scene.add_object("mirror sphere", scene.add_material(mirror));
  scene.geometry.add(Sphere{{-1.55f, 1.f, -0.9f}, 1.f}, mirror_obj);

  Material glass;
  glass.name = "glass";
  glass.color = {1.f, 1.f, 1.f};
  glass.kd = 0.f;
  glass.ks = 0.8f;
  glass.shininess = 600.f;
  glass.transmittance = 0.95f;
  glass.ior = 1.5f;
  const auto glass_obj = scene.add_object("glass sphere", scene.add_material(glass));
  scene.geometry.add(Sphere{{0.95f, 0.85f, 1.35f}, 0.85f}, glass_obj);

  Material plastic;
  plastic.name = "blue plastic";
  plastic.color = {0.12f, 0.3f, 0.85f};
  plastic.kd = 0.8f;
  plastic.ks = 0.7f;
  plastic.shininess = 80.f;
  const auto plastic_obj = scene.add_object("phong sphere", scene.add_material(plastic));
  scene.geometry.add(Sphere{{2.35f, 0.6f, -1.1f}, 0.6f}, plastic_obj);

  Material gold;
  gold.name = "gold";
  gold.color = {0.95f, 0.68f, 0.22f};
  gold.kd = 0.7f;
  gold.ks = 0.6f;
  gold.shininess = 120.f;
  gold.reflectivity = 0.2f;
  const auto torus_obj = scene.add_object("torus mesh", scene.add_material(gold));
  add_torus(scene.geometry, torus_obj, {-0.35f, 0.34f, -3.4f}, 1.1f, 0.34f, 72, 36);  // 5,184 triangles

  Material copper;
  copper.name = "copper cone";
  copper.color = {0.8f, 0.38f, 0.25f};
  copper.kd = 0.75f;
  copper.ks = 0.5f;
  copper.shininess = 60.f;
  const auto cone_obj = scene.add_object("cone", scene.add_material(copper));
  scene.geometry.add(Cylinder{{-3.3f, 0.f, 0.8f}, 0.45f, {-3.3f, 1.3f, 0.8f}, 0.05f}, cone_obj);

  Light key;
  key.kind = Light::Kind::kPoint;
  key.position = {5.f, 8.f, 6.f};
  key.intensity = {0.62f, 0.6f, 0.56f};
  Light rim;
  rim.kind = Light::Kind::kPoint;
  rim.position = {-7.f, 5.f, 2.f};
  rim.intensity = {0.22f, 0.24f, 0.3f};
  Light area;
  area.kind = Light::Kind::kQuad;
  area.position = {-1.5f, 7.f, -1.f};
  area.edge_u = {3.f, 0.f, 0.f};
  area.edge_v = {0.f, 0.f, 3.f};
  area.intensity = {0.34f, 0.34f, 0.32f};
  area.samples = 16;
  scene.lights = {key, rim, area};
  return scene;
}

}  // namespace raylab
