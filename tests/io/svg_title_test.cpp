// SVG titles that fit their canvas: the width estimate's properties, the shrink-then-wrap rule,
// and the titles of both chart kinds measured as they are written.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "raylab/io/line_chart.h"
#include "raylab/io/svg_chart.h"
#include "raylab/io/svg_text.h"

namespace raylab {
namespace {

// A scene path as long as people's are: the title that overflowed the compare chart.
const std::string kLongTitle =
    "raylab compare: /home/someone/projects/rendering/benchmarks/scenes/stanford/lucy-with-ground-plane-and-"
    "three-area-lights.json (28055742 primitives, 1920x1080)";

// The words of `text`, whatever the line breaks.
std::vector<std::string> words_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// What an SVG page says of its title: the page width, the title's x, font size and lines.
struct WrittenTitle {
  double page_width = 0, page_height = 0, x = 0, font_size = 0;
  std::vector<std::string> lines;
};

// The tag that starts with `start` ("<svg "), through its '>'; empty when there is none.
std::string tag_of(const std::string& svg, const std::string& start) {
  const std::size_t at = svg.find(start);
  if (at == std::string::npos) return "";
  return svg.substr(at, svg.find('>', at) - at + 1);
}

// The number in attribute `name` of `tag` (NaN when it is missing). No std::regex: GCC 12's
// <regex> trips -Wmaybe-uninitialized under the sanitizers.
double number_attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t at = tag.find(key);
  EXPECT_NE(at, std::string::npos) << name << " in " << tag;
  return at == std::string::npos ? std::nan("") : std::stod(tag.substr(at + key.size()));
}

WrittenTitle written_title(const std::string& svg) {
  WrittenTitle t;
  const std::string page = tag_of(svg, "<svg ");
  t.page_width = number_attribute(page, "width");
  t.page_height = number_attribute(page, "height");
  const std::string title = tag_of(svg, "<text class=\"title\"");
  EXPECT_FALSE(title.empty()) << "no title in the page";
  if (title.empty()) return t;
  t.x = number_attribute(title, "x");
  t.font_size = number_attribute(title, "font-size");
  const std::size_t body_start = svg.find(title) + title.size();
  const std::string body = svg.substr(body_start, svg.find("</text>", body_start) - body_start);
  t.lines.push_back(body.substr(0, body.find("<tspan")));
  for (std::size_t at = body.find("<tspan"); at != std::string::npos; at = body.find("<tspan", at + 1)) {
    const std::size_t text_start = body.find('>', at) + 1;
    t.lines.push_back(body.substr(text_start, body.find("</tspan>", text_start) - text_start));
  }
  return t;
}

// Every line of the written title within the page, right margin aside, by the estimate.
void expect_title_fits(const WrittenTitle& t) {
  for (const std::string& line : t.lines) {
    EXPECT_LE(t.x + estimate_text_width(line, t.font_size, true), t.page_width) << line << " at " << t.font_size;
  }
}

TEST(SvgText, WidthGrowsWithTheTextTheSizeAndTheWeight) {
  EXPECT_EQ(estimate_text_width("", 12), 0.0);
  EXPECT_LT(estimate_text_width("raylab", 12), estimate_text_width("raylab compare", 12));
  EXPECT_DOUBLE_EQ(estimate_text_width("raylab", 24), 2 * estimate_text_width("raylab", 12));
  EXPECT_GT(estimate_text_width("raylab", 12, true), estimate_text_width("raylab", 12, false));
  EXPECT_LT(estimate_text_width("iiii", 12), estimate_text_width("mmmm", 12));
  EXPECT_LT(estimate_text_width("abcd", 12), estimate_text_width("ABCD", 12));
  // An em of average text is at least half the size: no sans-serif is narrower than that.
  EXPECT_GE(estimate_text_width("the quick brown fox jumps over the lazy dog", 10), 43 * 10 * 0.45);
}

TEST(SvgText, ShortTitleKeepsItsSize) {
  const SvgTitle t = fit_svg_title("raylab compare: demo", 700, 18, 11);
  EXPECT_EQ(t.font_size, 18);
  EXPECT_EQ(t.lines, std::vector<std::string>{"raylab compare: demo"});
  EXPECT_EQ(t.extra_height(), 0.0);
}

TEST(SvgText, TitleShrinksBeforeItWraps) {
  const std::string text = "raylab quality: aa-zoneplate, every sampler against an auto reference";
  const double full = estimate_text_width(text, 18, true);
  const SvgTitle t = fit_svg_title(text, full * 0.8, 18, 11);
  ASSERT_EQ(t.lines.size(), 1u);
  EXPECT_LT(t.font_size, 18);
  EXPECT_GE(t.font_size, 11);
  EXPECT_LE(estimate_text_width(text, t.font_size, true), full * 0.8);
}

TEST(SvgText, LongTitleWrapsAtTheSmallestSize) {
  const SvgTitle t = fit_svg_title(kLongTitle, 400, 18, 11);
  EXPECT_EQ(t.font_size, 11);
  ASSERT_GT(t.lines.size(), 1u);
  for (const std::string& line : t.lines) EXPECT_LE(estimate_text_width(line, 11, true), 400) << line;
  // Nothing lost; the path, longer than a line, is broken inside itself.
  std::string joined;
  for (const std::string& line : t.lines) joined += line;
  std::string no_spaces;
  for (char c : kLongTitle) {
    if (c != ' ') no_spaces += c;
  }
  std::string joined_no_spaces;
  for (char c : joined) {
    if (c != ' ') joined_no_spaces += c;
  }
  EXPECT_EQ(joined_no_spaces, no_spaces);
  EXPECT_GT(t.extra_height(), 0.0);
}

TEST(SvgText, BarChartTitleFitsItsCanvas) {
  BarPanel p{"Build time", "ms", {"bvh", "grid"}, {"build"}, {{1.0}, {2.0}}};
  const std::vector<BarPanel> panels = {p};
  const WrittenTitle short_title = written_title(bar_chart_svg("raylab compare: demo", panels));
  EXPECT_EQ(short_title.lines.size(), 1u);
  expect_title_fits(short_title);
  const WrittenTitle long_title = written_title(bar_chart_svg(kLongTitle, panels));
  expect_title_fits(long_title);
  EXPECT_EQ(words_of(kLongTitle).front(), words_of(long_title.lines.front()).front());
  // A wrapped title pushes the panels down: the page grows by the extra lines.
  EXPECT_GT(long_title.page_height, short_title.page_height);
}

TEST(SvgText, LineChartTitleFitsItsCanvas) {
  LineChart c;
  c.x_label = "rays per pixel";
  c.y_label = "RMSE";
  c.series.push_back({"jittered", {{1, 0.1}, {4, 0.05}}});
  c.title = "raylab quality: demo";
  const WrittenTitle short_title = written_title(line_chart_svg(c));
  expect_title_fits(short_title);
  c.title = kLongTitle;
  const std::string svg = line_chart_svg(c);
  const WrittenTitle long_title = written_title(svg);
  expect_title_fits(long_title);
  EXPECT_GT(long_title.lines.size(), 1u);
  EXPECT_GT(long_title.page_height, short_title.page_height);
  EXPECT_NE(svg.find("<g transform=\"translate(0 "), std::string::npos);  // the plot moved under it
}

}  // namespace
}  // namespace raylab
