// `raylab quality` through the real binary: exit codes, messages, the table, the reference
// cache and the files it writes.

#include <gtest/gtest.h>

#include <algorithm>

#include "cli_fixture.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

using namespace cli_test;

// A study small enough for the ASan suite: 24 x 16 pixels, two seeds; kTiny adds two budgets.
const std::string kBase = "quality demo --width 24 --height 16 --seeds 2 --reference-spp 16 --threads 2";
const std::string kTiny = kBase + " --budgets 1,4";

TEST_F(Cli, QualityRejectsBadListsNamingTheValue) {
  const CliResult budgets = run(kBase + " --budgets 1,x,16 --cache-dir '" + out_file("c") + "'");
  EXPECT_EQ(budgets.code, 2);
  EXPECT_NE(budgets.err.find("'x'"), std::string::npos) << budgets.err;
  EXPECT_NE(budgets.err.find("--budgets"), std::string::npos) << budgets.err;
  const CliResult samplers = run(kTiny + " --samplers jittered,stratified --cache-dir '" + out_file("c") + "'");
  EXPECT_EQ(samplers.code, 2);
  EXPECT_NE(samplers.err.find("'stratified'"), std::string::npos) << samplers.err;
  for (const char* name : {"center", "cmj", "sobol", "adaptive-corners"}) {
    EXPECT_NE(samplers.err.find(name), std::string::npos) << samplers.err;
  }
  EXPECT_EQ(run(kTiny + " --seeds 0").code, 2);
  EXPECT_EQ(run(kTiny + " --plot '" + out_file("chart.png") + "'").code, 2);  // the plot is SVG
  EXPECT_EQ(run("quality").code, 2);                                          // the scene is required
  expect_out_empty();
}

TEST_F(Cli, QualityReportsAMissingReferenceWithItsPath) {
  const std::string missing = (work() / "nope.exr").string();
  const CliResult r = run(kTiny + " --reference '" + missing + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  EXPECT_EQ(run(kTiny + " --reference '" + (work() / "ref.png").string() + "'").code, 2);  // 8 bits: not a reference
}

TEST_F(Cli, QualityRejectsAReferenceOfAnotherSize) {
  const std::string ref = (work() / "ref.exr").string();
  write_image(Film(8, 8), ref);
  const CliResult r = run(kTiny + " --reference '" + ref + "' --csv '" + out_file("t.csv") + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("8x8"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("24x16"), std::string::npos) << r.err;
  expect_out_empty();
}

TEST_F(Cli, QualityRunsTheStudyAndWritesItsFiles) {
  const std::string cache = out_file("cache");
  const std::string files = " --cache-dir '" + cache + "' --plot '" + out_file("q.svg") + "' --csv '" +
                            out_file("q.csv") + "' --json '" + out_file("q.json") + "'";
  const CliResult r = run(kTiny + " --samplers center,jittered,random" + files);
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("scene demo: 24x16"), std::string::npos) << r.out;
  for (const char* row : {"\ncenter ", "\njittered ", "\nrandom "})
    EXPECT_NE(r.out.find(row), std::string::npos) << row;
  EXPECT_NE(r.err.find("reference: auto"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rendered and cached"), std::string::npos) << r.err;
  const std::string csv = read_text(out_file("q.csv"));
  EXPECT_TRUE(csv.starts_with("sampler,budget,spp,")) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 6);  // header, center, jittered x2, random x2
  EXPECT_NE(csv.find("\njittered,4,4,2,4,"), std::string::npos) << csv;
  const std::string svg = read_text(out_file("q.svg"));
  EXPECT_TRUE(svg.starts_with("<?xml")) << svg.substr(0, 80);
  EXPECT_NE(svg.find("<polyline class=\"line\""), std::string::npos);
  EXPECT_NE(read_text(out_file("q.json")).find("\"sampler\": \"random\""), std::string::npos);
  ASSERT_EQ(entries(cache).size(), 1u);  // the reference, and no temporary

  // The second run finds the reference in the cache; -q keeps stderr quiet.
  const CliResult again = run(kTiny + " --samplers jittered -q --cache-dir '" + cache + "'");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_TRUE(again.err.empty()) << again.err;
  EXPECT_EQ(entries(cache).size(), 1u);
  const CliResult verbose = run(kTiny + " --samplers jittered --cache-dir '" + cache + "'");
  EXPECT_NE(verbose.err.find("cached at"), std::string::npos) << verbose.err;
  EXPECT_EQ(verbose.err.find("rendered"), std::string::npos) << verbose.err;
}

TEST_F(Cli, QualityPrintsTheBarRatiosWhenAdaptiveAndJitteredRanAt16) {
  const CliResult r =
      run("quality demo --width 16 --height 12 --budgets 16 --seeds 1 --reference-spp 16 --threads 2 -q"
          " --samplers jittered,adaptive --cache-dir '" +
          out_file("cache") + "'");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find(") vs jittered at 16 spp: primary rays x"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("time at equal RMSE x"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace raylab
