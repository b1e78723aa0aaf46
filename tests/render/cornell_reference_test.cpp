// The path-traced Cornell box against its own reference image (tests/data, made by
// scripts/make-cornell-reference.sh at 65536 samples per pixel, with each pixel's per-sample
// variance), by a per-pixel z-test at alpha = 0.01 with Sidak correction as Mitsuba 3's render
// tests do, and a negative control that must fail: the same test on a box whose white paint is
// 4% darker.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../test_paths.h"
#include "raylab/accel/factory.h"
#include "raylab/io/image_io.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {
namespace {

// The reference's settings, which scripts/make-cornell-reference.sh passes to the command line.
constexpr int kSize = 16;
constexpr int kMaxDepth = 6;
constexpr int kReferenceSpp = 65536;

// The test's render: independent samples (the random sampler), so that the variance of its mean
// is the per-sample variance over the count, which the reference holds. (A stratified sampler
// would do better than that, and make the test blind to small errors.)
constexpr int kTestSpp = 16384;

Scene cornell(float white_scale) {
  Scene s = make_cornell_scene();
  s.settings.integrator = "path";
  s.settings.width = kSize;
  s.settings.height = kSize;
  s.settings.max_depth = kMaxDepth;
  s.settings.sampler = "random";
  s.settings.spp = kTestSpp;
  s.settings.seed = 7;
  for (Material& m : s.materials) {
    if (m.name == "white") m.color = m.color * white_scale;
  }
  return s;
}

Film read_data(const std::string& name) { return read_image(test::source_dir() + "/tests/data/" + name); }

// The smallest two-sided p-value over every pixel and channel of the z-test of `scene`'s image
// against the reference, and the number of tests made. The variance of one sample comes from
// the reference's 64 batches; a heavy tail (rare bright paths) makes a batch-based estimate of
// the test's own variance too small, so the test does not estimate it from its own samples.
std::pair<double, int> smallest_p_value(const Scene& scene) {
  static const Film reference = read_data("cornell-path-16x16.pfm");
  static const Film variance = read_data("cornell-path-16x16-variance.pfm");
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  Film film(kSize, kSize);
  RenderOptions options;
  options.threads = 2;
  options.tile_size = 4;  // 16 tiles, so that both threads work
  render(scene, *accel, film, options);
  double smallest = 1.0;
  int tests = 0;
  for (std::size_t i = 0; i < film.pixels().size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double var = static_cast<double>(variance.pixels()[i][k]) * (1.0 / kTestSpp + 1.0 / kReferenceSpp);
      const double diff = static_cast<double>(film.pixels()[i][k]) - static_cast<double>(reference.pixels()[i][k]);
      ++tests;
      if (var <= 0.0) {
        if (std::fabs(diff) > 1e-6) smallest = 0.0;
        continue;
      }
      smallest = std::min(smallest, std::erfc(std::fabs(diff) / std::sqrt(2.0 * var)));
    }
  }
  return {smallest, tests};
}

// The Sidak-corrected level: the whole image passes by chance with probability 1 - alpha.
double sidak(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

TEST(CornellReference, PathTracedBoxMatchesItsReference) {
  const auto [p, tests] = smallest_p_value(cornell(1.f));
  RecordProperty("smallest_p_value", std::to_string(p));
  EXPECT_GT(p, sidak(0.01, tests)) << "smallest p-value " << p << " over " << tests << " tests";
}

TEST(CornellReference, NegativeControlWithDarkerPaintFails) {
  const auto [p, tests] = smallest_p_value(cornell(0.96f));
  RecordProperty("smallest_p_value", std::to_string(p));
  EXPECT_LT(p, sidak(0.01, tests)) << "a box with 4% darker white paint passed: smallest p-value " << p;
}

}  // namespace
}  // namespace raylab
