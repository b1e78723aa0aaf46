// aa-whitted: Whitted's 1980 scene as an antialiasing chart: everything a ray tracer aliases
// (edges, shadow boundaries, reflected and refracted checkers) in one image, with the floor
// kept finite so that its own checker never goes beyond the Nyquist limit.

#include "aa_common.h"
#include "raylab/scene/aa_scenes.h"
#include "whitted_look.h"

namespace raylab {

Scene make_aa_whitted_scene() {
  Scene scene;
  aa_detail::set_chart_settings(scene, 5);
  whitted_detail::set_whitted_sky(scene.settings);
  scene.settings.ambient = {0.1f, 0.1f, 0.1f};

  // 26 degrees down, 58 degree field: the horizon is at row 30, the floor's far edge at row
  // 156, and above the far edge the rays (still pointing down) see the horizon's colour.
  scene.camera.from = {0.f, 6.f, 10.5f};
  scene.camera.at = {0.f, 0.9f, 0.f};
  scene.camera.up = {0.f, 1.f, 0.f};
  scene.camera.vfov_degrees = 58.f;

  const Material floor{.name = "checker floor",
                       .color = {0.95f, 0.85f, 0.25f},  // yellow
                       .kd = 0.85f,
                       .texture = {Texture::Kind::kChecker, {0.8f, 0.12f, 0.08f}, kAaWhittedCell}};  // red
  const auto floor_obj = scene.add_object("floor", scene.add_material(floor));
  const float h = 0.5f * kAaWhittedFloorSize;
  scene.geometry.add(Quad{{-h, 0.f, h}, {kAaWhittedFloorSize, 0.f, 0.f}, {0.f, 0.f, -kAaWhittedFloorSize}}, floor_obj);

  // The mirror and the glass of the demo scene, with highlights a little weaker so that no
  // radiance passes about 1.5.
  const auto mirror_obj = scene.add_object("mirror sphere", scene.add_material(whitted_detail::whitted_mirror(0.5f)));
  scene.geometry.add(Sphere{{-1.6f, 1.6f, -1.f}, 1.6f}, mirror_obj);
  const auto glass_obj = scene.add_object("glass sphere", scene.add_material(whitted_detail::whitted_glass(0.5f)));
  scene.geometry.add(Sphere{{1.8f, 1.3f, 2.2f}, 1.3f}, glass_obj);

  // A key light up and to the left in front, a weaker fill from the right: two shadows.
  const Light key{.kind = Light::Kind::kPoint, .position = {-5.f, 9.f, 6.f}, .intensity = {0.75f, 0.73f, 0.68f}};
  const Light fill{.kind = Light::Kind::kPoint, .position = {7.f, 6.f, 1.f}, .intensity = {0.25f, 0.27f, 0.32f}};
  scene.lights = {key, fill};
  return scene;
}

}  // namespace raylab
