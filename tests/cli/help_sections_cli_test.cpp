// Help that a new user can read, through the real binary: each command's options in named
// sections, every line within the terminal's width (COLUMNS when stdout is not a terminal), and
// --list-scenes saying what each built-in scene is.

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {
namespace {

using namespace cli_test;

// The section headings each command's help must show, in this order.
const std::map<std::string, std::vector<std::string>>& expected_sections() {
  static const std::map<std::string, std::vector<std::string>> sections = {
      {"render",
       {"Scene and output", "Sampling", "Structure and tracing", "Long renders", "Distributed (MPI)", "Reporting",
        "SPD testing procedure"}},
      {"diff", {"Threshold", "Difference image"}},
      {"info", {"Scene"}},
      {"convert", {"Tessellation", "Reporting"}},
      {"compare", {"Measurement", "Structure parameters", "Output", "Reporting"}},
      {"quality", {"Study", "Image and filter", "Reference", "Performance", "Output", "Reporting"}},
      {"bench", {"Measurement", "Ray and hit files", "Reporting"}},
  };
  return sections;
}

// The lines of `text` longer than `width`, for the failure message.
std::string lines_longer_than(const std::string& text, std::size_t width) {
  std::istringstream in(text);
  std::string longer;
  for (std::string line; std::getline(in, line);) {
    if (line.size() > width) longer += "[" + std::to_string(line.size()) + "] " + line + "\n";
  }
  return longer;
}

std::size_t longest_line(const std::string& text) {
  std::istringstream in(text);
  std::size_t most = 0;
  for (std::string line; std::getline(in, line);) most = std::max(most, line.size());
  return most;
}

TEST_F(Cli, HelpOfEachCommandHasItsSectionsInOrder) {
  for (const auto& [command, sections] : expected_sections()) {
    const CliResult r = run(command + " --help");
    ASSERT_EQ(r.code, 0) << command << ": " << r.err;
    std::size_t at = 0;
    for (const std::string& section : sections) {
      const std::size_t found = r.out.find("\n" + section + ":\n", at);
      EXPECT_NE(found, std::string::npos) << command << " lacks (or misplaces) section " << section << "\n" << r.out;
      if (found != std::string::npos) at = found;
    }
    EXPECT_EQ(r.out.find("\n\n\n"), std::string::npos) << command << ": two blank lines\n" << r.out;
  }
}

TEST_F(Cli, HelpFitsFiftyColumns) {
  std::vector<std::string> commands = {""};
  for (const auto& entry : expected_sections()) commands.push_back(entry.first);
  for (const std::string& command : commands) {
    const CliResult r = run(command + " --help", "COLUMNS=50");
    ASSERT_EQ(r.code, 0) << command << ": " << r.err;
    EXPECT_EQ(lines_longer_than(r.out, 50), "") << "raylab " << command << " --help";
  }
}

TEST_F(Cli, HelpUsesTheWidthItIsGiven) {
  // Wider than 80 when allowed, so the width is the one given, not a fixed 80.
  const CliResult wide = run("render --help", "COLUMNS=140");
  EXPECT_LE(longest_line(wide.out), 140u) << lines_longer_than(wide.out, 140);
  EXPECT_GT(longest_line(wide.out), 100u);
  const CliResult plain = run("render --help", "COLUMNS=");  // unset or empty: 80
  EXPECT_LE(longest_line(plain.out), 80u) << lines_longer_than(plain.out, 80);
  EXPECT_GT(longest_line(plain.out), 70u);
  // Every option is still there, however narrow.
  const CliResult narrow = run("render --help", "COLUMNS=50");
  for (const std::string option : {"--spp", "--sampler", "--accel", "--checkpoint", "--rank-timeout", "--json"}) {
    EXPECT_NE(narrow.out.find("  " + option), std::string::npos) << option;
  }
}

TEST_F(Cli, ListScenesDescribesEveryBuiltIn) {
  const CliResult r = run("render --list-scenes", "COLUMNS=300");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(builtin_scenes().size(), builtin_scene_names().size());
  for (const BuiltinScene& b : builtin_scenes()) {
    EXPECT_GE(b.description.size(), 20u) << b.name;
    const std::string line = "  " + std::string(b.name);
    const std::size_t at = r.out.find(line + " ");
    ASSERT_NE(at, std::string::npos) << b.name << "\n" << r.out;
    const std::string rest = r.out.substr(at, r.out.find('\n', at) - at);
    EXPECT_NE(rest.find(std::string(b.description)), std::string::npos) << rest;
  }
  const CliResult narrow = run("render --list-scenes", "COLUMNS=50");
  EXPECT_EQ(lines_longer_than(narrow.out, 50), "");
}

}  // namespace
}  // namespace raylab
