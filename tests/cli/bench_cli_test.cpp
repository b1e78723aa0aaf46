// `raylab bench` through the real binary: usage errors, a truncated .rays file, and .rays/.hits
// files that round-trip through another structure with the same answers.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_fixture.h"
#include "raylab/io/ray_file.h"

namespace raylab {
namespace {

using namespace cli_test;

const std::string kScene = "'spd:balls?size=1'";
const std::string kSmall = " --width 16 --height 8 --repeats 1 --threads 2 -q";

TEST_F(Cli, BenchUsageErrorsExitWithTwo) {
  const char* cases[] = {"bench",  // the scene is required
                         "bench 'spd:balls?size=1' --rays sideways",
                         "bench 'spd:balls?size=1' --threads -1",
                         "bench 'spd:balls?size=1' --repeats 0",
                         "bench 'spd:balls?size=1' --against optix",
                         "bench 'spd:balls?size=1' --accel kdtree",
                         "bench 'spd:balls?size=1' --embree-isa avx1024",
                         "bench 'spd:balls?size=1' --rays primary --rays-file x.rays",
                         "bench no-such-scene"};
  for (const char* args : cases) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
}

TEST_F(Cli, BenchTruncatedRaysFileIsAnInputErrorNamingIt) {
  const std::string rays = (work() / "cut.rays").string();
  write_text(rays, std::string(70, '\0'));  // two rays and 6 bytes
  const CliResult r =
      run("bench " + kScene + kSmall + " --rays-file '" + rays + "' --hits-out '" + out_file("h.hits") + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find(rays), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("70"), std::string::npos) << r.err;
  expect_out_empty();  // no half-written hits
}

TEST_F(Cli, BenchHitsOfAFileMatchBruteForce) {
  const std::string rays = out_file("p.rays"), hits = out_file("bvh.hits"), brute = out_file("brute.hits");
  const CliResult gen =
      run("bench " + kScene + kSmall + " --rays primary --rays-out '" + rays + "' --hits-out '" + hits + "'");
  ASSERT_EQ(gen.code, 0) << gen.err << gen.out;
  EXPECT_NE(gen.out.find("primary single Mrays/s"), std::string::npos) << gen.out;
  const std::vector<Ray> traced = read_rays(rays);
  EXPECT_EQ(traced.size(), 16u * 8u);
  const CliResult again = run("bench " + kScene + kSmall + " --accel brute --against none --rays-file '" + rays +
                              "' --hits-out '" + brute + "' --json -");
  ASSERT_EQ(again.code, 0) << again.err << again.out;
  const nlohmann::json j = nlohmann::json::parse(again.out);  // stdout is the JSON alone
  EXPECT_EQ(j["sets"][0]["name"], "file");
  EXPECT_EQ(j["sets"][0]["rays"], 128);
  const std::vector<HitRecord> a = read_hits(hits), b = read_hits(brute);
  ASSERT_EQ(a.size(), traced.size());
  ASSERT_EQ(b.size(), traced.size());
  std::size_t hit_count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].prim_id, b[i].prim_id) << i;
    if (a[i].miss()) {
      EXPECT_TRUE(std::isinf(a[i].t)) << i;
      continue;
    }
    ++hit_count;
    EXPECT_NEAR(a[i].t, b[i].t, 1e-4f * b[i].t) << i;
  }
  EXPECT_GT(hit_count, 0u);
}

}  // namespace
}  // namespace raylab
