// One side of the image given, the other follows the scene's shape; both given in another shape,
// the view widens and the scene's framing stays whole, in render, compare and quality alike.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "../test_paths.h"
#include "cli_fixture.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

using namespace cli_test;

const std::string kWhitted = "'" + raylab::test::source_dir() + "/scenes/whitted.json'";  // 640 x 400

// A cube two units wide: its fitted camera frames it edge to edge vertically.
const char kCube[] =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 1 5 8 4\nf 2 3 7 6\n";

// Mean absolute difference per channel between `a` and the `a`-sized window of `b` at (x0, y0).
double window_difference(const Film& a, const Film& b, int x0, int y0) {
  double sum = 0.0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const Color d = a.at(x, y) - b.at(x0 + x, y0 + y);
      sum += std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    }
  }
  return sum / (3.0 * a.width() * a.height());
}

TEST_F(Cli, WidthOrHeightAloneKeepsTheScenesShape) {
  struct Case {
    std::string flags;
    int width, height;
  };
  for (const Case& c : {Case{"--width 320", 320, 200}, Case{"--height 50", 80, 50}, Case{"--width 33", 33, 21}}) {
    SCOPED_TRACE(c.flags);
    const CliResult r = run("render " + kWhitted + " " + c.flags + " --spp 1 -q -o '" + out_file("w.pfm") + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    const Film film = read_image(out_file("w.pfm"));
    EXPECT_EQ(film.width(), c.width);
    EXPECT_EQ(film.height(), c.height);
  }
  // A mesh: the fitted camera's 640 x 480.
  const std::string cube = obj("cube.obj", kCube);
  ASSERT_EQ(run("render '" + cube + "' --height 30 -q -o '" + out_file("c.pfm") + "'").code, 0);
  const Film film = read_image(out_file("c.pfm"));
  EXPECT_EQ(film.width(), 40);
  EXPECT_EQ(film.height(), 30);
}

// Taller than the scene: the scene's own image appears whole, at the same scale, in the middle
// rows (a crop would show a narrower strip of the scene, scaled up).
TEST_F(Cli, ATallerImageShowsTheWholeSceneFrame) {
  const std::string flags = " --spp 1 --sampler center -q -o '";
  ASSERT_EQ(run("render " + kWhitted + " --width 64 --height 40" + flags + out_file("own.pfm") + "'").code, 0);
  ASSERT_EQ(run("render " + kWhitted + " --width 64 --height 80" + flags + out_file("tall.pfm") + "'").code, 0);
  const Film own = read_image(out_file("own.pfm")), tall = read_image(out_file("tall.pfm"));
  ASSERT_EQ(tall.height(), 80);
  EXPECT_LT(window_difference(own, tall, 0, 20), 0.01);
  // The bands above and below show more of the scene, not a copy of the frame.
  EXPECT_GT(window_difference(own, tall, 0, 0), 0.02);
}

// Wider than the scene: the scene's frame in the middle columns, the view widened sideways.
TEST_F(Cli, AWiderImageShowsTheWholeSceneFrame) {
  const std::string flags = " --spp 1 --sampler center -q -o '";
  ASSERT_EQ(run("render " + kWhitted + " --width 64 --height 40" + flags + out_file("own.pfm") + "'").code, 0);
  ASSERT_EQ(run("render " + kWhitted + " --width 128 --height 40" + flags + out_file("wide.pfm") + "'").code, 0);
  const Film own = read_image(out_file("own.pfm")), wide = read_image(out_file("wide.pfm"));
  EXPECT_LT(window_difference(own, wide, 32, 0), 0.01);
}

// A mesh filling its fitted frame stays inside a much narrower image: its border columns and
// rows show only the background.
TEST_F(Cli, ANarrowImageDoesNotCropTheFittedMesh) {
  const std::string cube = obj("cube.obj", kCube);
  for (const std::string size : {"--width 20 --height 60", "--width 90 --height 20"}) {
    SCOPED_TRACE(size);
    ASSERT_EQ(run("render '" + cube + "' " + size + " -q -o '" + out_file("c.pfm") + "'").code, 0);
    const Film film = read_image(out_file("c.pfm"));
    const Color background = film.at(0, 0);
    int covered_on_border = 0;
    for (int y = 0; y < film.height(); ++y) {
      for (int x = 0; x < film.width(); ++x) {
        const bool border = x == 0 || y == 0 || x == film.width() - 1 || y == film.height() - 1;
        covered_on_border += border && !(film.at(x, y) == background);
      }
    }
    EXPECT_EQ(covered_on_border, 0);
  }
}

// An animation's frames follow the rule too: every key of the camera path is framed alike.
TEST_F(Cli, FramesFollowTheSameRule) {
  const std::string orbit = "'" + raylab::test::source_dir() + "/scenes/orbit.json'";  // 320 x 240
  const std::string flags = " --frames 5 --spp 1 --sampler center -q -o '";
  ASSERT_EQ(run("render " + orbit + " --width 32" + flags + out_file("own.#.pfm") + "'").code, 0);
  ASSERT_EQ(run("render " + orbit + " --width 32 --height 48" + flags + out_file("tall.#.pfm") + "'").code, 0);
  const Film own = read_image(out_file("own.5.pfm")), tall = read_image(out_file("tall.5.pfm"));
  ASSERT_EQ(own.height(), 24);
  EXPECT_LT(window_difference(own, tall, 0, 12), 0.01);
}

// compare and quality follow the same rule as render.
TEST_F(Cli, CompareAndQualityFollowTheSameRule) {
  const CliResult c =
      run("compare " + kWhitted + " --accels bvh --height 20 --repeat 1 -q --json '" + out_file("c.json") + "'");
  ASSERT_EQ(c.code, 0) << c.err;
  const auto compare = nlohmann::json::parse(read_text(out_file("c.json")));
  const CliResult q = run("quality " + kWhitted +
                          " --width 16 --budgets 1 --seeds 1 --samplers center --reference-spp 4 --threads 2 -q "
                          "--cache-dir '" +
                          (work() / "cache").string() + "' --json '" + out_file("q.json") + "'");
  ASSERT_EQ(q.code, 0) << q.err;
  const auto quality = nlohmann::json::parse(read_text(out_file("q.json")));
  EXPECT_EQ(compare["width"], 32);  // 640 x 400 at 20 rows
  EXPECT_EQ(compare["height"], 20);
  EXPECT_EQ(quality["width"], 16);
  EXPECT_EQ(quality["height"], 10);
}

}  // namespace
}  // namespace raylab
