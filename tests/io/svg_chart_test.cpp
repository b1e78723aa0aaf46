// SVG charts: well-formed XML, one bar per value, escaped text, skipped structures without bars.

#include "raylab/io/svg_chart.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/lab/compare_charts.h"

namespace raylab {
namespace {

// A small XML checker: every tag closes in order, attributes are quoted, text has no raw '<'
// or unknown '&'. Returns "" when well-formed, else what is wrong; counts elements by name.
std::string check_xml(const std::string& xml, std::map<std::string, int>& counts) {
  std::vector<std::string> open;
  std::size_t i = 0;
  if (xml.rfind("<?xml", 0) == 0) i = xml.find("?>") + 2;
  bool root_seen = false;
  while (i < xml.size()) {
    if (xml[i] != '<') {
      if (xml[i] == '&') {
        const std::size_t semi = xml.find(';', i);
        const std::string entity = xml.substr(i, semi - i + 1);
        if (entity != "&amp;" && entity != "&lt;" && entity != "&gt;" && entity != "&quot;" && entity != "&apos;") {
          return "bad entity at " + std::to_string(i);
        }
      }
      if (open.empty() && !std::isspace(static_cast<unsigned char>(xml[i]))) return "text outside the root";
      ++i;
      continue;
    }
    const std::size_t end = xml.find('>', i);
    if (end == std::string::npos) return "unclosed tag";
    std::string tag = xml.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.starts_with('/')) {
      if (open.empty() || open.back() != tag.substr(1)) return "mismatched </" + tag.substr(1) + ">";
      open.pop_back();
      continue;
    }
    const bool self_closing = tag.ends_with('/');
    if (self_closing) tag.pop_back();
    const std::string name = tag.substr(0, tag.find_first_of(" \n"));
    if (open.empty()) {
      if (root_seen) return "two roots";
      root_seen = true;
    }
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return "unbalanced quotes in <" + name + ">";
    if (tag.find('<') != std::string::npos) return "'<' inside <" + name + ">";
    ++counts[name];
    if (tag.find("class=\"bar\"") != std::string::npos) ++counts["bar"];
    if (!self_closing) open.push_back(name);
  }
  return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

TEST(SvgChart, GroupedBarsAreWellFormed) {
  BarPanel p{"Speed & <size>", "Mrays/s", {"bvh", "grid\"s"}, {"primary", "shadow"}, {{1.5, 2.0}, {0.5, NAN}}};
  BarPanel q{"Build", "ms", {"bvh", "grid\"s"}, {"build"}, {{3.0}, {-1.0}}};
  const std::vector<BarPanel> panels = {p, q};
  const std::string svg = bar_chart_svg("a < b", panels);
  std::map<std::string, int> counts;
  ASSERT_EQ(check_xml(svg, counts), "") << svg;
  EXPECT_EQ(counts["svg"], 1);
  EXPECT_EQ(counts["bar"], 4);  // NaN and negative values draw no bar
  EXPECT_EQ(counts["g"], 2);    // one group per panel
  EXPECT_NE(svg.find("Speed &amp; &lt;size&gt;"), std::string::npos);
  EXPECT_NE(svg.find("grid&quot;s"), std::string::npos);
  EXPECT_NE(svg.find("a &lt; b"), std::string::npos);
}

TEST(SvgChart, TallerValuesGetTallerBars) {
  const BarPanel p{"t", "u", {"a", "b"}, {"s"}, {{1.0}, {4.0}}};
  const std::string svg = bar_chart_svg("t", std::vector<BarPanel>{p});
  std::vector<double> heights;
  for (std::size_t at = svg.find("class=\"bar\""); at != std::string::npos; at = svg.find("class=\"bar\"", at + 1)) {
    const std::size_t h = svg.find("height=\"", at) + 8;
    heights.push_back(std::stod(svg.substr(h)));
  }
  ASSERT_EQ(heights.size(), 2u);
  EXPECT_NEAR(heights[1] / heights[0], 4.0, 0.01);
}

TEST(SvgChart, ComparisonChartHasAllStructuresAndNoBarsForSkippedOnes) {
  CompareResult r;
  r.width = r.height = 8;
  for (const char* name : {"brute", "bvh", "bvh2"}) {
    AccelMeasure m;
    m.name = name;
    m.skipped = std::string(name) == "brute";
    m.build_seconds = 0.01;
    m.bytes_per_primitive = 50.0;
    for (KindMeasure& k : m.kinds) {
      k.rays = 10;
      k.mrays_per_second = 3.0;
    }
    r.accels.push_back(m);
  }
  const std::string svg = compare_chart_svg(r, "spd:balls");
  std::map<std::string, int> counts;
  ASSERT_EQ(check_xml(svg, counts), "") << svg;
  EXPECT_EQ(counts["bar"], 2 * 3 + 2 + 2);  // speed per kind, build time, memory; none for brute
  EXPECT_NE(svg.find("brute (skipped)"), std::string::npos);
  EXPECT_NE(svg.find("spd:balls"), std::string::npos);
}

TEST(SvgChart, FailedWriteLeavesNoFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "raylab-svg-missing-folder";
  std::filesystem::remove_all(dir);
  EXPECT_THROW(write_compare_chart(CompareResult{}, "s", (dir / "c.svg").string()), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir));
}

}  // namespace
}  // namespace raylab
