// The material showcase: a row of spheres of every physically based model and named metal, on a
// checkered ground, under a sky with a sun, for the path integrator (docs/rendering.md shows it).

#include <cmath>
#include <memory>
#include <numbers>

#include "raylab/scene/builtin_scenes.h"
#include "raylab/scene/environment.h"
#include "raylab/scene/metals.h"

namespace raylab {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// The sky: a lat-long image (scene/environment.h's mapping) blue overhead, pale at the horizon,
// a grey ground below it, and a sun 35 degrees high behind the camera's left shoulder, small
// and bright enough to cast sharp shadows (about 3 times the sky's irradiance).
std::shared_ptr<const EnvironmentImage> sky_image() {
  constexpr int kWidth = 512, kHeight = 256;
  const float sun_elevation = 35.f * kPi / 180.f, sun_azimuth = 120.f * kPi / 180.f;
  const Vec3 sun{std::cos(sun_elevation) * std::cos(sun_azimuth), std::sin(sun_elevation),
                 std::cos(sun_elevation) * std::sin(sun_azimuth)};
  const float sun_cos = std::cos(2.5f * kPi / 180.f);  // a disc of 2.5 degrees radius
  auto image = std::make_shared<EnvironmentImage>();
  image->width = kWidth;
  image->height = kHeight;
  image->texels.resize(static_cast<std::size_t>(kWidth) * kHeight);
  for (int j = 0; j < kHeight; ++j) {
    for (int i = 0; i < kWidth; ++i) {
      const Vec3 d =
          lat_long_direction((static_cast<float>(i) + 0.5f) / kWidth, (static_cast<float>(j) + 0.5f) / kHeight);
      Color c;
      if (d.y > 0.f) {
        const float t = std::pow(1.f - d.y, 4.f);
        c = lerp(Color{0.25f, 0.45f, 0.95f}, Color{0.85f, 0.9f, 1.f}, t);
      } else {
        c = Color{0.25f, 0.23f, 0.2f};
      }
      if (dot(d, sun) > sun_cos) c = Color{400.f, 370.f, 320.f};
      image->texels[static_cast<std::size_t>(j) * kWidth + i] = c;
    }
  }
  return image;
}

Material pbr(const char* name, MaterialModel model, Color color, float roughness = 0.f, float ior = 1.5f) {
  Material m;
  m.name = name;
  m.model = model;
  m.color = color;
  m.roughness = roughness;
  m.ior = ior;
  return m;
}

Material metal(const char* name, std::string_view which, float roughness) {
  Material m = pbr(name, MaterialModel::kConductor, Color{1.f}, roughness);
  const ConductorIor ior = *metal_ior(which);
  m.conductor_eta = ior.eta;
  m.conductor_k = ior.k;
  // For Whitted, which reads only the Phong members: a mirror of the metal's colour.
  m.kd = 0.f;
  m.reflectivity = 0.8f;
  return m;
}

}  // namespace

Scene make_showcase_scene() {
  Scene scene;
  const Material row[] = {
      pbr("diffuse", MaterialModel::kDiffuse, {0.8f, 0.18f, 0.15f}),
      pbr("plastic", MaterialModel::kPlastic, {0.1f, 0.25f, 0.8f}),
      pbr("rough plastic", MaterialModel::kPlastic, {0.9f, 0.55f, 0.1f}, 0.5f),
      metal("gold", "gold", 0.2f),
      metal("copper", "copper", 0.35f),
      metal("aluminium", "aluminium", 0.5f),
      metal("silver", "silver", 0.f),
      pbr("glass", MaterialModel::kDielectric, Color{1.f}),
      pbr("frosted glass", MaterialModel::kDielectric, {0.85f, 1.f, 0.9f}, 0.35f),
  };
  const int count = static_cast<int>(std::size(row));
  for (int i = 0; i < count; ++i) {
    Material m = row[i];
    if (m.model == MaterialModel::kDielectric) {  // Whitted: glass
      m.kd = 0.f;
      m.transmittance = 1.f;
    }
    const float x = (static_cast<float>(i) - 0.5f * static_cast<float>(count - 1)) * 1.15f;
    scene.geometry.add(Sphere{Vec3{x, 0.5f, 0.f}, 0.5f}, scene.add_object(m.name, scene.add_material(m)));
  }
  Material ground = pbr("ground", MaterialModel::kDiffuse, {0.75f, 0.75f, 0.72f});
  ground.texture = Texture(Texture::Kind::kChecker, Color{0.35f, 0.35f, 0.33f}, 1.f);
  // Wide enough that it meets the sky at the horizon.
  scene.geometry.add(Quad{Vec3{-500.f, 0.f, -500.f}, Vec3{0.f, 0.f, 1000.f}, Vec3{1000.f, 0.f, 0.f}},
                     scene.add_object("ground", scene.add_material(ground)));

  auto sky = std::make_shared<Environment>();
  sky->image = sky_image();
  scene.environment = sky;
  // For Whitted, which has no environment light: the sun as a directional light.
  Light sun;
  sun.kind = Light::Kind::kDirectional;
  sun.direction = -Vec3{std::cos(35.f * kPi / 180.f) * std::cos(120.f * kPi / 180.f), std::sin(35.f * kPi / 180.f),
                        std::cos(35.f * kPi / 180.f) * std::sin(120.f * kPi / 180.f)};
  sun.intensity = {0.9f, 0.85f, 0.75f};
  scene.lights = {sun};
  scene.settings.integrator = "path";
  scene.settings.width = 960;
  scene.settings.height = 360;
  scene.settings.spp = 64;
  scene.settings.max_depth = 8;
  scene.settings.background = {0.5f, 0.65f, 0.95f};
  scene.settings.ambient = {0.2f, 0.2f, 0.2f};

  scene.camera.from = {0.f, 2.2f, 10.5f};
  scene.camera.at = {0.f, 0.45f, 0.f};
  scene.camera.up = {0.f, 1.f, 0.f};
  scene.camera.vfov_degrees = 22.f;
  scene.camera_from_file = true;
  return scene;
}

}  // namespace raylab
