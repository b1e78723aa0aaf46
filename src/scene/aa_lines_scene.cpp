// aa-lines: thin lines at many angles and widths, and a Siemens star, white on black, unlit.

#include <cmath>
#include <numbers>

#include "aa_common.h"
#include "raylab/scene/aa_scenes.h"

namespace raylab {
namespace {

constexpr double kPi = std::numbers::pi;

// Image position at distance `r` from `c` in direction `angle` (radians, counter-clockwise as
// seen in the image, where y points down).
Vec2 polar(Vec2 c, double r, double angle) {
  return {static_cast<float>(c.x + r * std::cos(angle)), static_cast<float>(c.y - r * std::sin(angle))};
}

// The ring of thin lines: line k points at 2.3 + 14.4 k degrees. With an odd count spread evenly
// over the full turn, the directions modulo 180 degrees are all distinct, 7.2 degrees apart, and
// none is horizontal, vertical or diagonal. Widths are geometric from the thinnest to the widest;
// line k gets width number 7 k mod n (7 is prime to n), so that neighbours differ in width.
void add_lines(Scene& scene, std::uint32_t object) {
  constexpr int n = kAaLineCount;
  const double ratio = double(kAaLineMaxWidth) / double(kAaLineMinWidth);
  for (int k = 0; k < n; ++k) {
    const double angle = (2.3 + 360.0 * k / n) * kPi / 180.0;
    const int w_index = (7 * k) % n;
    const double width = kAaLineMinWidth * std::pow(ratio, double(w_index) / (n - 1));
    // Image-space unit direction and its left normal.
    const double dx = std::cos(angle), dy = -std::sin(angle);
    const Vec2 start = polar(kAaLinesCenter, kAaLineInnerRadius, angle);
    const double length = double(kAaLineOuterRadius) - double(kAaLineInnerRadius);
    const Vec2 corner{static_cast<float>(start.x + 0.5 * width * dy), static_cast<float>(start.y - 0.5 * width * dx)};
    const Vec2 along{static_cast<float>(length * dx), static_cast<float>(length * dy)};
    const Vec2 across{static_cast<float>(-width * dy), static_cast<float>(width * dx)};
    scene.geometry.add(aa_detail::image_quad(corner, along, across), object);
  }
}

// The Siemens star: wedge i spans angles [a_i, a_i + 2 pi / 128] with a_i = 2 pi i / 64 plus a
// quarter wedge, so that no edge through the centre runs along a pixel row or column. Each wedge
// is one triangle: the centre and two points on the rim.
void add_star(Scene& scene, std::uint32_t object) {
  const double wedge = 2.0 * kPi / (2.0 * kAaStarWedges);
  const double turn = 0.25 * wedge;
  for (int i = 0; i < kAaStarWedges; ++i) {
    const double a0 = turn + 2.0 * kPi * i / kAaStarWedges;
    const Vec2 p1 = polar(kAaStarCenter, kAaStarRadius, a0);
    const Vec2 p2 = polar(kAaStarCenter, kAaStarRadius, a0 + wedge);
    const Triangle t{aa_pixel_to_world(kAaStarCenter.x, kAaStarCenter.y), aa_pixel_to_world(p1.x, p1.y),
                     aa_pixel_to_world(p2.x, p2.y)};
    scene.geometry.add(t, object);
  }
}

}  // namespace

Scene make_aa_lines_scene() {
  Scene scene = aa_detail::unlit_chart({0.f, 0.f, 0.f});
  const std::uint32_t white = aa_detail::add_unlit_material(scene, "white", {1.f, 1.f, 1.f});
  add_lines(scene, scene.add_object("thin lines", white));
  add_star(scene, scene.add_object("siemens star", white));
  scene.camera = aa_pixel_camera();
  return scene;
}

}  // namespace raylab
