#include "raylab/io/line_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "raylab/io/atomic_file.h"
#include "raylab/io/svg_chart.h"
#include "raylab/io/svg_text.h"

namespace raylab {
namespace {

// Page geometry in SVG user units (pixels); the legend takes the strip right of the plot.
constexpr double kWidth = 820.0;
constexpr double kHeight = 520.0;
constexpr double kPlotLeft = 84.0;
constexpr double kPlotRight = 620.0;
constexpr double kPlotTop = 56.0;
constexpr double kPlotBottom = 456.0;
constexpr double kLegendLeft = 640.0;
constexpr double kRightMargin = 24.0;
constexpr double kTitleSize = 17.0;     // the title's font size, shrunk to fit ...
constexpr double kMinTitleSize = 11.0;  // ... down to this one, then wrapped
// Up to this many decades on an axis, the 2..9 sub-ticks are drawn too.
constexpr int kMinorTickDecades = 4;

// Eight colours well apart in hue and lightness (the bar chart's six and two more), and dash
// patterns, so that eight lines stay apart in grey too.
constexpr std::array<const char*, 8> kPalette = {"#3b528b", "#21918c", "#8fd14f", "#e07b39",
                                                 "#b5367a", "#6b6b6b", "#d4a017", "#17becf"};
constexpr std::array<const char*, 3> kDashes = {"", "7 3", "2 3"};

bool drawable(const ChartPoint& p) { return std::isfinite(p.x) && std::isfinite(p.y) && p.x > 0.0 && p.y > 0.0; }

// A log axis from 10^lo to 10^hi, whole decades around the data (at least one).
struct LogAxis {
  int lo = 0;
  int hi = 1;

  double fraction(double v) const { return (std::log10(v) - lo) / static_cast<double>(hi - lo); }
};

LogAxis axis_for(double min, double max) {
  if (!(min > 0.0) || !std::isfinite(min) || !std::isfinite(max)) return {};
  LogAxis a;
  // A little slack so that a value a hair above a power of ten (rounding) stays in its decade.
  a.lo = static_cast<int>(std::floor(std::log10(min) + 1e-9));
  a.hi = static_cast<int>(std::ceil(std::log10(max) - 1e-9));
  if (a.hi <= a.lo) a.hi = a.lo + 1;
  return a;
}

// "0.001", "1", "100", "10000"; beyond that "1e5", "1e-5".
std::string decade_label(int k) {
  if (k >= 0 && k <= 4) return fmt::format("{}", static_cast<long>(std::lround(std::pow(10.0, k))));
  if (k < 0 && k >= -4) return fmt::format("{:.{}f}", std::pow(10.0, k), -k);
  return fmt::format("1e{}", k);
}

std::string number(double v) { return fmt::format("{:.4g}", v); }

void append_grid(std::string& out, const LogAxis& xa, const LogAxis& ya) {
  const double w = kPlotRight - kPlotLeft, h = kPlotBottom - kPlotTop;
  auto minor = [](const LogAxis& a) { return a.hi - a.lo <= kMinorTickDecades; };
  for (int k = xa.lo; k <= xa.hi; ++k) {
    for (int m = 1; m <= (k < xa.hi && minor(xa) ? 9 : 1); ++m) {
      const double x = kPlotLeft + xa.fraction(m * std::pow(10.0, k)) * w;
      out += fmt::format("<line x1=\"{:.1f}\" y1=\"{}\" x2=\"{:.1f}\" y2=\"{}\" stroke=\"{}\"/>\n", x, kPlotTop, x,
                         kPlotBottom, m == 1 ? "#cccccc" : "#eeeeee");
    }
    out += fmt::format("<text x=\"{:.1f}\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\">{}</text>\n",
                       kPlotLeft + xa.fraction(std::pow(10.0, k)) * w, kPlotBottom + 18.0, decade_label(k));
  }
  for (int k = ya.lo; k <= ya.hi; ++k) {
    for (int m = 1; m <= (k < ya.hi && minor(ya) ? 9 : 1); ++m) {
      const double y = kPlotBottom - ya.fraction(m * std::pow(10.0, k)) * h;
      out += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"{}\"/>\n", kPlotLeft, y,
                         kPlotRight, y, m == 1 ? "#cccccc" : "#eeeeee");
    }
    out += fmt::format("<text x=\"{}\" y=\"{:.1f}\" font-size=\"12\" text-anchor=\"end\">{}</text>\n", kPlotLeft - 6.0,
                       kPlotBottom - ya.fraction(std::pow(10.0, k)) * h + 4.0, decade_label(k));
  }
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333333\"/>\n",
                     kPlotLeft, kPlotTop, w, h);
}

}  // namespace

