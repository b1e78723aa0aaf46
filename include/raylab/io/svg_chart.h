#pragma once
/// \file
/// SVG bar charts, written by hand (the format is text): used for the `raylab compare` plot
/// (lab/compare_charts.h).

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

/// One panel of a grouped bar chart: a cluster of bars per group, one bar per series in each,
/// on a linear axis from zero.
struct BarPanel {
  std::string title;                        ///< above the panel
  std::string unit;                         ///< axis label
  std::vector<std::string> groups;          ///< cluster labels (structures)
  std::vector<std::string> series;          ///< bar labels, one colour each (ray kinds)
  std::vector<std::vector<double>> values;  ///< values[group][series]; NaN or negative: no bar
};

/// An SVG document: `title`, then the panels stacked top to bottom, each with its axis, tick
/// lines, a legend of its series and the value above each bar. Text is XML-escaped. Each bar
/// is a `<rect class="bar">`.
std::string bar_chart_svg(std::string_view title, std::span<const BarPanel> panels);

/// `text` with &, <, >, " and ' replaced by entities.
std::string xml_escape(std::string_view text);

}  // namespace raylab
