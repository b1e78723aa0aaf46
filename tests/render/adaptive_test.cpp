// The adaptive samplers on scenes whose answer is known exactly: a flat image (only the cheapest
// rays), a single straight edge (which pixels are refined), and the invariants every render
// keeps (determinism whatever the threads and tiles, exact colour where nothing varies).

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "raylab/accel/factory.h"
#include "raylab/render/adaptive.h"
#include "raylab/render/renderer.h"

namespace raylab {
namespace {

constexpr int kWidth = 48;
constexpr int kHeight = 36;

// An unlit scene laid out in image coordinates: world (X, H - Y, 0) shows at image position
// (X, Y), one world unit per pixel (a pinhole looking straight at the plane maps it linearly).
Scene pixel_plane_scene() {
  Scene scene;
  scene.settings.width = kWidth;
  scene.settings.height = kHeight;
  scene.settings.max_depth = 1;
  scene.settings.ambient = {1.f, 1.f, 1.f};  // no lights: a surface shows its colour exactly
  scene.settings.background = {0.f, 0.f, 0.f};
  const float d = 1000.f;
  scene.camera.from = {kWidth / 2.f, kHeight / 2.f, d};
  scene.camera.at = {kWidth / 2.f, kHeight / 2.f, 0.f};
  scene.camera.vfov_degrees = 2.f * std::atan(kHeight / 2.f / d) * 180.f / 3.14159265358979f;
  return scene;
}

Vec3 image_to_world(float x, float y) { return {x, static_cast<float>(kHeight) - y, 0.f}; }

// A white region bounded by the line through image points a and b: the side to the left of a->b
// (in image coordinates), out to well beyond the frame.
void add_half_plane(Scene& scene, Vec3 a_img, Vec3 b_img) {
  Material white;
  white.color = {1.f, 1.f, 1.f};
  const auto obj = scene.add_object("half plane", scene.add_material(white));
  const Vec3 dir = normalize(b_img - a_img);
  const Vec3 left{dir.y, -dir.x, 0.f};  // image y points down
  const float far = 1000.f;
  const Vec3 p0 = a_img - dir * far;
  const Vec3 p1 = a_img + dir * far;
  const Vec3 p2 = p1 + left * far;
  const Vec3 p3 = p0 + left * far;
  auto w = [](Vec3 p) { return image_to_world(p.x, p.y); };
  scene.geometry.add(Triangle{w(p0), w(p1), w(p2)}, obj);
  scene.geometry.add(Triangle{w(p0), w(p2), w(p3)}, obj);
}

struct Outcome {
  Film film;
  RenderResult result;
};

Outcome render_with(Scene scene, const std::string& sampler, int depth, int threads = 0, int tile = 16) {
  scene.settings.sampler = sampler;
  scene.settings.aa_depth = depth;
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  Outcome out{Film(kWidth, kHeight), {}};
  RenderOptions options;
  options.threads = threads;
  options.tile_size = tile;
  out.result = render(scene, *accel, out.film, options);
  return out;
}

// Pixels whose interior the line f(x, y) = 0 crosses (corner values of both signs).
std::vector<bool> crossed_pixels(const std::function<double(double, double)>& f) {
  std::vector<bool> crossed(std::size_t(kWidth) * kHeight, false);
  for (int py = 0; py < kHeight; ++py) {
    for (int px = 0; px < kWidth; ++px) {
      const double v[4] = {f(px, py), f(px + 1, py), f(px, py + 1), f(px + 1, py + 1)};
      const double lo = std::min({v[0], v[1], v[2], v[3]});
      const double hi = std::max({v[0], v[1], v[2], v[3]});
      crossed[std::size_t(py) * kWidth + px] = lo < 0.0 && hi > 0.0;
    }
  }
  return crossed;
}

std::vector<bool> with_neighbours(const std::vector<bool>& set) {
  std::vector<bool> out(set.size(), false);
  for (int py = 0; py < kHeight; ++py) {
    for (int px = 0; px < kWidth; ++px) {
      if (!set[std::size_t(py) * kWidth + px]) continue;
      for (int y = std::max(0, py - 1); y <= std::min(kHeight - 1, py + 1); ++y) {
        for (int x = std::max(0, px - 1); x <= std::min(kWidth - 1, px + 1); ++x)
          out[std::size_t(y) * kWidth + x] = true;
      }
    }
  }
  return out;
}

TEST(AdaptiveCorners, FlatImageTracesOnlyTheCornerRays) {
  Scene scene = pixel_plane_scene();
  scene.settings.background = {0.3f, 0.5f, 0.7f};
  const Outcome out = render_with(scene, "adaptive-corners", 3);
  EXPECT_EQ(out.result.primary_rays(), std::uint64_t(kWidth + 1) * (kHeight + 1));
  for (std::uint32_t n : out.result.samples_per_pixel) EXPECT_EQ(n, 4u);
  for (const Color& c : out.film.pixels()) {
    EXPECT_FLOAT_EQ(c.x, 0.3f);
    EXPECT_FLOAT_EQ(c.z, 0.7f);
  }
}

TEST(AdaptiveSampler, FlatImageTracesOnlyTheBaseRays) {
  Scene scene = pixel_plane_scene();
  Material grey;
  grey.color = {0.4f, 0.4f, 0.4f};
  const auto obj = scene.add_object("wall", scene.add_material(grey));
  scene.geometry.add(Quad{{-100.f, -100.f, 0.f}, {400.f, 0.f, 0.f}, {0.f, 400.f, 0.f}}, obj);
  const Outcome out = render_with(scene, "adaptive", 3);
  EXPECT_EQ(out.result.primary_rays(), std::uint64_t(kWidth) * kHeight);
  for (const Color& c : out.film.pixels()) EXPECT_FLOAT_EQ(c.y, 0.4f);
}

TEST(AdaptiveCorners, RefinesExactlyThePixelsAStraightEdgeCrosses) {
  Scene scene = pixel_plane_scene();
  // Slope 0.3, offset chosen so that the line passes through no pixel corner.
  const Vec3 a{0.f, 10.37f, 0.f};
  const Vec3 b{10.f, 13.37f, 0.f};
  add_half_plane(scene, a, b);
  const Outcome out = render_with(scene, "adaptive-corners", 2);
  const auto crossed = crossed_pixels([](double x, double y) { return y - (0.3 * x + 10.37); });
  int n_crossed = 0;
  for (std::size_t i = 0; i < crossed.size(); ++i) {
    EXPECT_EQ(out.result.samples_per_pixel[i] > 4u, crossed[i]) << "pixel " << i % kWidth << "," << i / kWidth;
    n_crossed += crossed[i] ? 1 : 0;
  }
  EXPECT_GT(n_crossed, kWidth);  // the edge runs across the whole frame
}

TEST(AdaptiveSampler, RefinesTheCrossedPixelsAndTheirNeighbours) {
  // A vertical edge through the middle of pixel column 20: every crossed pixel is split in half,
  // so its 4 x 4 strata see both sides and the refinement must reach exactly columns 19 to 21.
  Scene scene = pixel_plane_scene();
  add_half_plane(scene, {20.5f, 0.f, 0.f}, {20.5f, 10.f, 0.f});
  const Outcome out = render_with(scene, "adaptive", 2);
  const auto crossed = crossed_pixels([](double x, double) { return x - 20.5; });
  const auto expected = with_neighbours(crossed);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(out.result.samples_per_pixel[i] > 1u, expected[i]) << "pixel " << i % kWidth << "," << i / kWidth;
  }
  // A 4 x 4 stratified pixel split in half is exactly half white.
  for (int py = 0; py < kHeight; ++py) EXPECT_FLOAT_EQ(out.film.at(20, py).x, 0.5f);
}

TEST(AdaptiveSampler, AnyEdgeRefinementLiesBetweenTheCrossedPixelsAndTheirNeighbours) {
  Scene scene = pixel_plane_scene();
  add_half_plane(scene, {0.f, 10.37f, 0.f}, {10.f, 13.37f, 0.f});
  const auto crossed = crossed_pixels([](double x, double y) { return y - (0.3 * x + 10.37); });
  const auto around = with_neighbours(crossed);
  for (std::uint64_t seed : {0u, 1u, 2u}) {
    scene.settings.seed = seed;
    const Outcome out = render_with(scene, "adaptive", 2);
    for (std::size_t i = 0; i < crossed.size(); ++i) {
      const bool refined = out.result.samples_per_pixel[i] > 1u;
      if (crossed[i]) {
        EXPECT_TRUE(refined) << "crossed pixel " << i % kWidth << "," << i / kWidth << " missed";
      }
      if (!around[i]) {
        EXPECT_FALSE(refined) << "pixel " << i % kWidth << "," << i / kWidth << " is far from the edge";
      }
    }
  }
}

TEST(AdaptiveSampler, DeeperLevelsOnlyWhereSamplesStillDiffer) {
  Scene scene = pixel_plane_scene();
  add_half_plane(scene, {0.f, 10.37f, 0.f}, {10.f, 13.37f, 0.f});
  const Outcome out = render_with(scene, "adaptive", 3);
  std::uint32_t most = 0;
  for (std::uint32_t n : out.result.samples_per_pixel) {
    most = std::max(most, n);
    EXPECT_TRUE(n == 1u || n >= 16u) << n;  // base only, or at least the 4 x 4 strata
    EXPECT_LE(n, 64u);
  }
  EXPECT_GT(most, 16u);  // the edge's quarters were split further
  std::uint64_t sum = 0;
  for (std::uint32_t n : out.result.samples_per_pixel) sum += n;
  EXPECT_EQ(sum, out.result.primary_rays());  // method b shares no sample between pixels
}

TEST(Adaptive, ImageDoesNotDependOnThreadsOrTiles) {
  Scene scene = pixel_plane_scene();
  add_half_plane(scene, {3.f, 2.2f, 0.f}, {40.f, 30.1f, 0.f});
  for (const char* sampler : {"adaptive", "adaptive-corners"}) {
    const Outcome a = render_with(scene, sampler, 3, 1, 16);
    const Outcome b = render_with(scene, sampler, 3, 2, 5);
    EXPECT_EQ(a.result.primary_rays(), b.result.primary_rays()) << sampler;
    EXPECT_EQ(a.result.samples_per_pixel, b.result.samples_per_pixel) << sampler;
    for (std::size_t i = 0; i < a.film.pixels().size(); ++i) {
      ASSERT_EQ(a.film.pixels()[i].x, b.film.pixels()[i].x) << sampler << " pixel " << i;
    }
  }
}

TEST(Adaptive, CoverageOfAnEdgeIsCloseToTheTruth) {
  // Area weighting: a pixel's value estimates the white area of the pixel.
  Scene scene = pixel_plane_scene();
  add_half_plane(scene, {0.f, 10.37f, 0.f}, {10.f, 13.37f, 0.f});
  for (const char* sampler : {"adaptive", "adaptive-corners"}) {
    const Outcome out = render_with(scene, sampler, 4);
    double worst = 0.0;
    for (int py = 0; py < kHeight; ++py) {
      for (int px = 0; px < kWidth; ++px) {
        // Exact white area (below the line in image coordinates = y > 0.3x + 10.37 is white? the
        // white side is left of a->b, which in image coordinates is y > line): integrate numerically.
        double area = 0.0;
        const int n = 64;
        for (int j = 0; j < n; ++j) {
          for (int i = 0; i < n; ++i) {
            const double x = px + (i + 0.5) / n;
            const double y = py + (j + 0.5) / n;
            area += (y - (0.3 * x + 10.37) < 0.0) ? 1.0 : 0.0;
          }
        }
        area /= n * n;
        worst = std::max(worst, std::abs(area - out.film.at(px, py).x));
      }
    }
    EXPECT_LT(worst, 0.15) << sampler;
  }
}

}  // namespace
}  // namespace raylab
