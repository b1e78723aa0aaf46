#include "raylab/io/heatmap.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "raylab/io/image_io.h"
#include "raylab/render/film.h"

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

// A 3x5 font: five rows of three pixels per glyph, '#' = ink, written row after row from the top.
struct Glyph {
  char c;
  const char* rows;  // 15 characters
};
// clang-format off
constexpr Glyph kFont[] = {
    {'0', "###" "# #" "# #" "# #" "###"},
    {'1', " # " "## " " # " " # " "###"},
    {'2', "## " "  #" " # " "#  " "###"},
    {'3', "## " "  #" " # " "  #" "## "},
    {'4', "# #" "# #" "###" "  #" "  #"},
    {'5', "###" "#  " "## " "  #" "## "},
    {'6', " ##" "#  " "## " "# #" " # "},
    {'7', "###" "  #" " # " " # " " # "},
    {'8', " # " "# #" " # " "# #" " # "},
    {'9', " # " "# #" " ##" "  #" "## "},
    {'A', " # " "# #" "###" "# #" "# #"},
    {'B', "## " "# #" "## " "# #" "## "},
    {'C', " ##" "#  " "#  " "#  " " ##"},
    {'D', "## " "# #" "# #" "# #" "## "},
    {'E', "###" "#  " "## " "#  " "###"},
    {'F', "###" "#  " "## " "#  " "#  "},
    {'G', " ##" "#  " "# #" "# #" " ##"},
    {'H', "# #" "# #" "###" "# #" "# #"},
    {'I', "###" " # " " # " " # " "###"},
    {'J', "  #" "  #" "  #" "# #" " # "},
    {'K', "# #" "# #" "## " "# #" "# #"},
    {'L', "#  " "#  " "#  " "#  " "###"},
    {'M', "# #" "###" "###" "# #" "# #"},
    {'N', "## " "# #" "# #" "# #" "# #"},
    {'O', " # " "# #" "# #" "# #" " # "},
    {'P', "## " "# #" "## " "#  " "#  "},
    {'Q', " # " "# #" "# #" "## " " ##"},
    {'R', "## " "# #" "## " "# #" "# #"},
    {'S', " ##" "#  " " # " "  #" "## "},
    {'T', "###" " # " " # " " # " " # "},
    {'U', "# #" "# #" "# #" "# #" "###"},
    {'V', "# #" "# #" "# #" "# #" " # "},
    {'W', "# #" "# #" "###" "###" "# #"},
    {'X', "# #" "# #" " # " "# #" "# #"},
    {'Y', "# #" "# #" " # " " # " " # "},
    {'Z', "###" "  #" " # " "#  " "###"},
    {'.', "   " "   " "   " "   " " # "},
    {'-', "   " "   " "###" "   " "   "},
    {'/', "  #" "  #" " # " "#  " "#  "},
    {':', "   " " # " "   " " # " "   "},
    {'(', " # " "#  " "#  " "#  " " # "},
    {')', " # " "  #" "  #" "  #" " # "},
    {'_', "   " "   " "   " "   " "###"},
    {',', "   " "   " "   " " # " "#  "},
    {'=', "   " "###" "   " "###" "   "},
};
// clang-format on

const char* glyph_rows(char c) {
  const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kFont) {
    if (g.c == up) return g.rows;
  }
  return nullptr;
}

constexpr Rgb8 kBackground{24, 24, 28};
constexpr Rgb8 kInk{235, 235, 235};
constexpr int kMinWidth = 160;  // legend room at font scale 1 (pixels)

// A count for a tick label: exact below 10000, then with a k or M suffix.
std::string tick_label(double v) {
  if (v < 10000.0) return fmt::format("{:.0f}", v);
  if (v < 1e7) return fmt::format("{:.0f}K", v / 1e3);
  return fmt::format("{:.0f}M", v / 1e6);
}