std::string line_chart_svg(const LineChart& chart) {
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const LineSeries& s : chart.series) {
    for (const ChartPoint& p : s.points) {
      if (!drawable(p)) continue;
      xmin = std::min(xmin, p.x);
      xmax = std::max(xmax, p.x);
      ymin = std::min(ymin, p.y);
      ymax = std::max(ymax, p.y);
    }
  }
  const LogAxis xa = axis_for(xmin, xmax), ya = axis_for(ymin, ymax);
  const double w = kPlotRight - kPlotLeft, h = kPlotBottom - kPlotTop;
  // A long title is shrunk, then wrapped, and the rest of the page moved down under it.
  const SvgTitle title = fit_svg_title(chart.title, kWidth - kPlotLeft - kRightMargin, kTitleSize, kMinTitleSize);
  const double extra = title.extra_height();
  std::string out = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      kWidth, kHeight + extra);
  out += svg_title_element(title, kPlotLeft, 30.0);
  if (extra > 0.0) out += fmt::format("<g transform=\"translate(0 {})\">\n", extra);
  append_grid(out, xa, ya);
  out += fmt::format("<text x=\"{:.1f}\" y=\"{}\" font-size=\"13\" text-anchor=\"middle\">{}</text>\n",
                     (kPlotLeft + kPlotRight) / 2.0, kPlotBottom + 42.0, xml_escape(chart.x_label));
  out += fmt::format(
      "<text transform=\"translate({:.1f} {:.1f}) rotate(-90)\" font-size=\"13\" text-anchor=\"middle\">{}</text>\n",
      kPlotLeft - 58.0, (kPlotTop + kPlotBottom) / 2.0, xml_escape(chart.y_label));

  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const LineSeries& s = chart.series[i];
    const char* colour = kPalette[i % kPalette.size()];
    const char* dash = kDashes[i % kDashes.size()];
    const std::string dash_attr = *dash ? fmt::format(" stroke-dasharray=\"{}\"", dash) : "";
    std::string points, markers;
    for (const ChartPoint& p : s.points) {
      if (!drawable(p)) continue;
      const double x = kPlotLeft + xa.fraction(p.x) * w, y = kPlotBottom - ya.fraction(p.y) * h;
      points += fmt::format("{}{:.1f},{:.1f}", points.empty() ? "" : " ", x, y);
      markers += fmt::format(
          "<circle class=\"point\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.5\" fill=\"{}\"><title>{}: {}, {}</title>"
          "</circle>\n",
          x, y, colour, xml_escape(s.name), number(p.x), number(p.y));
    }
    out += fmt::format("<g class=\"series\">\n");
    if (!points.empty()) {
      out += fmt::format("<polyline class=\"line\" points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"{}/>\n",
                         points, colour, dash_attr);
    }
    out += markers;
    const double ly = kPlotTop + 10.0 + 22.0 * static_cast<double>(i);
    out += fmt::format(
        "<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"2\"{}/>"
        "<circle cx=\"{}\" cy=\"{:.1f}\" r=\"3.5\" fill=\"{}\"/>"
        "<text x=\"{}\" y=\"{:.1f}\" font-size=\"12\">{}</text>\n</g>\n",
        kLegendLeft, ly, kLegendLeft + 28.0, ly, colour, dash_attr, kLegendLeft + 14.0, ly, colour, kLegendLeft + 36.0,
        ly + 4.0, xml_escape(s.name));
  }
  if (extra > 0.0) out += "</g>\n";
  return out + "</svg>\n";
}

void write_line_chart(const LineChart& chart, const std::string& path) {
  const std::string svg = line_chart_svg(chart);
  write_file_atomically(path, std::span(reinterpret_cast<const unsigned char*>(svg.data()), svg.size()));
}

}  // namespace raylab
