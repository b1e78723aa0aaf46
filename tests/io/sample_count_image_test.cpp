// The false-colour sample-count image: colours placed by the linear or log scale between the
// smallest and largest count, exactly the render's size, a legend that shows that range, and the
// PNGs written atomically.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "legend_text.h"
#include "raylab/core/error.h"
#include "raylab/io/heatmap.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

using test::shows_text;

// The legend of `counts` as write_sample_count_png draws it beside a map `width` wide.
Rgb8Image legend_of(const std::vector<std::uint32_t>& counts, CountScale scale, int width) {
  return render_heat_legend(sample_count_scale(counts, scale), sample_count_title(scale), width);
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
  ASSERT_EQ(img.width, 40);  // the render's size, to lay over it
  ASSERT_EQ(img.height, 20);
  EXPECT_EQ(img.at(0, 0), heat_colour(1.f));  // 64
  EXPECT_EQ(img.at(1, 0), heat_colour(0.f));  // 4
  for (int x = 20; x < 40; ++x) {
    const double v = c[std::size_t(x)];
    EXPECT_EQ(img.at(x, 0), heat_colour(static_cast<float>((v - 4.0) / 60.0))) << x;
  }
  const Rgb8Image legend = legend_of(c, CountScale::kLinear, 40);
  EXPECT_TRUE(shows_text(legend, 0, "4", kLegendFontScale));
  EXPECT_TRUE(shows_text(legend, 0, "64", kLegendFontScale));
  EXPECT_TRUE(shows_text(legend, 0, "PRIMARY SAMPLES PER PIXEL, LINEAR SCALE", kLegendFontScale));
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
  const Rgb8Image legend = legend_of(c, CountScale::kLog, 40);
  EXPECT_TRUE(shows_text(legend, 0, "4", kLegendFontScale));
  EXPECT_TRUE(shows_text(legend, 0, "64", kLegendFontScale));
  EXPECT_TRUE(shows_text(legend, 0, "PRIMARY SAMPLES PER PIXEL, LOG SCALE", kLegendFontScale));
}

TEST(SampleCountImage, AUniformCountIsOneColourAgainstZero) {
  const std::vector<std::uint32_t> c(50 * 30, 16);
  const Rgb8Image img = render_sample_count_image(c, 50, 30, CountScale::kLinear);
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 50; ++x) ASSERT_EQ(img.at(x, y), heat_colour(1.f));
  }
  const Rgb8Image legend = legend_of(c, CountScale::kLinear, 50);
  EXPECT_TRUE(shows_text(legend, 0, "0", kLegendFontScale));
  EXPECT_TRUE(shows_text(legend, 0, "16", kLegendFontScale));
  EXPECT_THROW(render_sample_count_image(c, 50, 31), std::invalid_argument);
}

TEST(SampleCountImage, LegendIsAsWideAsAWideMap) {
  const std::vector<std::uint32_t> c(700 * 10, 3);
  const Rgb8Image img = render_sample_count_image(c, 700, 10);
  EXPECT_EQ(img.width, 700);
  EXPECT_EQ(img.height, 10);
  const Rgb8Image legend = legend_of(c, CountScale::kLog, 700);
  EXPECT_EQ(legend.width, 700);  // can be set under the map
  EXPECT_EQ(legend.height, heat_legend_height());
  EXPECT_TRUE(shows_text(legend, 0, "3", kLegendFontScale));
}

TEST(SampleCountImage, PngIsWrittenAtomicallyWithTheImagesColours) {
  const fs::path dir = fs::temp_directory_path() / ("raylab-sample-count-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<std::uint32_t> c = counts();
  const std::string path = (dir / "spp.png").string();
  const std::vector<std::string> written = write_sample_count_png(c, 40, 20, path, CountScale::kLinear);
  EXPECT_EQ(written, (std::vector<std::string>{path, (dir / "spp.legend.png").string()}));
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
  EXPECT_EQ(files, 2u);  // the map and its legend; no temporary left behind
  fs::remove_all(dir);
}

}  // namespace
}  // namespace raylab
