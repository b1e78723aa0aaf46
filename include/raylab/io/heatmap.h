#pragma once
/// \file
/// Traversal-cost heat maps: a value per pixel drawn through a perceptual colour map on a scale
/// shared by several images, with a legend (colour bar, numeric labels, title) drawn in by a
/// tiny built-in bitmap font, so that no font library is needed.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/render/accel_compare.h"

namespace raylab {

/// An 8-bit sRGB colour.
struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  /// Channel-wise equality.
  constexpr bool operator==(const Rgb8&) const = default;
};

/// An 8-bit sRGB image, rows from the top.
struct Rgb8Image {
  int width = 0;
  int height = 0;
  std::vector<Rgb8> pixels;  ///< row-major

  /// A `width` x `height` image filled with `fill`.
  Rgb8Image(int w, int h, Rgb8 fill = {});
  /// Pixel (x, y); no range check.
  Rgb8& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// Pixel (x, y); no range check.
  const Rgb8& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// Sets (x, y) when it lies inside the image; drawing is clipped this way.
  void put(int x, int y, Rgb8 c);
};

/// The colour map (viridis: dark violet through blue and green to yellow, perceptually even and
/// readable in grey and by colour-blind viewers) at `t`, clamped to [0, 1].
Rgb8 heat_colour(float t);

/// A colour scale from 0 to `max_value`, logarithmic (log(1 + v)), so that structures whose
/// costs differ by orders of magnitude stay readable on one scale.
struct HeatScale {
  double max_value = 1.0;  ///< value drawn in the map's last colour (values above are clamped)

  /// Position of `value` on the colour map, in [0, 1].
  float position(double value) const;
  /// The colour of `value`.
  Rgb8 colour(double value) const { return heat_colour(position(value)); }
};

/// Draws `text` with the built-in 3x5-pixel font at (x, y) (top-left), each font pixel a
/// `scale` x `scale` square. Letters are drawn as capitals; characters without a glyph as blanks.
void draw_text(Rgb8Image& image, int x, int y, std::string_view text, Rgb8 colour, int scale);

/// Width in pixels of `text` as draw_text draws it.
int text_width(std::string_view text, int scale);

/// Height of the legend strip under a heat map drawn at font scale `scale`.
int legend_height(int scale);

/// Draws `values` (width x height, row-major) through `scale`, with a legend strip below it:
/// `title`, the colour bar from 0 to the maximum and labelled ticks. The image is widened (with
/// a dark background) when the map is too narrow for the legend.
Rgb8Image render_heatmap(std::span<const std::uint32_t> values, int width, int height, const HeatScale& scale,
                         std::string_view title);

/// Writes `image` as a PNG file, atomically.
void write_png(const Rgb8Image& image, const std::string& path);

/// Writes the heat maps of a comparison into `dir` (created if missing): for each structure
/// that ran and counts its work, `<name>-tests.png` (primitive tests per primary ray) and
/// `<name>-nodes.png` (nodes or cells visited), each kind on one scale shared by all
/// structures. Returns the paths written. Throws InputError when the folder cannot be made.
std::vector<std::string> write_compare_heatmaps(const CompareResult& result, const std::string& dir);

}  // namespace raylab
