#include "tile_samples.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "packet_tracing.h"
#include "raylab/core/error.h"

namespace raylab::detail {
namespace {

// Adds sample colour `c`, taken at image position (x, y), to the pixels of `sums` whose centre
// lies strictly within the filter's radius of it, weighted by the filter.
void add_filtered(TileSums& sums, const Filter& filter, float x, float y, Color c) {
  const float r = filter.radius();
  // Pixels whose centre lies strictly within the radius: |px + 0.5 - x| < r.
  const int px0 = std::max(sums.x0, static_cast<int>(std::floor(x - 0.5f - r)) + 1);
  const int px1 = std::min(sums.x1 - 1, static_cast<int>(std::ceil(x - 0.5f + r)) - 1);
  const int py0 = std::max(sums.y0, static_cast<int>(std::floor(y - 0.5f - r)) + 1);
  const int py1 = std::min(sums.y1 - 1, static_cast<int>(std::ceil(y - 0.5f + r)) - 1);
  for (int py = py0; py <= py1; ++py) {
    const float wy = filter.evaluate_1d(static_cast<float>(py) + 0.5f - y);
    if (wy == 0.f) continue;
    for (int px = px0; px <= px1; ++px) {
      const float w = wy * filter.evaluate_1d(static_cast<float>(px) + 0.5f - x);
      const std::size_t i = sums.index(px, py);
      sums.sum[i] += c * w;
      sums.weight[i] += w;
    }
  }
}

}  // namespace

bool is_pixel_box(const Filter& f) { return f.kind() == FilterKind::kBox && f.radius() == 0.5f; }

int filter_margin(const Filter& f) { return is_pixel_box(f) ? 0 : static_cast<int>(std::ceil(f.radius() - 0.5f)); }

void render_tile_samples(const TraceContext& ctx, const Camera& camera, const PixelSampler& sampler,
                         const SampleDimensions& dims, const Filter& filter, bool packets, const PixelRect& rect,
                         int first, int end, TileSums& sums) {
  const bool pixel_box = is_pixel_box(filter);
  // Sample i of pixel (px, py) has colour colour_of(i, x, y), at image position (x, y).
  auto add_pixel = [&](int px, int py, auto&& colour_of) {
    Color* own = pixel_box ? &sums.sum[sums.index(px, py)] : nullptr;
    for (int i = first; i < end; ++i) {
      // Every random choice of this sample comes from (pixel, index, seed): no shared state.
      const Sample2 u = sampler.sample(px, py, i);
      const float x = static_cast<float>(px) + u.x;
      const float y = static_cast<float>(py) + u.y;
      const Color c = colour_of(i, x, y);
      if (own) {
        *own += c;  // the box filter over the pixel: a plain sum, divided by the count at the end
      } else {
        add_filtered(sums, filter, x, y, c);
      }
    }
  };
  if (packets && ctx.integrator->traces_packets()) {
    // The same samples, seeds and sums in the same order; only the tracing is grouped.
    detail::TilePacketTracer tracer(ctx, camera, sampler, first, end);
    tracer.for_each_pixel(rect, [&](int px, int py, std::span<const Color> colours) {
      add_pixel(px, py, [&](int i, float, float) { return colours[static_cast<std::size_t>(i - first)]; });
    });
    return;
  }
  for (int py = rect.y0; py < rect.y1; ++py) {
    for (int px = rect.x0; px < rect.x1; ++px) {
      add_pixel(px, py, [&](int i, float x, float y) {
        SampleSource samples(sample_path_seed(sampler.seed(), px, py, i), dims, px, py, i);
        return detail::trace_image_position(ctx, camera, x, y, samples);
      });
    }
  }
}

void check_resumable(const RenderProgress& p, int width, int height, int tile_size, int spp, int margin) {
  if (p.width == width && p.height == height && p.tile_size == tile_size && p.spp == spp && p.margin == margin &&
      p.passes >= 1 && static_cast<int>(p.tiles.size()) == static_cast<int>(p.tile_done.size())) {
    return;
  }
  throw UsageError("the saved render state is for a " + std::to_string(p.width) + "x" + std::to_string(p.height) +
                   " image in tiles of " + std::to_string(p.tile_size) + " at " + std::to_string(p.spp) +
                   " spp (filter margin " + std::to_string(p.margin) + "), not for this " + std::to_string(width) +
                   "x" + std::to_string(height) + " render in tiles of " + std::to_string(tile_size) + " at " +
                   std::to_string(spp) + " spp (filter margin " + std::to_string(margin) + ")");
}

}  // namespace raylab::detail
