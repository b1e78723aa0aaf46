// One line per successful render (issue 21, item 8): on stderr, naming the file written, in every
// mode; stdout stays for what scripts read (--stats, --json -); --quiet prints nothing.

#include <algorithm>

#include "cli_fixture.h"

namespace raylab::cli_test {
namespace {

// The lines of `text` that start with `prefix`.
std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> found;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at, end - at);
    if (line.starts_with(prefix)) found.push_back(line);
    at = end + 1;
  }
  return found;
}

std::size_t line_count(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST_F(Cli, APlainRenderPrintsOneLineOnStderrAndNothingOnStdout) {
  const std::string image = out_file("one.png");
  const CliResult r = run("render demo --width 32 --height 24 -o " + image);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(line_count(r.err), 1u) << r.err;
  const std::vector<std::string> wrote = lines_starting(r.err, "wrote " + image + " (32x24, 4 spp jittered, ");
  ASSERT_EQ(wrote.size(), 1u) << r.err;
  EXPECT_NE(wrote[0].find("Mrays/s, --accel bvh) in "), std::string::npos) << wrote[0];
}

TEST_F(Cli, QuietPrintsNothingAndStatsKeepsItsTableOnStdout) {
  const CliResult quiet = run("render demo --width 32 --height 24 -q -o " + out_file("q.png"));
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.out + quiet.err, "");
  const CliResult stats = run("render demo --width 32 --height 24 --stats -o " + out_file("s.png"));
  ASSERT_EQ(stats.code, 0) << stats.err;
  EXPECT_NE(stats.out.find("throughput"), std::string::npos) << stats.out;
  EXPECT_EQ(stats.out.find("wrote"), std::string::npos) << stats.out;
  EXPECT_EQ(lines_starting(stats.err, "wrote ").size(), 1u) << stats.err;
}

TEST_F(Cli, PassesAndTheSpdProtocolEndWithTheSameOneLine) {
  const CliResult passes = run("render demo --width 32 --height 24 --spp 4 --passes 2 -o " + out_file("p.png"));
  ASSERT_EQ(passes.code, 0) << passes.err;
  EXPECT_EQ(passes.out, "");
  EXPECT_EQ(lines_starting(passes.err, "pass 1/2: wrote ").size(), 1u) << passes.err;
  EXPECT_EQ(lines_starting(passes.err, "wrote " + out_file("p.png") + " (").size(), 1u) << passes.err;
  EXPECT_EQ(line_count(passes.err), 2u) << passes.err;
  // --json -: stdout is the JSON document alone; the table and the one line go to stderr.
  const CliResult spd = run("render spd:balls?size=1 --spd-protocol --threads 2 --json - -o " + out_file("spd.png"));
  ASSERT_EQ(spd.code, 0) << spd.err;
  EXPECT_TRUE(spd.out.starts_with("{")) << spd.out;
  EXPECT_EQ(spd.out.find("wrote"), std::string::npos) << spd.out;
  EXPECT_EQ(lines_starting(spd.err, "wrote " + out_file("spd.png") + " (512x512, SPD protocol, ").size(), 1u)
      << spd.err;
}

TEST_F(Cli, FramesEndWithOneLine) {
  const std::string scene = raylab::test::source_dir() + "/scenes/orbit.json";
  const CliResult r =
      run("render " + scene + " --frames 0:1 --width 16 --height 12 --spp 1 -o " + out_file("f.####.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(lines_starting(r.err, "wrote frames 0-1 as " + out_file("f.0000.png") + " (2 frames, 16x12, ").size(), 1u)
      << r.err;
  // Besides it only the per-frame lines a log shows (stderr is not a terminal here).
  EXPECT_EQ(lines_starting(r.err, "frame ").size(), 2u) << r.err;
  EXPECT_EQ(line_count(r.err), 3u) << r.err;
}

}  // namespace
}  // namespace raylab::cli_test
