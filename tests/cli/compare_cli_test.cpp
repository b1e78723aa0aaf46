// `raylab compare` through the real binary: the table, exit codes, and the files it writes.

#include <gtest/gtest.h>

#include "../test_paths.h"
#include "cli_fixture.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

using namespace cli_test;

const std::string kWhitted = "'" + raylab::test::source_dir() + "/scenes/whitted.json'";

// The table row of `name`: the line that starts with it.
std::string row(const std::string& out, const std::string& name) {
  const std::size_t at = out.find("\n" + name + " ");
  if (at == std::string::npos) return "";
  return out.substr(at + 1, out.find('\n', at + 1) - at - 1);
}

TEST_F(Cli, ComparePrintsARowPerStructure) {
  const CliResult r = run("compare " + kWhitted + " --accels brute,bvh,bvh2 --width 64 --height 48 --repeat 1");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("64x48 pixel centres: 3072 primary"), std::string::npos) << r.out;
  for (const char* name : {"brute", "bvh", "bvh2"}) {
    const std::string line = row(r.out, name);
    ASSERT_FALSE(line.empty()) << name << "\n" << r.out;
    EXPECT_EQ(line.find("skipped"), std::string::npos) << line;
    EXPECT_TRUE(line.ends_with(std::string(name) == "brute" ? "reference" : "ok")) << line;
  }
  EXPECT_NE(r.out.find("Mrays/s"), std::string::npos);
  EXPECT_NE(r.err.find("compare: bvh2: building"), std::string::npos) << r.err;  // progress on stderr
}

TEST_F(Cli, CompareRejectsUnknownStructuresListingTheValidOnes) {
  const CliResult r = run("compare " + kWhitted + " --accels bvh,kdtree --width 8 --height 8");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("kdtree"), std::string::npos) << r.err;
  for (const char* name : {"bvh2", "brute", "grid", "grid2", "octree", "irregular"})
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
  const CliResult twice = run("compare " + kWhitted + " --accels bvh,bvh --width 8 --height 8");
  EXPECT_EQ(twice.code, 2);
  EXPECT_NE(twice.err.find("listed twice"), std::string::npos) << twice.err;
  EXPECT_EQ(run("compare").code, 2);  // the scene is required
}

TEST_F(Cli, CompareReportsBadScenesAsInputErrors) {
  const std::string missing = (work() / "nope.json").string();
  const CliResult r = run("compare '" + missing + "' --accels bvh");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(missing + ":"), std::string::npos) << r.err;
  write_text(work() / "bad.json", "{\"version\": 1,\n  \"objects\": [}\n");
  const CliResult bad = run("compare '" + (work() / "bad.json").string() + "' --accels bvh");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("bad.json:2:"), std::string::npos) << bad.err;
}

TEST_F(Cli, CompareWritesHeatmapsPlotCsvAndJson) {
  const std::string maps = out_file("maps/sub");  // created, parents included
  const CliResult r =
      run("compare 'spd:balls?size=2' --accels bvh,brute --width 40 --height 30 --repeat 1 -q"
          " --heatmaps '" +
          maps + "' --plot '" + out_file("chart.svg") + "' --csv '" + out_file("t.csv") + "' --json '" +
          out_file("t.json") + "'");
  ASSERT_EQ(r.code, 0) << r.err << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;  // -q
  for (const char* name : {"bvh-tests", "bvh-nodes", "brute-tests", "brute-nodes"}) {
    const Film f = read_image(maps + "/" + name + ".png");
    EXPECT_EQ(f.width(), 40) << name;  // the size of the rays' image, to lay over it
    EXPECT_EQ(f.height(), 30) << name;
    EXPECT_TRUE(fs::exists(maps + "/" + name + ".legend.png")) << name;
  }
  const std::string svg = read_text(out_file("chart.svg"));
  EXPECT_TRUE(svg.starts_with("<?xml")) << svg.substr(0, 100);
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
  EXPECT_NE(read_text(out_file("t.csv")).find("\nbrute,0,"), std::string::npos);
  EXPECT_NE(read_text(out_file("t.json")).find("\"agreed\": true"), std::string::npos);
  // Nothing but the outputs: no temporary files left behind.
  std::vector<std::string> names = entries(out());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"chart.svg", "maps", "t.csv", "t.json"}));
}

TEST_F(Cli, CompareFailsBeforeWorkOnAnUnwritableOutputAndLeavesNothing) {
  const CliResult r =
      run("compare " + kWhitted + " --accels bvh --width 8 --height 8 --plot '" + out_file("missing/chart.svg") + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");  // refused before measuring anything
  expect_out_empty();
  const CliResult ext = run("compare " + kWhitted + " --accels bvh --plot '" + out_file("chart.png") + "'");
  EXPECT_EQ(ext.code, 2);
  expect_out_empty();
  // A heat map folder that cannot be made: the table is printed, the error is an input error,
  // and no image is left half-written.
  write_text(out() / "taken", "a file");
  const CliResult maps =
      run("compare " + kWhitted + " --accels bvh --width 8 --height 8 -q --heatmaps '" + out_file("taken") + "'");
  EXPECT_EQ(maps.code, 1);
  EXPECT_EQ(entries(out()), std::vector<std::string>{"taken"});
}

}  // namespace
}  // namespace raylab
