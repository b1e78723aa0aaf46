// Image error measures against analytic answers and brute-force references.

#include "raylab/lab/image_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "raylab/core/error.h"
#include "raylab/core/rng.h"
#include "raylab/core/srgb.h"

namespace raylab {
namespace {

Film constant(int w, int h, Color c) {
  Film f(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) f.at(x, y) = c;
  }
  return f;
}

// A smooth picture with some structure: a diagonal ramp and a bright disc.
Film picture(int w, int h) {
  Film f(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float r = std::hypot(x - w * 0.6f, y - h * 0.4f);
      const float ramp = 0.1f + 0.5f * static_cast<float>(x + y) / static_cast<float>(w + h);
      f.at(x, y) = r < h * 0.25f ? Color{0.9f, 0.8f, 0.3f} : Color{ramp, ramp * 0.5f, 0.2f};
    }
  }
  return f;
}

// `f` plus independent uniform noise of amplitude `amp` per channel.
Film noisy(const Film& f, float amp, std::uint64_t seed) {
  Film out = f;
  Pcg32 rng(seed);
  for (int y = 0; y < f.height(); ++y) {
    for (int x = 0; x < f.width(); ++x) {
      Color& c = out.at(x, y);
      for (int k = 0; k < 3; ++k) c[k] = std::max(0.f, c[k] + amp * (2.f * rng.next_float() - 1.f));
    }
  }
  return out;
}

double luma(Color c) {
  return 0.2126 * linear_to_srgb(c.x) + 0.7152 * linear_to_srgb(c.y) + 0.0722 * linear_to_srgb(c.z);
}