// Tick values: the minimum, round values strictly between (1-2-5 steps of each decade on a log
// scale, about five even round steps on a linear one), and the maximum.
std::vector<double> tick_values(const HeatScale& scale) {
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

// The bar with labels under it, in the strip starting at row `top`.
void draw_legend(Rgb8Image& img, int top, const HeatScale& scale, std::string_view title, int s) {
  const int margin = 6 * s;
  draw_text(img, margin, top + 4 * s, title, kInk, s);
  const int bar_top = top + 12 * s;
  const int bar_h = 8 * s;
  const int x0 = margin;
  const int x1 = img.width - margin;  // exclusive
  const int bar_w = std::max(x1 - x0, 2);
  for (int x = x0; x < x1; ++x) {
    const Rgb8 c = heat_colour(static_cast<float>(x - x0) / static_cast<float>(bar_w - 1));
    for (int y = bar_top; y < bar_top + bar_h; ++y) img.put(x, y, c);
  }
  // Labels placed greedily from the left; the maximum first, so it is never crowded out.
  const std::vector<double> ticks = tick_values(scale);
  std::vector<std::pair<int, int>> taken;  // label extents [left, right)
  auto place = [&](double v, bool force) {
    const int x = x0 + static_cast<int>(std::lround(scale.position(v) * static_cast<float>(bar_w - 1)));
    const std::string label = tick_label(v);
    const int w = text_width(label, s);
    const int left = std::clamp(x - w / 2, 0, std::max(img.width - w, 0));
    for (const auto& [l, r] : taken) {
      if (!force && left < r + 3 * s && left + w + 3 * s > l) return;
    }
    taken.emplace_back(left, left + w);
    for (int y = bar_top + bar_h; y < bar_top + bar_h + 2 * s; ++y) {
      for (int dx = 0; dx < s; ++dx) img.put(x + dx, y, kInk);
    }
    draw_text(img, left, bar_top + bar_h + 3 * s, label, kInk, s);
  };
  place(ticks.back(), true);
  for (std::size_t i = 0; i + 1 < ticks.size(); ++i) place(ticks[i], false);
}

}  // namespace

Rgb8Image::Rgb8Image(int w, int h, Rgb8 fill)
    : width(w), height(h), pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}

void Rgb8Image::put(int x, int y, Rgb8 c) {
  if (x >= 0 && y >= 0 && x < width && y < height) at(x, y) = c;
}

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

void draw_text(Rgb8Image& image, int x, int y, std::string_view text, Rgb8 colour, int scale) {
  for (const char c : text) {
    if (const char* rows = glyph_rows(c)) {
      for (int gy = 0; gy < 5; ++gy) {
        for (int gx = 0; gx < 3; ++gx) {
          if (rows[gy * 3 + gx] != '#') continue;
          for (int sy = 0; sy < scale; ++sy) {
            for (int sx = 0; sx < scale; ++sx) image.put(x + gx * scale + sx, y + gy * scale + sy, colour);
          }
        }
      }
    }
    x += 4 * scale;
  }
}

int text_width(std::string_view text, int scale) {
  return text.empty() ? 0 : (4 * static_cast<int>(text.size()) - 1) * scale;
}

int legend_height(int scale) { return 32 * scale; }

Rgb8Image render_heatmap(std::span<const std::uint32_t> values, int width, int height, const HeatScale& scale,
                         std::string_view title) {
  if (values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("render_heatmap: values do not match the image size");
  }
  const int s = width >= 2 * kMinWidth ? 2 : 1;
  const int title_room = text_width(title, s) + 12 * s;  // the legend's margin on both sides
  Rgb8Image img(std::max({width, kMinWidth * s, title_room}), height + legend_height(s), kBackground);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) img.at(x, y) = scale.colour(values[static_cast<std::size_t>(y) * width + x]);
  }
  draw_legend(img, height, scale, title, s);
  return img;
}

Rgb8Image render_sample_count_image(std::span<const std::uint32_t> counts, int width, int height, CountScale scale) {
  if (counts.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("render_sample_count_image: counts do not match the image size");
  }
  HeatScale heat;
  heat.logarithmic = scale == CountScale::kLog;
  if (!counts.empty()) {
    const auto [lo, hi] = std::minmax_element(counts.begin(), counts.end());
    heat.max_value = *hi;
    heat.min_value = *lo < *hi ? *lo : 0.0;  // one count everywhere: show it against zero
  }
  return render_heatmap(
      counts, width, height, heat,
      heat.logarithmic ? "primary samples per pixel, log scale" : "primary samples per pixel, linear scale");
}

void write_sample_count_png(std::span<const std::uint32_t> counts, int width, int height, const std::string& path,
                            CountScale scale) {
  write_png(render_sample_count_image(counts, width, height, scale), path);
}

void write_png(const Rgb8Image& image, const std::string& path) {
  // Through the film writer, which encodes linear values to sRGB: decoding each byte to linear
  // first makes the round trip exact (tested), and keeps one PNG writer and its atomic write.
  Film film(image.width, image.height);
  std::array<float, 256> linear{};
  for (int i = 0; i < 256; ++i) linear[i] = srgb_to_linear(static_cast<float>(i) / 255.f);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Rgb8 c = image.at(x, y);
      film.at(x, y) = Color{linear[c.r], linear[c.g], linear[c.b]};
    }
  }
  write_image(film, path);
}

}  // namespace raylab
