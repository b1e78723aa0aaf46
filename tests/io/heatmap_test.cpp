// Heat maps: the render's size, one colour scale across structures, a legend of their own with
// its bar and labels, exact PNG colours, and no partial files.

#include "raylab/io/heatmap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "legend_text.h"
#include "raylab/core/error.h"
#include "raylab/io/image_io.h"
#include "raylab/lab/compare_charts.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

float luma(Rgb8 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// The PNG at `path` back as 8-bit colours.
Rgb8 png_pixel(const Film& film, int x, int y) {
  const Color c = film.at(x, y);
  auto byte = [](float v) { return static_cast<std::uint8_t>(std::lround(linear_to_srgb(v) * 255.f)); };
  return {byte(c.x), byte(c.y), byte(c.z)};
}

class HeatmapFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    m_dir = fs::temp_directory_path() /
            ("raylab-heatmap-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(m_dir);
  }
  void TearDown() override { fs::remove_all(m_dir); }
  fs::path m_dir;
};

TEST(Heatmap, ColourMapRunsFromDarkToLightWithoutGoingBack) {
  float previous = -1.f;
  for (int i = 0; i <= 64; ++i) {
    const float l = luma(heat_colour(i / 64.f));
    EXPECT_GT(l, previous) << i;  // perceptual maps brighten steadily: no false features
    previous = l;
  }
  EXPECT_EQ(heat_colour(-1.f), heat_colour(0.f));
  EXPECT_EQ(heat_colour(2.f), heat_colour(1.f));
  EXPECT_EQ(heat_colour(NAN), heat_colour(0.f));
}

TEST(Heatmap, ScaleIsLogarithmicFromZeroToTheMaximum) {
  const HeatScale s{999.0};
  EXPECT_EQ(s.position(0.0), 0.f);
  EXPECT_FLOAT_EQ(s.position(999.0), 1.f);
  EXPECT_FLOAT_EQ(s.position(5000.0), 1.f);
  EXPECT_NEAR(s.position(std::sqrt(1000.0) - 1.0), 0.5f, 1e-6f);  // log(1 + v) halfway
}

TEST(Heatmap, MapIsExactlyTheRenderSize) {
  std::vector<std::uint32_t> values(200 * 50);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<std::uint32_t>(i % 200);
  const HeatScale scale{500.0};
  const Rgb8Image img = render_heatmap(values, 200, 50, scale);
  ASSERT_EQ(img.width, 200);
  ASSERT_EQ(img.height, 50);
  for (int y : {0, 49}) {
    for (int x = 0; x < 200; ++x) ASSERT_EQ(img.at(x, y), scale.colour(x)) << x << "," << y;
  }
  const std::vector<std::uint32_t> narrow(16 * 8, 3);
  const Rgb8Image small = render_heatmap(narrow, 16, 8, HeatScale{10.0});
  EXPECT_EQ(small.width, 16);  // no longer widened for a legend
  EXPECT_EQ(small.height, 8);
  EXPECT_THROW(render_heatmap(narrow, 16, 9, HeatScale{10.0}), std::invalid_argument);
}

TEST(Heatmap, LegendHasTheColourBarAndLabels) {
  const HeatScale scale{500.0};
  const Rgb8Image img = render_heat_legend(scale, "bvh tests", 400);
  ASSERT_EQ(img.width, 400);
  ASSERT_EQ(img.height, heat_legend_height());
  // A row runs through the whole colour map, first to last colour.
  int bar_row = -1;
  for (int y = 0; y < img.height && bar_row < 0; ++y) {
    int first = -1, last = -1;
    for (int x = 0; x < img.width; ++x) {
      if (img.at(x, y) == heat_colour(0.f) && first < 0) first = x;
      if (img.at(x, y) == heat_colour(1.f)) last = x;
    }
    if (first >= 0 && last > first + img.width / 2) bar_row = y;
  }
  ASSERT_GE(bar_row, 0) << "no colour bar";
  // The title above the bar, every tick label that fits below it: 0, 1, 2, 5, ..., 200, 500.
  EXPECT_TRUE(test::shows_text(img, 0, "BVH TESTS", kLegendFontScale));
  for (const char* label : {"0", "10", "100", "500"}) {
    EXPECT_TRUE(test::shows_text(img, bar_row, label, kLegendFontScale)) << label;
  }
}

TEST(Heatmap, LegendIsWidenedForItsTitleAndLabels) {
  const Rgb8Image narrow = render_heat_legend(HeatScale{10.0}, "x", 16);
  EXPECT_GE(narrow.width, 320);  // room for the labels under the narrowest map
  const std::string title(80, 'w');
  const Rgb8Image titled = render_heat_legend(HeatScale{10.0}, title, 100);
  EXPECT_GE(titled.width, text_width(title, kLegendFontScale));
  EXPECT_TRUE(test::shows_text(titled, 0, title, kLegendFontScale));
}

TEST(Heatmap, LegendPathSitsBesideTheMap) {
  EXPECT_EQ(heat_legend_path("maps/bvh-tests.png"), "maps/bvh-tests.legend.png");
  EXPECT_EQ(heat_legend_path("out.samples.png"), "out.samples.legend.png");
  EXPECT_EQ(heat_legend_path("A.PNG"), "A.legend.png");
  EXPECT_EQ(heat_legend_path("map"), "map.legend.png");
}