// SSIM straight from the definition: for every 11x11 window inside the image, the weighted
// means, variances and covariance summed over the window in 2-D, then the mean of the index.
double brute_ssim(const Film& a, const Film& b) {
  constexpr int r = 5;
  double w[2 * r + 1][2 * r + 1], total = 0.0;
  for (int j = -r; j <= r; ++j) {
    for (int i = -r; i <= r; ++i) total += (w[j + r][i + r] = std::exp(-(i * i + j * j) / (2.0 * 1.5 * 1.5)));
  }
  double sum = 0.0;
  int windows = 0;
  for (int cy = r; cy + r < a.height(); ++cy) {
    for (int cx = r; cx + r < a.width(); ++cx) {
      double mx = 0, my = 0;
      for (int j = -r; j <= r; ++j) {
        for (int i = -r; i <= r; ++i) {
          mx += w[j + r][i + r] / total * luma(a.at(cx + i, cy + j));
          my += w[j + r][i + r] / total * luma(b.at(cx + i, cy + j));
        }
      }
      double vx = 0, vy = 0, cxy = 0;
      for (int j = -r; j <= r; ++j) {
        for (int i = -r; i <= r; ++i) {
          const double dx = luma(a.at(cx + i, cy + j)) - mx, dy = luma(b.at(cx + i, cy + j)) - my;
          vx += w[j + r][i + r] / total * dx * dx;
          vy += w[j + r][i + r] / total * dy * dy;
          cxy += w[j + r][i + r] / total * dx * dy;
        }
      }
      const double c1 = 1e-4, c2 = 9e-4;
      sum += (2 * mx * my + c1) * (2 * cxy + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ++windows;
    }
  }
  return sum / windows;
}

TEST(ImageMetrics, IdenticalImagesHaveNoError) {
  const Film a = picture(40, 30);
  const ImageError e = measure_error(a, a);
  EXPECT_EQ(e.rmse, 0.0);
  EXPECT_EQ(e.psnr, std::numeric_limits<double>::infinity());
  EXPECT_EQ(e.ssim, 1.0);
  EXPECT_EQ(e.p999, 0.0);
  const std::vector<float> p = pixel_errors(a, a);
  EXPECT_EQ(p.size(), 40u * 30u);
  EXPECT_TRUE(std::all_of(p.begin(), p.end(), [](float v) { return v == 0.f; }));
}

TEST(ImageMetrics, ConstantOffsetGivesExactRmseAndPsnr) {
  const Film ref = constant(20, 10, {0.2f, 0.2f, 0.2f});
  const Film img = constant(20, 10, {0.25f, 0.15f, 0.25f});
  const ImageError e = measure_error(img, ref);
  const double d = 0.25 - double(0.2f);  // the float values as stored
  EXPECT_NEAR(e.rmse, std::sqrt((2 * d * d + std::pow(double(0.15f) - double(0.2f), 2)) / 3.0), 1e-7);
  const double up = double(linear_to_srgb(0.25f)) - linear_to_srgb(0.2f);
  const double down = double(linear_to_srgb(0.15f)) - linear_to_srgb(0.2f);
  EXPECT_NEAR(e.psnr, 10.0 * std::log10(3.0 / (2 * up * up + down * down)), 1e-9);
  // Every pixel has the same error, so every percentile is that error.
  EXPECT_NEAR(e.p999, e.rmse, 1e-7);
  // PSNR clamps like a display: beyond white nothing changes.
  const ImageError bright = measure_error(constant(4, 4, {3.f, 3.f, 3.f}), constant(4, 4, {1.f, 1.f, 1.f}));
  EXPECT_NEAR(bright.rmse, 2.0, 1e-12);
  EXPECT_EQ(bright.psnr, std::numeric_limits<double>::infinity());
}

TEST(ImageMetrics, SsimOfFlatImagesIsTheLuminanceTerm) {
  const Color ca{0.3f, 0.3f, 0.3f}, cb{0.6f, 0.6f, 0.6f};
  const double a = linear_to_srgb(0.3f), b = linear_to_srgb(0.6f);
  const double expected = (2 * a * b + 1e-4) / (a * a + b * b + 1e-4);  // no variance: the contrast term is 1
  EXPECT_NEAR(measure_error(constant(24, 16, ca), constant(24, 16, cb)).ssim, expected, 1e-9);
}

TEST(ImageMetrics, SsimMatchesTheDefinitionWindowByWindow) {
  const Film a = picture(23, 17), b = noisy(a, 0.2f, 7);
  EXPECT_NEAR(measure_error(b, a).ssim, brute_ssim(b, a), 1e-10);
}

TEST(ImageMetrics, SsimDropsWithNoiseAndIsSymmetric) {
  const Film a = picture(48, 32);
  const Film light = noisy(a, 0.05f, 1), heavy = noisy(a, 0.3f, 2);
  const double s_light = measure_error(light, a).ssim, s_heavy = measure_error(heavy, a).ssim;
  EXPECT_LT(s_light, 1.0);
  EXPECT_LT(s_heavy, s_light);
  EXPECT_GT(s_heavy, -1.0);
  EXPECT_EQ(measure_error(a, heavy).ssim, s_heavy);  // symmetric to the bit
  EXPECT_GT(measure_error(heavy, a).rmse, measure_error(light, a).rmse);
  EXPECT_LT(measure_error(heavy, a).psnr, measure_error(light, a).psnr);
}

TEST(ImageMetrics, SmallImagesUseTheWindowThatFits) {
  const Film a = picture(6, 9), b = noisy(a, 0.2f, 3);
  EXPECT_EQ(measure_error(a, a).ssim, 1.0);
  const double s = measure_error(b, a).ssim;
  EXPECT_TRUE(std::isfinite(s));
  EXPECT_LT(s, 1.0);
  EXPECT_EQ(measure_error(constant(1, 1, {0.5f, 0.5f, 0.5f}), constant(1, 1, {0.5f, 0.5f, 0.5f})).ssim, 1.0);
}

TEST(ImageMetrics, PercentileIsTheNearestRankOfThePixelErrors) {
  // A grey image against black: each pixel's error is its grey level. 2000 pixels in a
  // scrambled order, with a few outliers at the top.
  const int w = 50, h = 40;
  Film img(w, h);
  const Film black(w, h);
  Pcg32 rng(11);
  std::vector<float> levels;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float v = (x * 7 + y * 13) % 17 == 0 ? 5.f + rng.next_float() : rng.next_float();
      img.at(x, y) = {v, v, v};
      levels.push_back(v);
    }
  }
  const std::vector<float> errors = pixel_errors(img, black);
  for (std::size_t i = 0; i < errors.size(); ++i) EXPECT_NEAR(errors[i], levels[i], 1e-6f);
  std::vector<float> sorted = errors;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t rank = 1998;  // ceil(0.999 * 2000), exactly
  EXPECT_EQ(measure_error(img, black).p999, sorted[rank - 1]);
  EXPECT_NE(sorted[rank - 1], sorted.back());  // a real percentile, not the maximum
}

TEST(ImageMetrics, SizeMismatchThrowsNamingBothSizes) {
  try {
    measure_error(Film(4, 3), Film(3, 4));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("4x3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("3x4"), std::string::npos) << e.what();
  }
  EXPECT_THROW(pixel_errors(Film(4, 3), Film(4, 4)), InputError);
}

}  // namespace
}  // namespace raylab
