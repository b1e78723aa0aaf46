// aa-edges: long straight edges of slopes 1/10, 1 and 10 (and axis-aligned ones), at high
// contrast on the left and at low contrast on the right.

#include <array>

#include "aa_common.h"
#include "raylab/scene/aa_scenes.h"

namespace raylab {
namespace {

// A parallelogram in image coordinates: corner `a`, long edge `u`, short edge `v`.
struct Shape {
  Vec2 a, u, v;
};

// The left half's shapes; the right half repeats them 320 px to the right. Every corner sits at
// .3 / .6 of a pixel, so no edge falls on a pixel boundary and straight edges cut each pixel
// row or column at a sub-pixel phase that repeats with the slope's period (10 px for 1/10 and
// 10, 1 px for 1 and for the axes). Each long edge rises to the right in the image.
constexpr std::array<Shape, 4> kShapes{{
    // slope 1/10: 270 x 27 px long edges (271 px), 36 px high, near the top
    {{24.3f, 100.6f}, {270.f, -27.f}, {0.f, -36.f}},
    // axis-aligned rectangle, 160 x 120 px
    {{40.3f, 250.6f}, {160.f, 0.f}, {0.f, -120.f}},
    // slope 1: 150 x 150 px long edges (212 px), horizontal ends 40 px wide, lower left
    {{30.3f, 430.6f}, {150.f, -150.f}, {40.f, 0.f}},
    // slope 10: 30 x 300 px long edges (301 px), horizontal ends 30 px wide, on the right
    {{240.3f, 440.6f}, {30.f, -300.f}, {30.f, 0.f}},
}};

void add_shapes(Scene& scene, std::uint32_t object, float shift_x) {
  for (const Shape& s : kShapes) scene.geometry.add(aa_detail::image_quad({s.a.x + shift_x, s.a.y}, s.u, s.v), object);
}

}  // namespace

Scene make_aa_edges_scene() {
  Scene scene = aa_detail::unlit_chart({0.f, 0.f, 0.f});
  const float half = 0.5f * kAaWidth;

  const std::uint32_t white = aa_detail::add_unlit_material(scene, "white", {1.f, 1.f, 1.f});
  add_shapes(scene, scene.add_object("high-contrast shapes", white), 0.f);

  const std::uint32_t grey_shape = aa_detail::add_unlit_material(scene, "grey 0.55", Color(kAaEdgesGreyShape));
  add_shapes(scene, scene.add_object("low-contrast shapes", grey_shape), half);

  // The right half's background: a quad 1 unit behind the shapes (so never level with them),
  // from world x = 320, which the camera shows exactly at the pixel boundary x = 320 whatever
  // the depth, to well past the other three sides of the frame.
  const std::uint32_t grey_back = aa_detail::add_unlit_material(scene, "grey 0.50", Color(kAaEdgesGreyBackground));
  constexpr float kMargin = 100.f;
  scene.geometry.add(Quad{{half, -kMargin, -1.f}, {half + kMargin, 0.f, 0.f}, {0.f, kAaHeight + 2.f * kMargin, 0.f}},
                     scene.add_object("low-contrast background", grey_back));
  scene.camera = aa_pixel_camera();
  return scene;
}

}  // namespace raylab
