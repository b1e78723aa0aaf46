#include "raylab/io/svg_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "raylab/io/atomic_file.h"
#include "raylab/io/svg_text.h"

namespace raylab {
namespace {

// Page geometry in SVG user units (pixels).
constexpr double kWidth = 820.0;
constexpr double kTitleHeight = 44.0;
constexpr double kPanelHeight = 300.0;
constexpr double kPlotLeft = 74.0;
constexpr double kPlotRight = kWidth - 24.0;
constexpr double kTitleSize = 18.0;     // the chart title's font size, shrunk to fit ...
constexpr double kMinTitleSize = 11.0;  // ... down to this one, then wrapped
constexpr double kPlotTop = 44.0;       // below the panel's top
constexpr double kPlotBottom = 250.0;   // below the panel's top; group labels go under it

// Series colours: well apart in hue and lightness, readable on white.
constexpr std::array<const char*, 6> kPalette = {"#3b528b", "#21918c", "#8fd14f", "#e07b39", "#b5367a", "#6b6b6b"};

bool has_bar(double v) { return std::isfinite(v) && v >= 0.0; }

// A round tick step (1, 2 or 5 times a power of ten) giving about five ticks up to `max`.
double tick_step(double max) {
  if (!(max > 0.0)) return 0.2;
  const double raw = max / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / mag;
  return (norm <= 1.0 ? 1.0 : norm <= 2.0 ? 2.0 : norm <= 5.0 ? 5.0 : 10.0) * mag;
}

std::string number(double v) { return fmt::format("{:.4g}", v); }

void append_panel(std::string& out, const BarPanel& p, double top) {
  double max = 0.0;
  for (const auto& row : p.values) {
    for (double v : row) {
      if (has_bar(v)) max = std::max(max, v);
    }
  }
  const double step = tick_step(max);
  const double axis_max = max > 0.0 ? std::ceil(max / step - 1e-9) * step : 1.0;
  const double y0 = top + kPlotBottom, y1 = top + kPlotTop;
  const double plot_h = y0 - y1, plot_w = kPlotRight - kPlotLeft;
  out +=
      fmt::format("<g class=\"panel\">\n<text x=\"{}\" y=\"{:.1f}\" font-size=\"15\" font-weight=\"bold\">{}</text>\n",
                  kPlotLeft, top + 20.0, xml_escape(p.title));
  // Legend: one swatch per series, right-aligned on the title line.
  double lx = kPlotRight - 110.0 * static_cast<double>(p.series.size());
  for (std::size_t s = 0; s < p.series.size(); ++s, lx += 110.0) {
    out += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"12\" height=\"12\" fill=\"{}\"/>", lx, top + 10.0,
                       kPalette[s % kPalette.size()]);
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"12\">{}</text>\n", lx + 16.0, top + 20.5,
                       xml_escape(p.series[s]));
  }
  for (double v = 0.0; v <= axis_max + step * 1e-6; v += step) {
    const double y = y0 - v / axis_max * plot_h;
    out += fmt::format(
        "<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#dddddd\"/>"
        "<text x=\"{}\" y=\"{:.1f}\" font-size=\"11\" text-anchor=\"end\">{}</text>\n",
        kPlotLeft, y, kPlotRight, y, kPlotLeft - 6.0, y + 4.0, number(v));
  }
  out += fmt::format(
      "<text transform=\"translate({:.1f} {:.1f}) rotate(-90)\" font-size=\"12\" text-anchor=\"middle\">{}</text>\n",
      kPlotLeft - 50.0, (y0 + y1) / 2.0, xml_escape(p.unit));
  const double group_w = plot_w / static_cast<double>(std::max<std::size_t>(p.groups.size(), 1));
  const double bar_w = group_w * 0.8 / static_cast<double>(std::max<std::size_t>(p.series.size(), 1));
  for (std::size_t g = 0; g < p.groups.size(); ++g) {
    const double gx = kPlotLeft + static_cast<double>(g) * group_w;
    for (std::size_t s = 0; s < p.series.size(); ++s) {
      const double v = g < p.values.size() && s < p.values[g].size() ? p.values[g][s] : NAN;
      if (!has_bar(v)) continue;
      const double h = v / axis_max * plot_h;
      const double x = gx + group_w * 0.1 + static_cast<double>(s) * bar_w;
      out += fmt::format(
          "<rect class=\"bar\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"{}\">"
          "<title>{} {}: {}</title></rect>"
          "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"10\" text-anchor=\"middle\">{}</text>\n",
          x, y0 - h, bar_w * 0.92, h, kPalette[s % kPalette.size()], xml_escape(p.groups[g]), xml_escape(p.series[s]),
          number(v), x + bar_w * 0.46, y0 - h - 3.0, number(v));
    }
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"12\" text-anchor=\"middle\">{}</text>\n",
                       gx + group_w / 2.0, y0 + 18.0, xml_escape(p.groups[g]));
  }
  out += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#333333\"/>\n</g>\n", kPlotLeft,
                     y0, kPlotRight, y0);
}

}  // namespace

std::string xml_escape(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string bar_chart_svg(std::string_view title, std::span<const BarPanel> panels) {
  // A long title (a scene's path) is shrunk, then wrapped, and the panels moved down under it.
  const SvgTitle fitted = fit_svg_title(title, kWidth - kPlotLeft - (kWidth - kPlotRight), kTitleSize, kMinTitleSize);
  const double title_height = kTitleHeight + fitted.extra_height();
  const double height = title_height + kPanelHeight * static_cast<double>(panels.size());
  std::string out = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      kWidth, height);
  out += svg_title_element(fitted, kPlotLeft, 28.0);
  for (std::size_t i = 0; i < panels.size(); ++i) {
    append_panel(out, panels[i], title_height + kPanelHeight * static_cast<double>(i));
  }
  return out + "</svg>\n";
}

}  // namespace raylab
