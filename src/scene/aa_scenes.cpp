// The pixel camera and the settings shared by the antialiasing charts.

#include <cmath>
#include <numbers>
#include <utility>

#include "aa_common.h"
#include "raylab/scene/aa_scenes.h"

namespace raylab {

CameraSpec aa_pixel_camera() {
  CameraSpec camera;
  const float cx = 0.5f * static_cast<float>(kAaWidth);
  const float cy = 0.5f * static_cast<float>(kAaHeight);
  camera.from = {cx, cy, kAaCameraDistance};
  camera.at = {cx, cy, 0.f};
  camera.up = {0.f, 1.f, 0.f};
  // In double, so that the image plane's half height is cy / D to the last bit of float.
  camera.vfov_degrees =
      static_cast<float>(2.0 * std::atan(double(cy) / double(kAaCameraDistance)) * 180.0 / std::numbers::pi);
  camera.fov_span = CameraSpec::FovSpan::kImageEdges;
  return camera;
}

namespace aa_detail {

void set_chart_settings(Scene& scene, int max_depth) {
  RenderSettings defaults;
  scene.settings.width = kAaWidth;
  scene.settings.height = kAaHeight;
  scene.settings.spp = 1;
  scene.settings.seed = 0;
  scene.settings.max_depth = max_depth;
  scene.settings.sampler = defaults.sampler;
  scene.settings.filter = defaults.filter;
  scene.camera_from_file = true;
}

Scene unlit_chart(Color background) {
  Scene scene;
  set_chart_settings(scene, 1);
  scene.settings.ambient = {1.f, 1.f, 1.f};
  scene.settings.background = background;
  return scene;
}

std::uint32_t add_unlit_material(Scene& scene, std::string name, Color color) {
  Material m;
  m.name = std::move(name);
  m.color = color;
  m.kd = 1.f;
  m.ks = 0.f;
  return scene.add_material(m);
}

Quad image_quad(Vec2 a, Vec2 u, Vec2 v, float z) {
  // Image y points down, world y up: positions flip about the image height, edges change sign.
  return Quad{aa_pixel_to_world(a.x, a.y, z), Vec3{u.x, -u.y, 0.f}, Vec3{v.x, -v.y, 0.f}};
}

}  // namespace aa_detail
}  // namespace raylab
