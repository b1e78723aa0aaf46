#pragma once
// Test helpers for heat maps and their legends: a PNG read back as 8-bit colours, and whether a
// text drawn by the built-in font appears in a picture as a whole word.

#include <cmath>
#include <string>
#include <string_view>

#include "raylab/io/bitmap_font.h"
#include "raylab/io/image_io.h"
#include "raylab/io/rgb8_image.h"

namespace raylab::test {

/// The ink colour of legends.
inline constexpr Rgb8 kLegendInk{235, 235, 235};

/// The PNG at `path` as 8-bit colours (exact: write_png round-trips).
inline Rgb8Image read_png_rgb8(const std::string& path) {
  const Film film = read_image(path);
  Rgb8Image img(film.width(), film.height());
  auto byte = [](float v) { return static_cast<std::uint8_t>(std::lround(linear_to_srgb(v) * 255.f)); };
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      const Color c = film.at(x, y);
      img.at(x, y) = {byte(c.x), byte(c.y), byte(c.z)};
    }
  }
  return img;
}

/// True when `text`, drawn by draw_text at font scale `s` in kLegendInk, appears in `img` at or
/// below row `top` as a whole word (no ink right before or after it).
inline bool shows_text(const Rgb8Image& img, int top, std::string_view text, int s) {
  const int w = text_width(text, s), h = kGlyphHeight * s;
  Rgb8Image stamp(w, h);
  draw_text(stamp, 0, 0, text, kLegendInk, s);
  for (int y = top; y + h <= img.height; ++y) {
    for (int x = 0; x + w <= img.width; ++x) {
      bool match = true;
      for (int sy = 0; sy < h && match; ++sy) {
        for (int sx = 0; sx < w && match; ++sx) {
          match = (img.at(x + sx, y + sy) == kLegendInk) == (stamp.at(sx, sy) == kLegendInk);
        }
      }
      for (int sy = 0; sy < h && match; ++sy) {
        for (int d = 1; d <= 2 * s && match; ++d) {  // the gap between glyphs and the next glyph's edge
          if (x - d >= 0) match = !(img.at(x - d, y + sy) == kLegendInk);
          if (match && x + w - 1 + d < img.width) match = !(img.at(x + w - 1 + d, y + sy) == kLegendInk);
        }
      }
      if (match) return true;
    }
  }
  return false;
}

}  // namespace raylab::test
