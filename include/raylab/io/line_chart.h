#pragma once
/// \file
/// SVG line charts on log-log axes, written by hand (the format is text): error against cost
/// for `raylab quality`, and any other power law worth a look (scaling plots).

#include <string>
#include <string_view>
#include <vector>

namespace raylab {

/// A point of a line.
struct ChartPoint {
  double x = 0.0;
  double y = 0.0;
};

/// One line of the chart, drawn through its points in the order given, a marker on each.
struct LineSeries {
  std::string name;                ///< legend entry
  std::vector<ChartPoint> points;  ///< points with a coordinate that is not finite and > 0 are left out
};

/// A chart: title, axis labels and lines. Both axes are logarithmic.
struct LineChart {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<LineSeries> series;
};

/// An SVG document of `chart`: both axes logarithmic, spanning whole decades around the data,
/// with a labelled grid line at each power of ten (and unlabelled ones at 2..9 times it when
/// few decades are shown), the title above, the axis labels, and a legend on the right with
/// each series' colour, dash pattern and name. Each line is a `<polyline class="line">` and
/// each marker a `<circle class="point">` with a `<title>` giving its values. Text is
/// XML-escaped. A chart with no drawable point still has its frame and axes (one decade each).
std::string line_chart_svg(const LineChart& chart);

/// Writes line_chart_svg to `path` atomically.
void write_line_chart(const LineChart& chart, const std::string& path);

}  // namespace raylab
