// aa-highlights: tiny shiny spheres and sub-pixel emissive dots on black: small, bright,
// isolated features that one sample per pixel mostly misses.

#include <array>
#include <cmath>
#include <string>

#include "aa_common.h"
#include "raylab/scene/aa_scenes.h"

namespace raylab {
namespace {

constexpr float kMinDiameter = 0.5f, kMaxDiameter = 3.f;  // spheres, pixels
constexpr float kMinShininess = 1000.f, kMaxShininess = 4000.f;
constexpr std::array<Color, 2> kSphereColors{{{0.6f, 0.1f, 0.08f}, {0.1f, 0.15f, 0.6f}}};  // dark red, dark blue
constexpr std::array<float, 7> kDotDiameters{0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f};
constexpr std::array<Color, 4> kDotColors{
    {{1.f, 1.f, 1.f}, {1.f, 0.75f, 0.35f}, {0.45f, 0.7f, 1.f}, {0.5f, 1.f, 0.5f}}};

// Geometric interpolation from `lo` to `hi` at step `i` of `n`.
float geometric(float lo, float hi, int i, int n) { return lo * std::pow(hi / lo, float(i) / float(n - 1)); }

}  // namespace

Scene make_aa_highlights_scene() {
  Scene scene;
  aa_detail::set_chart_settings(scene, 5);
  scene.settings.background = {0.f, 0.f, 0.f};
  scene.settings.ambient = {0.f, 0.f, 0.f};
  scene.camera = aa_pixel_camera();

  // Spheres on an 11 x 9 lattice that fills the frame evenly (58.2 x 53.3 px cells, so that
  // the centres fall at every sub-pixel phase). Diameter grows along a row, shininess down a
  // column; one material per row and colour.
  const float step_x = float(kAaWidth) / kAaHighlightColumns;
  const float step_y = float(kAaHeight) / kAaHighlightRows;
  for (int row = 0; row < kAaHighlightRows; ++row) {
    std::array<std::uint32_t, 2> objects{};
    for (int c = 0; c < 2; ++c) {
      Material m;
      m.name = std::string(c == 0 ? "red" : "blue") + " shiny " + std::to_string(row);
      m.color = kSphereColors[c];
      m.kd = 0.3f;
      m.ks = 1.f;
      m.shininess = geometric(kMinShininess, kMaxShininess, row, kAaHighlightRows);
      objects[c] = scene.add_object(m.name, scene.add_material(m));
    }
    for (int col = 0; col < kAaHighlightColumns; ++col) {
      const float radius = 0.5f * geometric(kMinDiameter, kMaxDiameter, col, kAaHighlightColumns);
      const Vec3 centre = aa_pixel_to_world(step_x * (col + 0.5f), step_y * (row + 0.5f));
      scene.geometry.add(Sphere{centre, radius}, objects[(row + col) % 2]);
    }
  }

  // Dots at the lattice's inner corners where (i + j) is even: 40 of the 10 x 8, each about
  // 40 px from its nearest sphere. Emitters only (kd 0, ks 0): their colour is their emission.
  int n = 0;
  for (int j = 0; j + 1 < kAaHighlightRows; ++j) {
    for (int i = 0; i + 1 < kAaHighlightColumns; ++i) {
      if ((i + j) % 2 != 0) continue;
      Material m;
      m.name = "dot " + std::to_string(n);
      m.kd = 0.f;
      m.ks = 0.f;
      m.emission = kDotColors[n % kDotColors.size()];
      const float radius = 0.5f * kDotDiameters[n % kDotDiameters.size()];
      scene.geometry.add(Sphere{aa_pixel_to_world(step_x * (i + 1), step_y * (j + 1)), radius},
                         scene.add_object(m.name, scene.add_material(m)));
      ++n;
    }
  }

  // One point light, without falloff, up and to the left of the camera: every highlight sits
  // on the camera's side of its sphere, a quarter of a radius up and left of its centre. Its
  // peak is ks * 1 plus at most kd * colour = 0.18.
  Light light;
  light.kind = Light::Kind::kPoint;
  light.position = aa_pixel_to_world(-280.f, -560.f, kAaCameraDistance);
  light.intensity = {1.f, 1.f, 1.f};
  scene.lights = {light};
  return scene;
}

}  // namespace raylab
