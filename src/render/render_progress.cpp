#include "raylab/render/render_progress.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "raylab/core/error.h"
#include "raylab/core/hash64.h"
#include "render_workers.h"

namespace raylab {
namespace {

// The rectangle tile `t` (numbered as TileGrid numbers the render's tiles) and its margin cover,
// clipped to the image.
TileSums tile_area(int t, int width, int height, int tile_size, int margin) {
  const detail::PixelRect r = detail::TileGrid(width, height, tile_size).rect(t);
  TileSums s;
  s.x0 = std::max(0, r.x0 - margin);
  s.y0 = std::max(0, r.y0 - margin);
  s.x1 = std::min(width, r.x1 + margin);
  s.y1 = std::min(height, r.y1 + margin);
  return s;
}

}  // namespace

std::vector<int> scattered_tile_order(std::vector<int> tiles) {
  auto key = [](int t) {
    Hash64 h;
    h.word(static_cast<std::uint64_t>(t));
    return h.value();
  };
  std::sort(tiles.begin(), tiles.end(), [&](int a, int b) { return key(a) < key(b); });
  return tiles;
}

std::vector<int> RenderProgress::unfinished_tiles() const {
  std::vector<int> out;
  if (complete()) return out;
  for (int t = 0; t < tile_count(); ++t) {
    if (tile_done[t] == 0) out.push_back(t);
  }
  return out;
}

std::size_t RenderProgress::memory_bytes() const {
  std::size_t bytes = tile_done.size();
  for (const TileSums& s : tiles) bytes += s.sum.size() * sizeof(Color) + s.weight.size() * sizeof(float);
  return bytes;
}

std::vector<std::uint32_t> samples_per_pixel(const RenderProgress& progress) {
  std::vector<std::uint32_t> samples(std::size_t(progress.width) * std::size_t(progress.height));
  const detail::TileGrid grid(progress.width, progress.height, progress.tile_size);
  for (int t = 0; t < grid.count(); ++t) {
    const detail::PixelRect r = grid.rect(t);
    const auto n = static_cast<std::uint32_t>(progress.samples_in_tile(t));
    for (int y = r.y0; y < r.y1; ++y) {
      std::fill_n(samples.begin() + static_cast<std::ptrdiff_t>(std::size_t(y) * progress.width + r.x0), r.x1 - r.x0,
                  n);
    }
  }
  return samples;
}

std::int64_t progress_tile_count(int width, int height, int tile_size) {
  // As TileGrid::count, without its int product (a damaged checkpoint may claim 2^30 tiles).
  auto across = [&](int pixels) { return std::int64_t(pixels + tile_size - 1) / tile_size; };
  return across(width) * across(height);
}

std::size_t progress_pixels(int width, int height, int tile_size, int margin) {
  std::size_t pixels = 0;
  const std::int64_t count = progress_tile_count(width, height, tile_size);
  for (std::int64_t t = 0; t < count; ++t) {
    const TileSums s = tile_area(static_cast<int>(t), width, height, tile_size, margin);
    pixels += std::size_t(s.x1 - s.x0) * (s.y1 - s.y0);
  }
  return pixels;
}

std::size_t progress_memory_bytes(int width, int height, int tile_size, int margin) {
  if (width <= 0 || height <= 0 || tile_size <= 0) return 0;
  const auto count = static_cast<std::size_t>(progress_tile_count(width, height, tile_size));
  return progress_pixels(width, height, tile_size, margin) * (sizeof(Color) + (margin > 0 ? sizeof(float) : 0)) +
         count * (sizeof(TileSums) + 1);
}

RenderProgress start_progress(int width, int height, int tile_size, int spp, int passes, int margin) {
  if (width <= 0 || height <= 0) throw UsageError("the image size must be positive");
  if (tile_size <= 0) throw UsageError("the tile size must be positive");
  if (spp <= 0) throw UsageError("the samples per pixel must be positive");
  if (passes < 1 || passes > spp) {
    throw UsageError("--passes " + std::to_string(passes) + " must be between 1 and the samples per pixel (" +
                     std::to_string(spp) + ")");
  }
  if (margin < 0) throw UsageError("the filter margin must not be negative");
  RenderProgress p{
      .width = width, .height = height, .tile_size = tile_size, .spp = spp, .passes = passes, .margin = margin};
  const int count = detail::TileGrid(width, height, tile_size).count();
  p.tile_done.assign(static_cast<std::size_t>(count), 0);
  p.tiles.reserve(static_cast<std::size_t>(count));
  for (int t = 0; t < count; ++t) {
    TileSums s = tile_area(t, width, height, tile_size, margin);
    const std::size_t pixels = std::size_t(s.x1 - s.x0) * (s.y1 - s.y0);
    s.sum.assign(pixels, Color{0.f});
    if (margin > 0) s.weight.assign(pixels, 0.f);
    p.tiles.push_back(std::move(s));
  }
  return p;
}

void develop(const RenderProgress& progress, Film& film) {
  if (progress.margin == 0) {
    // The pixel box: every pixel's samples are its own tile's; the plain average, as the sum
    // times the reciprocal of the count (the same float operations as a render in one go).
    for (int t = 0; t < progress.tile_count(); ++t) {
      const TileSums& s = progress.tiles[t];
      const int n = progress.samples_in_tile(t);
      const float inv = n > 0 ? 1.f / static_cast<float>(n) : 0.f;
      for (int y = s.y0; y < s.y1; ++y) {
        for (int x = s.x0; x < s.x1; ++x) film.at(x, y) = n > 0 ? s.sum[s.index(x, y)] * inv : Color{0.f};
      }
    }
    return;
  }
  // Wider filters: the tiles' sums and weights added up in tile order, whatever order the tiles
  // were rendered in, so the image does not depend on scheduling.
  const std::size_t pixels = std::size_t(film.width()) * film.height();
  std::vector<Color> sum(pixels, Color{0.f});
  std::vector<float> weight(pixels, 0.f);
  for (int t = 0; t < progress.tile_count(); ++t) {
    if (progress.samples_in_tile(t) == 0) continue;
    const TileSums& s = progress.tiles[t];
    for (int y = s.y0; y < s.y1; ++y) {
      for (int x = s.x0; x < s.x1; ++x) {
        const std::size_t dst = std::size_t(y) * film.width() + x;
        sum[dst] += s.sum[s.index(x, y)];
        weight[dst] += s.weight[s.index(x, y)];
      }
    }
  }
  for (int y = 0; y < film.height(); ++y) {
    for (int x = 0; x < film.width(); ++x) {
      const std::size_t i = std::size_t(y) * film.width() + x;
      // Every pixel centre has samples within any radius >= 0.5, so the weight is positive
      // except where a negative lobe (Mitchell) cancels it, or no tile near it has samples yet:
      // such a pixel is left black.
      film.at(x, y) = std::abs(weight[i]) > 1e-12f ? sum[i] / weight[i] : Color{0.f};
    }
  }
}

}  // namespace raylab
