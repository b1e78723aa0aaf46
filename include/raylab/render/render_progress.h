#pragma once
/// \file
/// How far a render of the uniform samplers has come, as plain data: the weighted sums of the
/// samples taken in every tile so far, which tiles have finished the pass under way, and how many
/// passes are done. A render can stop after any tile and go on later from this state (a
/// checkpoint file holds it), and the image of the samples so far can be developed from it at any
/// moment. Continuing from a saved state gives the same bits as never stopping: the sums are the
/// same floats, added to in the same order.

#include <cstdint>
#include <vector>

#include "raylab/core/vec3.h"
#include "raylab/render/film.h"

namespace raylab {

/// The samples that fell on a rectangle of pixels: one tile, and the margin around it that a
/// filter wider than a pixel reaches into (clipped to the image).
struct TileSums {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< the pixels covered: [x0, x1) x [y0, y1)
  std::vector<Color> sum;              ///< filter-weighted sum of the samples per pixel, row-major
  /// Sum of the filter weights per pixel; empty with the pixel box filter, where every sample
  /// weighs 1 and stays in its pixel (the weight is then the tile's sample count).
  std::vector<float> weight;

  /// Index of pixel (x, y), which must lie in the rectangle, into `sum` and `weight`.
  std::size_t index(int x, int y) const { return std::size_t(y - y0) * (x1 - x0) + (x - x0); }
};

/// The resumable state of a uniform-sampler render (see the file comment).
struct RenderProgress {
  int width = 0;                          ///< image width in pixels
  int height = 0;                         ///< image height in pixels
  int tile_size = 0;                      ///< side of the square tiles, numbered row-major from the top-left
  int spp = 0;                            ///< samples per pixel when every pass is done
  int passes = 1;                         ///< the samples are taken in this many passes over the image
  int margin = 0;                         ///< pixels a tile's samples reach beyond it (0 with the pixel box filter)
  int passes_done = 0;                    ///< passes finished; the pass under way is this one
  std::vector<std::uint8_t> tile_done{};  ///< per tile: 1 when it has finished the pass under way
  std::vector<TileSums> tiles{};          ///< per tile, in tile order

  /// Whether every pass is done.
  bool complete() const { return passes_done >= passes; }
  /// Number of tiles.
  int tile_count() const { return static_cast<int>(tiles.size()); }
  /// Samples per pixel taken by the passes before `pass`: pass p takes samples
  /// [samples_before(p), samples_before(p + 1)) of every pixel.
  int samples_before(int pass) const { return static_cast<int>(static_cast<std::int64_t>(spp) * pass / passes); }
  /// Samples per pixel tile `t` holds now.
  int samples_in_tile(int t) const { return samples_before(passes_done + (complete() ? 0 : tile_done[t])); }
  /// The tiles that have not finished the pass under way (none when complete).
  std::vector<int> unfinished_tiles() const;
  /// Bytes the state holds (its sums and weights).
  std::size_t memory_bytes() const;
};

/// The state of a render not yet started: `width` x `height` pixels in tiles of `tile_size`,
/// `spp` samples per pixel in `passes` passes (1 to spp), tiles reaching `margin` pixels beyond
/// themselves (0: the pixel box filter, no weights kept). Throws UsageError on sizes out of range.
RenderProgress start_progress(int width, int height, int tile_size, int spp, int passes, int margin);

/// `tiles` in a scattered order, the same on every run (sorted by a hash of the tile number): a
/// render that starts its tiles in this order has done a fair sample of the image's work at any
/// moment, so the share of tiles done is the share of the time taken and the ETA holds (row by
/// row, a sky's cheap rows come first and the ETA is too short by half; docs/performance.md).
/// Which tile is rendered when changes nothing in the image.
std::vector<int> scattered_tile_order(std::vector<int> tiles);

/// Bytes that start_progress would allocate for these sizes, without allocating them.
std::size_t progress_memory_bytes(int width, int height, int tile_size, int margin);

/// Number of tiles of side `tile_size` over a `width` x `height` image (all positive).
std::int64_t progress_tile_count(int width, int height, int tile_size);

/// Pixels summed over the rectangles of all tiles (each tile with its margin, clipped), i.e. the
/// number of sums start_progress keeps.
std::size_t progress_pixels(int width, int height, int tile_size, int margin);

/// Samples each pixel holds now (row-major, width x height): what render() reports as
/// RenderResult::samples_per_pixel.
std::vector<std::uint32_t> samples_per_pixel(const RenderProgress& progress);

/// Develops the image of the samples so far into `film` (which must be `progress`'s size): with
/// the pixel box, each pixel's sum over its tile's sample count; with wider filters, the tiles'
/// sums and weights added up in tile order, then divided. Pixels no sample has reached are black.
void develop(const RenderProgress& progress, Film& film);

}  // namespace raylab
