// Errors that point at the fix, through the real binary: a misspelled command or option gets the
// nearest valid one, every parse error names the help of the command it is in, and `raylab help`
// prints what --help prints.

#include <gtest/gtest.h>

#include <string>

#include "cli_fixture.h"

namespace raylab {
namespace {

using namespace cli_test;

// The first line of `text`.
std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST_F(Cli, MisspelledCommandGetsTheNearestOne) {
  const CliResult r = run("rendr");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "raylab: unknown command 'rendr'; did you mean 'render'?\nRun 'raylab --help' for usage.\n");
  EXPECT_EQ(first_line(run("comapre demo").err), "raylab: unknown command 'comapre'; did you mean 'compare'?");
  EXPECT_EQ(first_line(run("qualty").err), "raylab: unknown command 'qualty'; did you mean 'quality'?");
}

// Options that parse but do not go together are found by the command itself, after parsing;
// their message names that command's help too.
TEST_F(Cli, UsageErrorsFoundAfterParsingNameTheCommandsHelp) {
  const CliResult render = run("render demo --spd-facing viewer -o '" + out_file("x.png") + "'");
  EXPECT_EQ(render.code, 2);
  EXPECT_EQ(render.err, "raylab: --spd-facing applies to --spd-protocol only\nRun 'raylab render --help' for usage.\n");
  expect_out_empty();
  const CliResult compare = run("compare demo --plot '" + out_file("chart.png") + "'");
  EXPECT_EQ(compare.code, 2);
  EXPECT_NE(compare.err.find("\nRun 'raylab compare --help' for usage.\n"), std::string::npos) << compare.err;
}

TEST_F(Cli, FarFromEveryCommandGetsNoGuess) {
  const CliResult r = run("paint demo");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(first_line(r.err), "raylab: unknown command 'paint'");
}

TEST_F(Cli, MisspelledOptionGetsTheNearestOfItsCommand) {
  const CliResult r = run("render --sppp 4 -o '" + out_file("x.png") + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "raylab: unknown option '--sppp'; did you mean '--spp'?\nRun 'raylab render --help' for usage.\n");
  expect_out_empty();
  // The candidates are the command's own: --heatmaps is compare's, --max-rmse diff's.
  EXPECT_EQ(first_line(run("compare demo --heatmap d").err),
            "raylab: unknown option '--heatmap'; did you mean '--heatmaps'?");
  EXPECT_EQ(first_line(run("diff a.png b.png --max-rsme 1").err),
            "raylab: unknown option '--max-rsme'; did you mean '--max-rmse'?");
  // An option given with '=' is looked up without its value.
  EXPECT_EQ(first_line(run("render --sampelr=cmj").err),
            "raylab: unknown option '--sampelr'; did you mean '--sampler'?");
}

TEST_F(Cli, OptionFarFromEveryOptionGetsNoGuess) {
  const CliResult r = run("render --colour red");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(first_line(r.err), "raylab: unknown option '--colour'");
}

TEST_F(Cli, EveryParseErrorInACommandNamesItsHelp) {
  // A value out of range, a missing value, a missing argument, an unknown choice.
  for (const std::string args : {"render --spp 0", "render --spp", "diff onlyone.png", "render --sampler best",
                                 "compare", "bench demo --rays some", "info", "convert demo"}) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    const std::string command = args.substr(0, args.find(' '));
    EXPECT_NE(r.err.find("Run 'raylab " + command + " --help' for usage."), std::string::npos) << args << ": " << r.err;
  }
  // With no command at all, the top-level help.
  const CliResult none = run("");
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("Run 'raylab --help' for usage."), std::string::npos) << none.err;
}

TEST_F(Cli, HelpCommandPrintsWhatHelpFlagPrints) {
  const CliResult top = run("help", "COLUMNS=80");
  EXPECT_EQ(top.code, 0) << top.err;
  EXPECT_EQ(top.out, run("--help", "COLUMNS=80").out);
  EXPECT_NE(top.out.find("help"), std::string::npos);  // listed among the commands
  for (const std::string command : {"render", "diff", "info", "convert", "compare", "quality", "bench"}) {
    const CliResult r = run("help " + command, "COLUMNS=80");
    EXPECT_EQ(r.code, 0) << command << ": " << r.err;
    EXPECT_FALSE(r.out.empty()) << command;
    EXPECT_EQ(r.out, run(command + " --help", "COLUMNS=80").out) << command;
    EXPECT_NE(r.out.find("Usage: raylab " + command), std::string::npos) << r.out;
  }
  const CliResult wrong = run("help rendr");
  EXPECT_EQ(wrong.code, 2);
  EXPECT_EQ(first_line(wrong.err), "raylab: unknown command 'rendr'; did you mean 'render'?");
}

}  // namespace
}  // namespace raylab
