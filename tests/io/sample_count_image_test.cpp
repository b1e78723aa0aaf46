// The false-colour sample-count image: colours placed by the linear or log scale between the
// smallest and largest count, a legend that shows that range, and the PNG written atomically.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "raylab/core/error.h"
#include "raylab/io/heatmap.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

constexpr Rgb8 kInk{235, 235, 235};

// True when `text`, drawn by draw_text at font scale `s`, appears in the legend strip below
// row `top` as a whole word (no ink right before or after it).
bool legend_shows(const Rgb8Image& img, int top, std::string_view text, int s) {
  const int w = text_width(text, s), h = 5 * s;
  Rgb8Image stamp(w, h);
  draw_text(stamp, 0, 0, text, kInk, s);
  for (int y = top; y + h <= img.height; ++y) {
    for (int x = 0; x + w <= img.width; ++x) {
      bool match = true;
      for (int sy = 0; sy < h && match; ++sy) {
        for (int sx = 0; sx < w && match; ++sx) match = (img.at(x + sx, y + sy) == kInk) == (stamp.at(sx, sy) == kInk);
      }
      for (int sy = 0; sy < h && match; ++sy) {
        for (int d = 1; d <= 2 * s && match; ++d) {  // the gap between glyphs and the next glyph's edge
          if (x - d >= 0) match = !(img.at(x - d, y + sy) == kInk);
          if (match && x + w - 1 + d < img.width) match = !(img.at(x + w - 1 + d, y + sy) == kInk);
        }
      }
      if (match) return true;
    }
  }
  return false;
}

// Counts 4 .. 64 over a 40 x 20 image: left half 4, then a ramp of values to 64.
std::vector<std::uint32_t> counts() {
  std::vector<std::uint32_t> c(40 * 20, 4);
  for (int y = 0; y < 20; ++y) {
    for (int x = 20; x < 40; ++x) c[std::size_t(y) * 40 + x] = static_cast<std::uint32_t>(4 + (x - 20) * 3 + (y % 2));
  }
  c[0] = 64;
  return c;
}

TEST(SampleCountImage, LinearScaleRunsFromTheSmallestToTheLargestCount) {
  const std::vector<std::uint32_t> c = counts();
  const Rgb8Image img = render_sample_count_image(c, 40, 20, CountScale::kLinear);
  ASSERT_GE(img.width, 160);  // widened for the legend
  ASSERT_EQ(img.height, 20 + legend_height(1));
  EXPECT_EQ(img.at(0, 0), heat_colour(1.f));  // 64
  EXPECT_EQ(img.at(1, 0), heat_colour(0.f));  // 4
  for (int x = 20; x < 40; ++x) {
    const double v = c[std::size_t(x)];
    EXPECT_EQ(img.at(x, 0), heat_colour(static_cast<float>((v - 4.0) / 60.0))) << x;
  }
  EXPECT_TRUE(legend_shows(img, 20, "4", 1));
  EXPECT_TRUE(legend_shows(img, 20, "64", 1));
  EXPECT_TRUE(legend_shows(img, 20, "PRIMARY SAMPLES PER PIXEL, LINEAR SCALE", 1));
}

TEST(SampleCountImage, LogScaleSpreadsTheLowCounts) {
  const std::vector<std::uint32_t> c = counts();
  const Rgb8Image img = render_sample_count_image(c, 40, 20, CountScale::kLog);
  for (int x = 20; x < 40; ++x) {
    const double v = c[std::size_t(x)];
    EXPECT_EQ(img.at(x, 0), heat_colour(static_cast<float>(std::log1p(v - 4.0) / std::log1p(60.0)))) << x;
  }
  // 7 samples (3 above the least) sit far further up the map than on the linear scale.
  const HeatScale log_scale{64.0, true, 4.0}, linear_scale{64.0, false, 4.0};
  EXPECT_GT(log_scale.position(7.0), 2.f * linear_scale.position(7.0));
  EXPECT_TRUE(legend_shows(img, 20, "4", 1));
  EXPECT_TRUE(legend_shows(img, 20, "64", 1));
  EXPECT_TRUE(legend_shows(img, 20, "PRIMARY SAMPLES PER PIXEL, LOG SCALE", 1));
}

TEST(SampleCountImage, AUniformCountIsOneColourAgainstZero) {
  const std::vector<std::uint32_t> c(50 * 30, 16);
  const Rgb8Image img = render_sample_count_image(c, 50, 30, CountScale::kLinear);
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 50; ++x) ASSERT_EQ(img.at(x, y), heat_colour(1.f));
  }
  EXPECT_TRUE(legend_shows(img, 30, "0", 1));
  EXPECT_TRUE(legend_shows(img, 30, "16", 1));
  EXPECT_THROW(render_sample_count_image(c, 50, 31), std::invalid_argument);
}

TEST(SampleCountImage, LargeImagesUseTheDoubleFont) {
  const std::vector<std::uint32_t> c(400 * 10, 3);
  const Rgb8Image img = render_sample_count_image(c, 400, 10);
  EXPECT_EQ(img.width, 400);
  EXPECT_EQ(img.height, 10 + legend_height(2));
  EXPECT_TRUE(legend_shows(img, 10, "3", 2));
}

TEST(SampleCountImage, PngIsWrittenAtomicallyWithTheImagesColours) {
  const fs::path dir = fs::temp_directory_path() / ("raylab-sample-count-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<std::uint32_t> c = counts();
  const std::string path = (dir / "spp.png").string();
  write_sample_count_png(c, 40, 20, path, CountScale::kLinear);
  const Film f = read_image(path);
  const Rgb8Image img = render_sample_count_image(c, 40, 20, CountScale::kLinear);
  ASSERT_EQ(f.width(), img.width);
  ASSERT_EQ(f.height(), img.height);
  for (int x : {0, 1, 25, 39}) {
    const Color p = f.at(x, 0);
    const Rgb8 expected = img.at(x, 0);
    EXPECT_EQ(std::lround(linear_to_srgb(p.x) * 255.f), expected.r) << x;
    EXPECT_EQ(std::lround(linear_to_srgb(p.y) * 255.f), expected.g) << x;
    EXPECT_EQ(std::lround(linear_to_srgb(p.z) * 255.f), expected.b) << x;
  }
  EXPECT_THROW(write_sample_count_png(c, 40, 20, (dir / "no" / "spp.png").string()), InputError);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);  // no temporary left behind
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raylab
