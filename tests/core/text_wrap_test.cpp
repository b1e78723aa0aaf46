// Wrapping text to a width: no line longer than the width, no word lost or reordered, and the
// terminal-width rule without a terminal.

#include "raylab/core/text_wrap.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "raylab/core/terminal.h"

namespace raylab {
namespace {

// The words of `text` in order, whatever the spacing and line breaks.
std::vector<std::string> words_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& l : lines) all += l + "\n";
  return all;
}

TEST(WrapText, BreaksAtSpacesWithinTheWidth) {
  const std::string text = "Samples per pixel; a count the sampler cannot use is rounded with a notice.";
  for (std::size_t width : {10u, 20u, 33u, 80u}) {
    const std::vector<std::string> lines = wrap_text(text, width);
    for (const std::string& l : lines) EXPECT_LE(l.size(), width) << "'" << l << "'";
    EXPECT_EQ(words_of(joined(lines)), words_of(text)) << width;
  }
  EXPECT_EQ(wrap_text("one two three", 7), (std::vector<std::string>{"one two", "three"}));
  EXPECT_EQ(wrap_text("short", 80), (std::vector<std::string>{"short"}));
}

TEST(WrapText, SplitsALongWordAfterACommaElseAnywhere) {
  EXPECT_EQ(wrap_text("TEXT:{box,tent,gaussian,mitchell}", 16),
            (std::vector<std::string>{"TEXT:{box,tent,", "gaussian,", "mitchell}"}));
  EXPECT_EQ(wrap_text("abcdefghij", 4), (std::vector<std::string>{"abcd", "efgh", "ij"}));
  // A word split anyway starts on the line before, so that an option keeps its choices beside it.
  EXPECT_EQ(wrap_text("--filter TEXT:{box,tent,gaussian,mitchell}", 24),
            (std::vector<std::string>{"--filter TEXT:{box,tent,", "gaussian,mitchell}"}));
}

TEST(WrapText, KeepsSpacesInsideALineAndDropsThemAtABreak) {
  EXPECT_EQ(wrap_text("  demo     the demo scene", 80), (std::vector<std::string>{"  demo     the demo scene"}));
  EXPECT_EQ(wrap_text("  ab  cd  ef", 6), (std::vector<std::string>{"  ab", "cd  ef"}));
  EXPECT_EQ(wrap_text("ab   ", 80), (std::vector<std::string>{"ab"}));
}

TEST(WrapText, KeepsLineBreaksAndDropsTheFinalOne) {
  EXPECT_EQ(wrap_text("a b\nc\n", 80), (std::vector<std::string>{"a b", "c"}));
  EXPECT_EQ(wrap_text("a\n\nb", 80), (std::vector<std::string>{"a", "", "b"}));
  EXPECT_TRUE(wrap_text("", 80).empty());
}

TEST(WrapHanging, IndentsTheLinesAfterTheFirst) {
  EXPECT_EQ(wrap_hanging("one two three four", 14, 4), "one two\n    three four\n");
  const std::string text = "Render frames A to B of the scene's camera path (A:B, or one frame A)";
  const std::string out = wrap_hanging(text, 30, 10);
  std::istringstream lines(out);
  bool first = true;
  for (std::string l; std::getline(lines, l); first = false) {
    EXPECT_LE(l.size() + (first ? 10 : 0), 30u) << l;  // the first line follows a 10-column name
    if (!first) {
      EXPECT_EQ(l.substr(0, 10), std::string(10, ' '));
    }
  }
}

TEST(TerminalColumns, FromTheEnvironmentWhenNotATerminal) {
  EXPECT_EQ(columns_from_environment(nullptr), 80);
  EXPECT_EQ(columns_from_environment("50"), 50);
  EXPECT_EQ(columns_from_environment("200"), 200);
  EXPECT_EQ(columns_from_environment("5"), 20);  // too narrow to be useful
  EXPECT_EQ(columns_from_environment("wide"), 80);
  EXPECT_EQ(columns_from_environment("50x"), 80);
  EXPECT_EQ(columns_from_environment("-3"), 80);
  EXPECT_EQ(columns_from_environment(""), 80);
}

}  // namespace
}  // namespace raylab
