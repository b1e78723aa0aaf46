#include "raylab/io/heatmap.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace raylab {
namespace {

// Viridis sampled at nine evenly spaced points; between them the colour is interpolated.
constexpr std::array<Rgb8, 9> kViridis = {{{68, 1, 84},
                                           {71, 45, 123},
                                           {59, 82, 139},
                                           {44, 114, 142},
                                           {33, 145, 140},
                                           {40, 174, 128},
                                           {94, 201, 98},
                                           {173, 220, 48},
                                           {253, 231, 37}}};

constexpr Rgb8 kBackground{24, 24, 28};
constexpr Rgb8 kInk{235, 235, 235};

// Legend geometry in font pixels (times kLegendFontScale): margins, the title, the bar, the
// tick marks and the labels under them, top to bottom.
constexpr int kMargin = 8;
constexpr int kTitleGap = 4;  // between the title and the bar
constexpr int kBarHeight = 8;
constexpr int kTickLength = 2;
constexpr int kLabelGap = 3;          // from the bar's bottom to the labels' top
constexpr int kLabelSpace = 3;        // the least room between two labels
constexpr int kMinLegendWidth = 320;  // pixels: room for a few labels under the shortest map

void check_size(std::span<const std::uint32_t> values, int width, int height, const char* who) {
  if (width < 0 || height < 0 || values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument(std::string(who) + ": values do not match the image size");
  }
}

}  // namespace

Rgb8 heat_colour(float t) {
  const float f = std::clamp(std::isfinite(t) ? t : 0.f, 0.f, 1.f) * static_cast<float>(kViridis.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(f), kViridis.size() - 2);
  const float w = f - static_cast<float>(i);
  auto mix = [w](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::lround(static_cast<float>(a) + w * static_cast<float>(b - a)));
  };
  const Rgb8 a = kViridis[i], b = kViridis[i + 1];
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

float HeatScale::position(double value) const {
  const double range = max_value - min_value, v = value - min_value;
  if (!(range > 0.0) || !(v > 0.0)) return 0.f;
  return static_cast<float>(std::min(1.0, logarithmic ? std::log1p(v) / std::log1p(range) : v / range));
}

int heat_legend_height() {
  return (2 * kMargin + kGlyphHeight + kTitleGap + kBarHeight + kLabelGap + kGlyphHeight) * kLegendFontScale;
}

std::string heat_legend_label(double v) {
  if (v < 10000.0) return fmt::format("{:.0f}", v);
  if (v < 1e7) return fmt::format("{:.0f}K", v / 1e3);
  return fmt::format("{:.0f}M", v / 1e6);
}

std::vector<double> heat_legend_ticks(const HeatScale& scale) {
  const double lo = scale.min_value, hi = scale.max_value;
  std::vector<double> ticks = {lo};
  if (scale.logarithmic) {
    for (double decade = 1.0; decade < hi; decade *= 10.0) {
      for (double m : {1.0, 2.0, 5.0}) {
        if (m * decade > lo && m * decade < hi) ticks.push_back(m * decade);
      }
    }
  } else if (hi > lo) {
    const double raw = (hi - lo) / 5.0;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double norm = raw / mag;
    const double step = std::max(1.0, (norm <= 1.0 ? 1.0 : norm <= 2.0 ? 2.0 : norm <= 5.0 ? 5.0 : 10.0) * mag);
    for (double v = std::floor(lo / step + 1.0) * step; v < hi; v += step) ticks.push_back(v);
  }
  if (hi > lo) ticks.push_back(hi);
  return ticks;
}

Rgb8Image render_heatmap(std::span<const std::uint32_t> values, int width, int height, const HeatScale& scale) {
  check_size(values, width, height, "render_heatmap");
  Rgb8Image img(width, height);
  for (std::size_t i = 0; i < values.size(); ++i) img.pixels[i] = scale.colour(values[i]);
  return img;
}

