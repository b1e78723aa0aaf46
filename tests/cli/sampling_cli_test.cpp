// `raylab render` with the sampling options: rounding notices, the sample-count outputs, and
// usage errors for combinations that make no sense.

#include <algorithm>

#include "cli_fixture.h"
#include "raylab/io/image_io.h"

namespace raylab::cli_test {
namespace {

TEST_F(Cli, SppRoundingIsAnnounced) {
  const CliResult r = run("render aa-edges --width 32 --height 24 --sampler jittered --spp 10 -o " + out_file("a.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("--spp 10 rounded to 9 for the jittered sampler"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("9 spp jittered"), std::string::npos) << r.err;
}

// A bare mesh renders at 4 spp by default; --sampler center alone asks for one sample, not for
// the default rounded down with a notice about a --spp nobody gave. An explicit --spp still is.
TEST_F(Cli, CenterSamplerAloneTakesOneSampleWithoutANotice) {
  const std::string mesh = obj("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const CliResult alone = run("render '" + mesh + "' --width 16 --sampler center -o " + out_file("a.png"));
  ASSERT_EQ(alone.code, 0) << alone.err;
  EXPECT_EQ(alone.err.find("rounded"), std::string::npos) << alone.err;
  EXPECT_NE(alone.err.find("1 spp center"), std::string::npos) << alone.err;
  const CliResult given = run("render '" + mesh + "' --width 16 --sampler center --spp 4 -o " + out_file("b.png"));
  ASSERT_EQ(given.code, 0) << given.err;
  EXPECT_NE(given.err.find("--spp 4 rounded to 1 for the center sampler"), std::string::npos) << given.err;
}

TEST_F(Cli, AdaptiveReportsItsRaysAndWritesTheSampleCounts) {
  const CliResult r =
      run("render aa-edges --width 64 --height 48 --sampler adaptive --aov samples -o " + out_file("a.exr"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("primary rays per pixel"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out() / "a.samples.png"));
  EXPECT_FALSE(fs::exists(out() / "a.samples.exr"));  // the layer is inside a.exr
  const auto channels = read_exr_channels(out_file("a.exr"));
  bool found = false;
  float most = 0.f;
  for (const ImageLayer& layer : channels) {
    if (layer.name != "samples.Y") continue;
    found = true;
    for (float v : layer.values) {
      EXPECT_GE(v, 1.f);
      most = std::max(most, v);
    }
  }
  EXPECT_TRUE(found);
  EXPECT_GE(most, 16.f);  // the edges were refined
}

TEST_F(Cli, SampleCountsBesideAPngGoToTheirOwnExr) {
  const CliResult r =
      run("render aa-edges --width 32 --height 24 --sampler adaptive-corners --aov samples -o " + out_file("b.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"b.png", "b.samples.png", "b.samples.exr"}) EXPECT_TRUE(fs::exists(out() / f)) << f;
}

TEST_F(Cli, SamplingMisusesAreUsageErrors) {
  for (const std::string args : {"--sampler halton", "--sampler adaptive --filter mitchell", "--aa-depth 2",
                                 "--sampler jittered --aa-threshold 0.2", "--filter-radius 0.2",
                                 "--sampler adaptive --aa-depth 9", "--aov depth"}) {
    const CliResult r = run("render aa-edges --width 8 --height 8 " + args + " -o " + out_file("x.png"));
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(entries(out()).empty()) << args;
  }
}

}  // namespace
}  // namespace raylab::cli_test