TEST(Heatmap, TickLabelsReadAsNumbers) {
  EXPECT_EQ(heat_legend_label(0), "0");
  EXPECT_EQ(heat_legend_label(9999), "9999");
  EXPECT_EQ(heat_legend_label(25000), "25K");
  EXPECT_EQ(heat_legend_label(3e7), "30M");
  EXPECT_EQ(heat_legend_ticks(HeatScale{500.0}), (std::vector<double>{0, 1, 2, 5, 10, 20, 50, 100, 200, 500}));
  EXPECT_EQ(heat_legend_ticks(HeatScale{64.0, false, 4.0}), (std::vector<double>{4, 20, 40, 60, 64}));
}

TEST(Heatmap, FontGlyphsAreDistinct) {
  std::set<std::string> seen;
  for (char c : std::string("0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ.,-+=/:()_%^'")) {
    ASSERT_TRUE(has_glyph(c)) << c;
    Rgb8Image img(kGlyphWidth, kGlyphHeight);
    draw_text(img, 0, 0, std::string(1, c), Rgb8{255, 255, 255}, 1);
    std::string ink;
    for (const Rgb8& p : img.pixels) ink += p.r ? '#' : ' ';
    EXPECT_NE(ink, std::string(kGlyphWidth * kGlyphHeight, ' ')) << "glyph " << c << " is blank";
    EXPECT_TRUE(seen.insert(ink).second) << "glyph " << c << " looks like another";
  }
  EXPECT_TRUE(has_glyph('a'));  // drawn as a capital
  EXPECT_FALSE(has_glyph('#'));
  EXPECT_EQ(text_width("12", 2), 22);
  Rgb8Image clip(4, 4);
  draw_text(clip, -2, -2, "88", Rgb8{1, 1, 1}, 3);  // drawing off the edges is clipped, not a crash
}

TEST_F(HeatmapFiles, PngKeepsTheExactColours) {
  fs::create_directories(m_dir);
  Rgb8Image img(256, 2);
  for (int x = 0; x < 256; ++x) {
    img.at(x, 0) = {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(x)};
    img.at(x, 1) = heat_colour(x / 255.f);
  }
  const std::string path = (m_dir / "grey.png").string();
  write_png(img, path);
  const Film film = read_image(path);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 256; ++x) ASSERT_EQ(png_pixel(film, x, y), img.at(x, y)) << x << "," << y;
  }
}

TEST_F(HeatmapFiles, OneScaleForEveryStructure) {
  CompareResult r;
  r.width = 4;
  r.height = 3;
  for (const char* name : {"cheap", "costly", "embree"}) {
    AccelMeasure m;
    m.name = name;
    m.has_counts = std::string(name) != "embree";
    m.pixel_tests.assign(12, 1);
    m.pixel_nodes.assign(12, 2);
    r.accels.push_back(m);
  }
  r.accels[0].pixel_tests[5] = 10;    // the cheap structure's worst pixel
  r.accels[1].pixel_tests[5] = 10;    // the same value in the costly one ...
  r.accels[1].pixel_tests[6] = 1000;  // ... whose worst pixel sets the shared maximum
  const std::vector<std::string> written = write_compare_heatmaps(r, (m_dir / "maps").string());
  ASSERT_EQ(written.size(), 8u);  // tests and nodes, each with its legend, for both counting structures
  for (const std::string& p : written) EXPECT_TRUE(fs::exists(p)) << p;
  EXPECT_FALSE(fs::exists(m_dir / "maps" / "embree-tests.png"));  // none for embree
  EXPECT_TRUE(fs::exists(m_dir / "maps" / "cheap-tests.legend.png"));
  const Film cheap = read_image((m_dir / "maps" / "cheap-tests.png").string());
  const Film costly = read_image((m_dir / "maps" / "costly-tests.png").string());
  EXPECT_EQ(cheap.width(), 4);
  EXPECT_EQ(cheap.height(), 3);
  const HeatScale shared{1000.0};
  // Same value, same colour in both maps; the cheap map's maximum is not its top colour.
  EXPECT_EQ(png_pixel(cheap, 1, 1), png_pixel(costly, 1, 1));
  EXPECT_EQ(png_pixel(cheap, 1, 1), shared.colour(10));
  EXPECT_NE(png_pixel(cheap, 1, 1), heat_colour(1.f));
  EXPECT_EQ(png_pixel(costly, 2, 1), heat_colour(1.f));
  EXPECT_EQ(png_pixel(cheap, 0, 0), png_pixel(costly, 0, 0));
}

TEST_F(HeatmapFiles, FailedWritesLeaveNothing) {
  Rgb8Image img(8, 8);
  EXPECT_THROW(write_png(img, (m_dir / "missing" / "x.png").string()), InputError);
  EXPECT_FALSE(fs::exists(m_dir));
  // A file where the folder should be.
  fs::create_directories(m_dir);
  std::ofstream(m_dir / "file") << "x";
  CompareResult r;
  EXPECT_THROW(write_compare_heatmaps(r, (m_dir / "file").string()), InputError);
  EXPECT_EQ(std::distance(fs::directory_iterator(m_dir), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace raylab
