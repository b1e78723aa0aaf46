#pragma once
/// \file
/// False-colour maps: a value per pixel drawn through a perceptual colour map on a scale shared
/// by several images. A map is exactly the size of the render it describes, so that it can be
/// laid over the image; its legend (title, colour bar, labelled ticks, drawn with the built-in
/// bitmap font) is a picture of its own, written beside the map as NAME.legend.png.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/io/bitmap_font.h"
#include "raylab/io/rgb8_image.h"

namespace raylab {

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

/// The font scale of legends: each font pixel 2 x 2, so digits are 10 x 14 pixels.
inline constexpr int kLegendFontScale = 2;

/// Height in pixels of every legend (title, bar, tick labels and margins).
int heat_legend_height();

/// The tick values of a legend: the scale's minimum, round values strictly between (1-2-5 steps
/// of each decade on a log scale, about five even round steps on a linear one), its maximum.
std::vector<double> heat_legend_ticks(const HeatScale& scale);

/// A tick value as a legend writes it: the whole number below 10000, then with a K or M suffix.
std::string heat_legend_label(double value);

/// Draws `values` (width x height, row-major) through `scale`: an image of exactly width x
/// height, pixel (x, y) the colour of value (x, y). Throws std::invalid_argument when `values`
/// does not have width x height entries.
Rgb8Image render_heatmap(std::span<const std::uint32_t> values, int width, int height, const HeatScale& scale);

/// The legend of maps drawn on `scale`: `title`, the colour bar from the scale's minimum to its
/// maximum, and labelled ticks. At least `width` wide (the map's width, so that it can be set
/// under the map), wider when the title or the labels need it.
Rgb8Image render_heat_legend(const HeatScale& scale, std::string_view title, int width);

/// Where the legend of the map at `map_path` goes: "a/b.png" -> "a/b.legend.png" (any other
/// name gets ".legend.png" appended).
std::string heat_legend_path(const std::string& map_path);

/// Writes render_heatmap(...) to `path` and its legend to heat_legend_path(path), both as PNG
/// and atomically; when the legend cannot be written the map is removed too. Returns the two
/// paths. Throws InputError when a file cannot be written.
std::vector<std::string> write_heatmap_png(std::span<const std::uint32_t> values, int width, int height,
                                           const HeatScale& scale, std::string_view title, const std::string& path);

/// How a sample-count image spaces its colours.
enum class CountScale {
  kLinear,  ///< even steps in the count
  kLog,     ///< even steps in log(1 + count - min): a few refined pixels stand out among many
};

/// The scale of a per-pixel primary-sample count: from the smallest count (dark) to the largest
/// (yellow); a uniform count is drawn on the range 0..count (all one colour).
HeatScale sample_count_scale(std::span<const std::uint32_t> counts, CountScale scale = CountScale::kLog);

/// The legend title of a sample-count map: "primary samples per pixel" plus the scale.
std::string_view sample_count_title(CountScale scale);

/// The false-colour picture of a per-pixel primary-sample count (`counts`: width x height,
/// row-major, e.g. RenderResult::samples_per_pixel) on sample_count_scale: exactly width x
/// height. Throws std::invalid_argument when `counts` does not have width x height values.
Rgb8Image render_sample_count_image(std::span<const std::uint32_t> counts, int width, int height,
                                    CountScale scale = CountScale::kLog);

/// Writes render_sample_count_image(...) to `path` and its legend (whose labels give the
/// range: the smallest and largest counts and round values between) beside it, as
/// write_heatmap_png does. Returns the two paths.
std::vector<std::string> write_sample_count_png(std::span<const std::uint32_t> counts, int width, int height,
                                                const std::string& path, CountScale scale = CountScale::kLog);

}  // namespace raylab
