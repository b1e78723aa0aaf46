// False-colour maps through the real binary: every map the size of the render it describes, so
// that it can be laid over the image, and its legend in a file of its own with readable labels.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "../io/legend_text.h"
#include "cli_fixture.h"
#include "raylab/io/heatmap.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

using namespace cli_test;
using test::read_png_rgb8;
using test::shows_text;

TEST_F(Cli, CompareHeatmapsAreTheRaysImageSizeWithLegendsBeside) {
  // An odd size, narrower than any legend: nothing may be widened or padded.
  const std::string maps = out_file("maps");
  const CliResult r =
      run("compare 'spd:balls?size=1' --accels bvh,grid --width 37 --height 23 --repeat 1 -q"
          " --heatmaps '" +
          maps + "'");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  for (const std::string accel : {"bvh", "grid"}) {
    for (const std::string kind : {"tests", "nodes"}) {
      const std::string base = maps + "/" + accel + "-" + kind;
      const Rgb8Image map = read_png_rgb8(base + ".png");
      EXPECT_EQ(map.width, 37) << base;
      EXPECT_EQ(map.height, 23) << base;
      const Rgb8Image legend = read_png_rgb8(base + ".legend.png");
      EXPECT_EQ(legend.height, heat_legend_height()) << base;
      const std::string what = kind == "tests" ? "PRIMITIVE TESTS" : "NODES OR CELLS";
      EXPECT_TRUE(shows_text(legend, 0, " " + what + " PER PIXEL, LOG SCALE", kLegendFontScale)) << base;
      EXPECT_TRUE(shows_text(legend, 0, "0", kLegendFontScale)) << base;  // the scale starts at zero
    }
  }
}

TEST_F(Cli, SampleMapIsTheRenderSizeWithItsLegendBeside) {
  const std::string out = out_file("a.png");
  const CliResult r =
      run("render aa-edges --sampler adaptive --width 64 --height 48 -q --aov samples -o '" + out + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const Rgb8Image map = read_png_rgb8(out_file("a.samples.png"));
  EXPECT_EQ(map.width, 64);
  EXPECT_EQ(map.height, 48);
  // The legend's end labels are the smallest and largest counts of the EXR layer.
  const std::vector<ImageLayer> layers = read_exr_channels(out_file("a.samples.exr"));
  const auto layer =
      std::find_if(layers.begin(), layers.end(), [](const ImageLayer& l) { return l.name == "samples.Y"; });
  ASSERT_NE(layer, layers.end());
  const auto [lo, hi] = std::minmax_element(layer->values.begin(), layer->values.end());
  ASSERT_LT(*lo, *hi) << "the adaptive sampler refined nothing: no range to show";
  const Rgb8Image legend = read_png_rgb8(out_file("a.samples.legend.png"));
  EXPECT_GE(legend.width, 64);
  EXPECT_TRUE(shows_text(legend, 0, "PRIMARY SAMPLES PER PIXEL, LOG SCALE", kLegendFontScale));
  EXPECT_TRUE(shows_text(legend, 0, heat_legend_label(*lo), kLegendFontScale)) << *lo;
  EXPECT_TRUE(shows_text(legend, 0, heat_legend_label(*hi), kLegendFontScale)) << *hi;
}

}  // namespace
}  // namespace raylab
