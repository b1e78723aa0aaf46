// The demo scene against a committed reference image, compared with the same RMSE measure that
// `raylab diff` uses. The reference was made with:
//   raylab render demo --width 200 --height 112 --spp 4 -o tests/data/demo_200x112_4spp.png
// Regenerate it (and say why in the commit) only when the demo is changed on purpose.

#include <gtest/gtest.h>

#include "../test_paths.h"
#include "raylab/accel/factory.h"
#include "raylab/io/image_io.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {
namespace {

// In 8-bit sRGB steps. The reference is quantised to 8 bits, which alone gives about 0.29
// (uniform rounding error, 1/sqrt(12)); the rest allows for floating-point differences between
// compilers and CPUs in the few pixels where a ray grazes an edge.
constexpr double kMaxRmse = 1.5;

Film render_demo(int max_depth) {
  Scene scene = make_demo_scene();
  scene.settings.width = 200;
  scene.settings.height = 112;
  scene.settings.spp = 4;
  scene.settings.max_depth = max_depth;
  const auto accel = make_accelerator("bvh", scene.geometry);
  Film film(scene.settings.width, scene.settings.height);
  render(scene, *accel, film);
  return film;
}

const Film& reference() {
  static const Film film = read_image(raylab::test::source_dir() + "/tests/data/demo_200x112_4spp.png");
  return film;
}

TEST(ReferenceImage, DemoMatchesCommittedReference) {
  const Film film = render_demo(5);
  const double rmse = image_rmse(film, reference());
  RecordProperty("rmse", std::to_string(rmse));
  EXPECT_LE(rmse, kMaxRmse) << "demo render differs from tests/data/demo_200x112_4spp.png";
}

// The tolerance must be tight enough to notice a real change: dropping reflections and
// refractions (max depth 1) has to fail it by a wide margin.
TEST(ReferenceImage, ToleranceDetectsMissingReflections) {
  const Film film = render_demo(1);
  EXPECT_GT(image_rmse(film, reference()), 5.0 * kMaxRmse);
}

}  // namespace
}  // namespace raylab
