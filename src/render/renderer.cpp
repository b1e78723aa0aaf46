#include "raylab/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <span>

#include "packet_tracing.h"
#include "raylab/core/error.h"
#include "raylab/render/adaptive.h"
#include "raylab/render/camera.h"
#include "raylab/sampling/filter.h"
#include "raylab/sampling/pixel_sampler.h"
#include "render_workers.h"

namespace raylab {
namespace {

using detail::PixelRect;
using detail::RenderWorkers;
using detail::TileGrid;

// The box filter of half-width 0.5 is the plain per-pixel average: no sample leaves its pixel.
bool is_pixel_box(const Filter& f) { return f.kind() == FilterKind::kBox && f.radius() == 0.5f; }

// Weighted sums of one tile and the margin its samples reach into (filters wider than a pixel).
struct TileAccumulator {
  PixelRect area;  // pixels covered, margin included, clipped to the image
  std::vector<Color> sum;
  std::vector<float> weight;

  explicit TileAccumulator(PixelRect a)
      : area(a), sum(std::size_t(a.x1 - a.x0) * (a.y1 - a.y0)), weight(sum.size(), 0.f) {}

  void add(const Filter& filter, float x, float y, Color c) {
    const float r = filter.radius();
    // Pixels whose centre lies strictly within the radius: |px + 0.5 - x| < r.
    const int px0 = std::max(area.x0, static_cast<int>(std::floor(x - 0.5f - r)) + 1);
    const int px1 = std::min(area.x1 - 1, static_cast<int>(std::ceil(x - 0.5f + r)) - 1);
    const int py0 = std::max(area.y0, static_cast<int>(std::floor(y - 0.5f - r)) + 1);
    const int py1 = std::min(area.y1 - 1, static_cast<int>(std::ceil(y - 0.5f + r)) - 1);
    for (int py = py0; py <= py1; ++py) {
      const float wy = filter.evaluate_1d(static_cast<float>(py) + 0.5f - y);
      if (wy == 0.f) continue;
      for (int px = px0; px <= px1; ++px) {
        const float w = wy * filter.evaluate_1d(static_cast<float>(px) + 0.5f - x);
        const std::size_t i = std::size_t(py - area.y0) * (area.x1 - area.x0) + (px - area.x0);
        sum[i] += c * w;
        weight[i] += w;
      }
    }
  }
};

RenderResult render_uniform(const Scene& scene, const Accelerator& accel, Film& film, const RenderOptions& options,
                            const PixelSampler& sampler, const Filter& filter) {
  const Camera camera(scene.camera, film.width(), film.height());
  const TileGrid grid(film.width(), film.height(), options.tile_size);
  const int spp = sampler.spp();
  const float inv_spp = 1.f / static_cast<float>(spp);
  const bool pixel_box = is_pixel_box(filter);
  // Wider filters: each tile accumulates into its own buffer (tile plus margin); the buffers are
  // merged afterwards in tile order, so the sums (and the image) do not depend on scheduling.
  const int margin = pixel_box ? 0 : static_cast<int>(std::ceil(filter.radius() - 0.5f));
  std::vector<std::unique_ptr<TileAccumulator>> tiles(pixel_box ? 0 : grid.count());

  RenderWorkers workers(scene, accel, options);
  std::atomic<int> tiles_done{0};
  const auto start = std::chrono::steady_clock::now();
  workers.for_each(grid.count(), [&](int t, const TraceContext& ctx) {
    const PixelRect r = grid.rect(t);
    TileAccumulator* acc = nullptr;
    if (!pixel_box) {
      tiles[t] = std::make_unique<TileAccumulator>(PixelRect{std::max(0, r.x0 - margin), std::max(0, r.y0 - margin),
                                                             std::min(film.width(), r.x1 + margin),
                                                             std::min(film.height(), r.y1 + margin)});
      acc = tiles[t].get();
    }
    // Sample i of pixel (px, py) has colour colour_of(i, x, y), at image position (x, y).
    auto add_pixel = [&](int px, int py, auto&& colour_of) {
      Color sum{0.f};
      for (int i = 0; i < spp; ++i) {
        // Every random choice of this sample comes from (pixel, index, seed): no shared state.
        const Sample2 u = sampler.sample(px, py, i);
        const float x = static_cast<float>(px) + u.x;
        const float y = static_cast<float>(py) + u.y;
        const Color c = colour_of(i, x, y);
        if (acc) {
          acc->add(filter, x, y, c);
        } else {
          sum += c;
        }
      }
      if (!acc) film.at(px, py) = sum * inv_spp;  // box filter over the pixel: the plain average
    };
    if (options.packets) {
      // The same samples, seeds and sums in the same order; only the tracing is grouped.
      detail::TilePacketTracer tracer(ctx, camera, sampler);
      tracer.for_each_pixel(r, [&](int px, int py, std::span<const Color> colours) {
        add_pixel(px, py, [&](int i, float, float) { return colours[static_cast<std::size_t>(i)]; });
      });
    } else {
      for (int py = r.y0; py < r.y1; ++py) {
        for (int px = r.x0; px < r.x1; ++px) {
          add_pixel(px, py, [&](int i, float x, float y) {
            return detail::trace_image_position(ctx, camera, x, y, sample_path_seed(sampler.seed(), px, py, i));
          });
        }
      }
    }
    const int done = tiles_done.fetch_add(1, std::memory_order_relaxed) + 1;
    if (options.on_progress) options.on_progress(done, grid.count());
  });

  if (!pixel_box) {
    std::vector<Color> sum(std::size_t(film.width()) * film.height());
    std::vector<float> weight(sum.size(), 0.f);
    for (const auto& tile : tiles) {
      const PixelRect& a = tile->area;
      for (int y = a.y0; y < a.y1; ++y) {
        for (int x = a.x0; x < a.x1; ++x) {
          const std::size_t src = std::size_t(y - a.y0) * (a.x1 - a.x0) + (x - a.x0);
          const std::size_t dst = std::size_t(y) * film.width() + x;
          sum[dst] += tile->sum[src];
          weight[dst] += tile->weight[src];
        }
      }
    }
    for (int y = 0; y < film.height(); ++y) {
      for (int x = 0; x < film.width(); ++x) {
        const std::size_t i = std::size_t(y) * film.width() + x;
        // Every pixel centre has samples within any radius >= 0.5, so the weight is positive
        // except where a negative lobe (Mitchell) cancels it: leave such a pixel black.
        film.at(x, y) = std::abs(weight[i]) > 1e-12f ? sum[i] / weight[i] : Color{0.f};
      }
    }
  }

  return detail::finish_render(
      workers, start,
      std::vector<std::uint32_t>(std::size_t(film.width()) * film.height(), static_cast<std::uint32_t>(spp)));
}

}  // namespace

std::string resolve_sampler_name(const RenderSettings& settings) {
  if (settings.sampler == "auto") return settings.spp <= 1 ? "center" : "jittered";
  return settings.sampler;
}

std::vector<std::string_view> render_sampler_names() {
  std::vector<std::string_view> names(pixel_sampler_names().begin(), pixel_sampler_names().end());
  names.insert(names.end(), adaptive_sampler_names().begin(), adaptive_sampler_names().end());
  return names;
}

void check_sampling_settings(const RenderSettings& s) {
  const std::string name = resolve_sampler_name(s);
  const std::vector<std::string_view> names = render_sampler_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string valid = "auto";
    for (std::string_view n : names) valid += ", " + std::string(n);
    throw UsageError("unknown sampler '" + name + "' (valid: " + valid + ")");
  }
  const Filter filter = make_filter(s.filter, s.filter_radius);
  if (is_adaptive_sampler(name) && !is_pixel_box(filter)) {
    throw UsageError("the adaptive samplers weight their samples by area within the pixel (a box filter); filter '" +
                     s.filter + "' applies to the uniform samplers");
  }
}

RenderResult render(const Scene& scene, const Accelerator& accel, Film& film, const RenderOptions& options) {
  const RenderSettings& s = scene.settings;
  check_sampling_settings(s);
  const std::string name = resolve_sampler_name(s);
  const Filter filter = make_filter(s.filter, s.filter_radius);
  RenderResult result;
  if (is_adaptive_sampler(name)) {
    const AdaptiveParams params = adaptive_params(name, s);
    result = name == "adaptive" ? render_adaptive(scene, accel, film, options, params)
                                : render_adaptive_corners(scene, accel, film, options, params);
  } else {
    const std::string notice = spp_rounding_notice(name, s.spp);
    const std::unique_ptr<PixelSampler> sampler = make_pixel_sampler(name, s.spp, s.seed);
    result = render_uniform(scene, accel, film, options, *sampler, filter);
    if (!notice.empty()) result.notices.push_back(notice);
  }
  return result;
}

}  // namespace raylab
