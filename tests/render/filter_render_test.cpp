// Reconstruction filters in the renderer: weights are normalised (a flat image stays exactly
// flat, borders included), a filter wider than a pixel blurs an edge by the right amount, and
// the per-tile sums keep images independent of the thread count and scheduling.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "raylab/accel/factory.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/aa_scenes.h"

namespace raylab {
namespace {

Film render_scene(Scene scene, int threads = 0, int tile = 16) {
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  Film film(scene.settings.width, scene.settings.height);
  RenderOptions options;
  options.threads = threads;
  options.tile_size = tile;
  render(scene, *accel, film, options);
  return film;
}

Scene flat_scene(const char* filter) {
  Scene scene;
  scene.settings.width = 20;
  scene.settings.height = 14;
  scene.settings.spp = 4;
  scene.settings.sampler = "jittered";
  scene.settings.filter = filter;
  scene.settings.background = {0.25f, 0.5f, 0.75f};
  return scene;
}

TEST(FilterRender, FlatImageStaysFlatWithEveryFilter) {
  for (const char* f : {"box", "tent", "gaussian", "mitchell"}) {
    const Film film = render_scene(flat_scene(f));
    for (const Color& c : film.pixels()) {
      EXPECT_NEAR(c.x, 0.25f, 1e-5f) << f;
      EXPECT_NEAR(c.z, 0.75f, 1e-5f) << f;
    }
  }
}

TEST(FilterRender, WideBoxBlursAVerticalEdgeByItsWidth) {
  // aa-edges' left half is white shapes on black; use a box of radius 1.5 (three pixels wide)
  // on a regular 8x8 grid: a pixel next to a vertical edge sees a known fraction of white.
  Scene scene = make_aa_edges_scene();
  scene.settings.width = 80;  // the whole chart, smaller
  scene.settings.height = 60;
  scene.settings.sampler = "regular";
  scene.settings.spp = 64;
  const Film box = render_scene(scene);
  scene.settings.filter = "box";
  scene.settings.filter_radius = 1.5f;
  const Film wide = render_scene(scene);
  // The wide box is the mean of the 3 x 3 block of narrow pixels wherever all nine lie inside
  // the image (every sample weighs the same and each pixel has the same count).
  double worst = 0.0;
  for (int y = 1; y + 1 < box.height(); ++y) {
    for (int x = 1; x + 1 < box.width(); ++x) {
      double mean = 0.0;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) mean += box.at(x + dx, y + dy).x / 9.0;
      }
      worst = std::max(worst, std::abs(mean - wide.at(x, y).x));
    }
  }
  EXPECT_LT(worst, 1e-4);
}

// The tile size is part of the summation order (a pixel near a tile border adds the tiles'
// partial sums in tile order), so it is fixed here; threads and scheduling are not.
TEST(FilterRender, WideFiltersDoNotDependOnThreads) {
  Scene scene = make_aa_lines_scene();
  scene.settings.width = 96;
  scene.settings.height = 72;
  scene.settings.sampler = "cmj";
  scene.settings.spp = 5;
  scene.settings.filter = "mitchell";
  const Film a = render_scene(scene, 1, 16);
  const Film b = render_scene(scene, 2, 16);
  for (std::size_t i = 0; i < a.pixels().size(); ++i) ASSERT_EQ(a.pixels()[i].y, b.pixels()[i].y) << i;
}

}  // namespace
}  // namespace raylab
