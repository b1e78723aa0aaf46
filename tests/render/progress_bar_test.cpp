// The progress bar's line and ETA (issue 21, item 6): the ETA arithmetic, a line that fits 50
// and 120 columns (never wrapping), the terminal width from $COLUMNS when the stream is no
// terminal, and the scattered tile order that makes the share of tiles done a fair ETA.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <set>

#include "raylab/core/terminal.h"
#include "raylab/render/progress.h"
#include "raylab/render/render_progress.h"

namespace raylab {
namespace {

TEST(ProgressBar, EtaIsTheTimeLeftAtTheRateSoFar) {
  EXPECT_DOUBLE_EQ(ProgressBar::eta_seconds(25, 100, 10.0), 30.0);
  EXPECT_DOUBLE_EQ(ProgressBar::eta_seconds(50, 100, 4.0), 4.0);
  EXPECT_DOUBLE_EQ(ProgressBar::eta_seconds(100, 100, 7.0), 0.0);
  EXPECT_TRUE(std::isnan(ProgressBar::eta_seconds(0, 100, 5.0)));  // nothing to go by yet
  EXPECT_EQ(ProgressBar::format_duration(ProgressBar::eta_seconds(0, 100, 5.0)), "?");
}

TEST(ProgressBar, TheLineFitsFiftyColumnsWithPercentAndEta) {
  const std::string line = ProgressBar::format_line("render", 30, 100, 3.0, 50);
  EXPECT_LE(line.size(), 49u) << line;
  EXPECT_NE(line.find(" 30%"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 7.0s"), std::string::npos) << line;
  EXPECT_NE(line.find('['), std::string::npos) << "a bar still fits: " << line;
}

TEST(ProgressBar, TheLineAtOneHundredTwentyColumnsHasEverything) {
  const std::string line = ProgressBar::format_line("render", 30, 100, 3.0, 120);
  EXPECT_EQ(line, "render [#########---------------------]  30%  elapsed 3.0s  ETA 7.0s");
  EXPECT_LE(line.size(), 119u);
}

TEST(ProgressBar, EveryWidthFromTenColumnsUpNeverWraps) {
  for (int columns = 10; columns <= 200; ++columns) {
    for (double elapsed : {0.5, 75.0, 4000.0}) {
      const std::string line = ProgressBar::format_line("frames", 7, 9, elapsed, columns);
      EXPECT_LE(static_cast<int>(line.size()), columns - 1) << columns << ": " << line;
      if (columns >= 30) {
        EXPECT_NE(line.find("ETA"), std::string::npos) << columns << ": " << line;
      }
    }
  }
}

TEST(ProgressBar, TerminalWidthFromColumnsWhenTheStreamIsNoTerminal) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  const char* saved = std::getenv("COLUMNS");
  const std::string keep = saved ? saved : "";
  ::setenv("COLUMNS", "77", 1);
  EXPECT_EQ(raylab::terminal_columns(::fileno(file)), 77);
  ::unsetenv("COLUMNS");
  EXPECT_EQ(raylab::terminal_columns(::fileno(file)), 80);
  if (saved) ::setenv("COLUMNS", keep.c_str(), 1);
  std::fclose(file);
}

TEST(ScatteredTileOrder, IsAFixedPermutationSpreadOverTheImage) {
  // A 20 x 10 grid of tiles, row-major.
  std::vector<int> tiles(200);
  std::iota(tiles.begin(), tiles.end(), 0);
  const std::vector<int> order = scattered_tile_order(tiles);
  EXPECT_EQ(order, scattered_tile_order(tiles)) << "the same on every run";
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, tiles) << "every tile once";
  // The first fifth reaches most rows and columns (row by row it would be the top two rows).
  std::set<int> rows, columns;
  for (std::size_t i = 0; i < 40; ++i) {
    rows.insert(order[i] / 20);
    columns.insert(order[i] % 20);
  }
  EXPECT_GE(rows.size(), 8u);
  EXPECT_GE(columns.size(), 14u);
  // A subset (the tiles a resumed render has left) keeps its own order.
  const std::vector<int> some{3, 50, 120, 199};
  std::vector<int> expected;
  for (int t : order) {
    if (std::find(some.begin(), some.end(), t) != some.end()) expected.push_back(t);
  }
  EXPECT_EQ(scattered_tile_order(some), expected);
}

}  // namespace
}  // namespace raylab
