// Log-log line charts: decade ticks around the data, points where the log scale puts them, one
// line and legend entry per series, escaped text. (The quality study's chart: tests/lab.)

#include "raylab/io/line_chart.h"

#include <gtest/gtest.h>

#include <cmath>

namespace raylab {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The (cx, cy) of every marker circle, in document order. (Plain string search: GCC 12 warns
// inside std::regex under the sanitizers, and warnings are errors.)
std::vector<std::pair<double, double>> markers(const std::string& svg) {
  std::vector<std::pair<double, double>> out;
  const std::string head = "<circle class=\"point\" cx=\"";
  for (std::size_t at = svg.find(head); at != std::string::npos; at = svg.find(head, at + 1)) {
    const std::size_t x = at + head.size();
    const std::size_t y = svg.find("cy=\"", x) + 4;
    out.emplace_back(std::stod(svg.substr(x)), std::stod(svg.substr(y)));
  }
  return out;
}

// The tick labels: text elements anchored at the middle (x axis) or the end (y axis).
bool has_label(const std::string& svg, const std::string& anchor, const std::string& label) {
  return svg.find("text-anchor=\"" + anchor + "\">" + label + "</text>") != std::string::npos;
}

LineChart two_lines() {
  LineChart c;
  c.title = "RMSE <vs> rays & \"time\"";
  c.x_label = "rays per pixel";
  c.y_label = "RMSE";
  c.series = {{"jittered", {{1, 0.1}, {4, 0.05}, {16, 0.025}, {64, 0.0125}}},
              {"adaptive", {{1.5, 0.06}, {3, 0.02}, {0, 0.5}, {5, NAN}, {6, -1}}}};
  return c;
}

TEST(LineChart, AxesSpanWholeDecadesAroundTheData) {
  const std::string svg = line_chart_svg(two_lines());
  ASSERT_TRUE(svg.starts_with("<?xml")) << svg.substr(0, 80);
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
  // x: 1 .. 64 -> 1, 10, 100; y: 0.0125 .. 0.1 -> 0.01, 0.1 (0.1 is a decade itself).
  for (const char* x : {"1", "10", "100"}) EXPECT_TRUE(has_label(svg, "middle", x)) << x;
  EXPECT_FALSE(has_label(svg, "middle", "1000"));
  for (const char* y : {"0.01", "0.1"}) EXPECT_TRUE(has_label(svg, "end", y)) << y;
  EXPECT_FALSE(has_label(svg, "end", "1"));
  EXPECT_FALSE(has_label(svg, "end", "0.001"));
}

TEST(LineChart, PointsLieWhereTheLogScalePutsThem) {
  const std::vector<std::pair<double, double>> m = markers(line_chart_svg(two_lines()));
  ASSERT_EQ(m.size(), 6u);  // the points with a zero, negative or NaN coordinate are left out
  // The plot spans x 84..620 for 10^0..10^2 and y 456..56 for 10^-2..10^-1.
  auto px = [](double x) { return 84.0 + std::log10(x) / 2.0 * 536.0; };
  auto py = [](double y) { return 456.0 - (std::log10(y) + 2.0) * 400.0; };
  const double xs[] = {1, 4, 16, 64, 1.5, 3}, ys[] = {0.1, 0.05, 0.025, 0.0125, 0.06, 0.02};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_NEAR(m[i].first, px(xs[i]), 0.051) << i;
    EXPECT_NEAR(m[i].second, py(ys[i]), 0.051) << i;
  }
  // Halving the error at every factor four of rays is a straight line of slope -1/2: equal
  // steps on both axes.
  EXPECT_NEAR(m[1].first - m[0].first, m[2].first - m[1].first, 0.11);
  EXPECT_NEAR(m[1].second - m[0].second, m[2].second - m[1].second, 0.11);
}

TEST(LineChart, OneLineAndOneLegendEntryPerSeriesWithEscapedText) {
  const std::string svg = line_chart_svg(two_lines());
  EXPECT_EQ(count(svg, "<g class=\"series\">"), 2u);
  EXPECT_EQ(count(svg, "<polyline class=\"line\""), 2u);
  EXPECT_NE(svg.find(">jittered</text>"), std::string::npos);
  EXPECT_NE(svg.find(">adaptive</text>"), std::string::npos);
  EXPECT_NE(svg.find("RMSE &lt;vs&gt; rays &amp; &quot;time&quot;"), std::string::npos);
  EXPECT_EQ(svg.find("<vs>"), std::string::npos);
  EXPECT_NE(svg.find(">rays per pixel</text>"), std::string::npos);
  EXPECT_NE(svg.find("rotate(-90)"), std::string::npos);  // the y label stands upright
}

TEST(LineChart, EmptyChartsStillHaveAxes) {
  LineChart c;
  c.title = "nothing";
  c.series = {{"none", {{0, 0}}}};
  const std::string svg = line_chart_svg(c);
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
  EXPECT_EQ(count(svg, "<polyline"), 0u);
  EXPECT_TRUE(has_label(svg, "middle", "1"));
  EXPECT_TRUE(has_label(svg, "middle", "10"));
}

}  // namespace
}  // namespace raylab
