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

/// A colour scale from `min_value` to `max_value`, logarithmic by default (log(1 + v - min)),
/// so that structures whose costs differ by orders of magnitude stay readable on one scale.
struct HeatScale {
  double max_value = 1.0;   ///< value drawn in the map's last colour (values above are clamped)
  bool logarithmic = true;  ///< log(1 + v - min) spacing; false: linear in v
  double min_value = 0.0;   ///< value drawn in the map's first colour (values below are clamped)

  /// Position of `value` on the colour map, in [0, 1]; 0 when the range is empty.
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
/// `title`, the colour bar from the scale's minimum to its maximum and labelled ticks. The image
/// is widened (with a dark background) when the map is too narrow for the legend or its title.
Rgb8Image render_heatmap(std::span<const std::uint32_t> values, int width, int height, const HeatScale& scale,
                         std::string_view title);

/// How a sample-count image spaces its colours.
enum class CountScale {
  kLinear,  ///< even steps in the count
  kLog,     ///< even steps in log(1 + count - min): a few refined pixels stand out among many
};

/// The false-colour picture of a per-pixel primary-sample count (`counts`: width x height,
/// row-major, e.g. RenderResult::samples_per_pixel): viridis from the smallest count (dark) to
/// the largest (yellow) on `scale`, with the legend of render_heatmap titled "primary samples
/// per pixel" plus the scale, whose labels give the range (the smallest and largest counts and
/// round values between). A uniform count is drawn on the range 0..count (all one colour).
/// Throws std::invalid_argument when `counts` does not have width x height values.
Rgb8Image render_sample_count_image(std::span<const std::uint32_t> counts, int width, int height,
                                    CountScale scale = CountScale::kLog);

/// Writes render_sample_count_image(...) to `path` as a PNG, atomically (InputError when the
/// file cannot be written).
void write_sample_count_png(std::span<const std::uint32_t> counts, int width, int height, const std::string& path,
                            CountScale scale = CountScale::kLog);

/// Writes `image` as a PNG file, atomically.
void write_png(const Rgb8Image& image, const std::string& path);

}  // namespace raylab