Rgb8Image render_heat_legend(const HeatScale& scale, std::string_view title, int width) {
  const int s = kLegendFontScale;
  const int margin = kMargin * s;
  const std::vector<double> ticks = heat_legend_ticks(scale);
  // Wide enough for the title, and for the end labels, which overhang the bar by half a label.
  const int end_labels =
      text_width(heat_legend_label(ticks.front()), s) + text_width(heat_legend_label(ticks.back()), s);
  Rgb8Image img(std::max({width, kMinLegendWidth, text_width(title, s) + 2 * margin, end_labels + 2 * margin}),
                heat_legend_height(), kBackground);
  draw_text(img, margin, margin, title, kInk, s);

  const int bar_top = margin + (kGlyphHeight + kTitleGap) * s;
  const int bar_h = kBarHeight * s;
  const int x0 = margin, bar_w = img.width - 2 * margin;
  for (int x = 0; x < bar_w; ++x) {
    const Rgb8 c = heat_colour(static_cast<float>(x) / static_cast<float>(bar_w - 1));
    for (int y = bar_top; y < bar_top + bar_h; ++y) img.put(x0 + x, y, c);
  }
  // Labels placed greedily from the left; the maximum first, so that it is never crowded out.
  const int label_top = bar_top + bar_h + kLabelGap * s;
  std::vector<std::pair<int, int>> taken;  // label extents [left, right)
  auto place = [&](double v, bool force) {
    const int x = x0 + static_cast<int>(std::lround(scale.position(v) * static_cast<float>(bar_w - 1)));
    const std::string label = heat_legend_label(v);
    const int w = text_width(label, s);
    const int left = std::clamp(x - w / 2, margin / 2, std::max(img.width - margin / 2 - w, 0));
    for (const auto& [l, r] : taken) {
      if (!force && left < r + kLabelSpace * s && left + w + kLabelSpace * s > l) return;
    }
    taken.emplace_back(left, left + w);
    for (int y = bar_top + bar_h; y < bar_top + bar_h + kTickLength * s; ++y) {
      for (int dx = 0; dx < s; ++dx) img.put(std::min(x, x0 + bar_w - s) + dx, y, kInk);
    }
    draw_text(img, left, label_top, label, kInk, s);
  };
  place(ticks.back(), true);
  for (std::size_t i = 0; i + 1 < ticks.size(); ++i) place(ticks[i], false);
  return img;
}

std::string heat_legend_path(const std::string& map_path) {
  const std::filesystem::path p(map_path);
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".png") return map_path + ".legend.png";
  return map_path.substr(0, map_path.size() - 4) + ".legend.png";
}

std::vector<std::string> write_heatmap_png(std::span<const std::uint32_t> values, int width, int height,
                                           const HeatScale& scale, std::string_view title, const std::string& path) {
  const Rgb8Image map = render_heatmap(values, width, height, scale);
  const std::string legend_path = heat_legend_path(path);
  write_png(map, path);
  try {
    write_png(render_heat_legend(scale, title, width), legend_path);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(path, ec);  // a map without its legend cannot be read
    throw;
  }
  return {path, legend_path};
}

HeatScale sample_count_scale(std::span<const std::uint32_t> counts, CountScale scale) {
  HeatScale heat;
  heat.logarithmic = scale == CountScale::kLog;
  if (!counts.empty()) {
    const auto [lo, hi] = std::minmax_element(counts.begin(), counts.end());
    heat.max_value = *hi;
    heat.min_value = *lo < *hi ? *lo : 0.0;  // one count everywhere: show it against zero
  }
  return heat;
}

std::string_view sample_count_title(CountScale scale) {
  return scale == CountScale::kLog ? "primary samples per pixel, log scale" : "primary samples per pixel, linear scale";
}

Rgb8Image render_sample_count_image(std::span<const std::uint32_t> counts, int width, int height, CountScale scale) {
  check_size(counts, width, height, "render_sample_count_image");
  return render_heatmap(counts, width, height, sample_count_scale(counts, scale));
}

std::vector<std::string> write_sample_count_png(std::span<const std::uint32_t> counts, int width, int height,
                                                const std::string& path, CountScale scale) {
  check_size(counts, width, height, "write_sample_count_png");
  return write_heatmap_png(counts, width, height, sample_count_scale(counts, scale), sample_count_title(scale), path);
}

}  // namespace raylab
