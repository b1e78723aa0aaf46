#pragma once
// Internal to the render module: the parallel machinery every pixel-loop policy shares (uniform
// samplers, adaptive-corners, adaptive): a thread arena of the requested size, one statistics
// record per thread, and the tile grid.

#include <tbb/enumerable_thread_specific.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_for_each.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/core/stopwatch.h"
#include "raylab/render/camera.h"
#include "raylab/render/integrator.h"
#include "raylab/render/renderer.h"

namespace raylab::detail {

/// A rectangle of pixels [x0, x1) x [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// The image cut into square tiles, numbered row-major from the top-left.
class TileGrid {
 public:
  /// Tiles of `tile` pixels (at least 1) over a `width` x `height` image.
  TileGrid(int width, int height, int tile)
      : m_width(width),
        m_height(height),
        m_tile(std::max(1, tile)),
        m_tiles_x((width + m_tile - 1) / m_tile),
        m_tiles_y((height + m_tile - 1) / m_tile) {}

  /// Number of tiles.
  int count() const { return m_tiles_x * m_tiles_y; }
  /// Pixels of tile `t`.
  PixelRect rect(int t) const {
    const int x0 = (t % m_tiles_x) * m_tile;
    const int y0 = (t / m_tiles_x) * m_tile;
    return {x0, y0, std::min(x0 + m_tile, m_width), std::min(y0 + m_tile, m_height)};
  }
  /// Tile side in pixels.
  int tile() const { return m_tile; }

 private:
  int m_width, m_height, m_tile, m_tiles_x, m_tiles_y;
};

/// Runs work items in parallel, each with a TraceContext whose statistics belong to the worker
/// thread, so no counter is shared, and whose integrator is the scene's. Results must not depend
/// on which thread runs an item.
class RenderWorkers {
 public:
  /// Workers for `scene` traced through `accel` with the integrator its settings name, as many
  /// threads as `options` asks. Throws UsageError for an unknown integrator.
  RenderWorkers(const Scene& scene, const Accelerator& accel, const RenderOptions& options)
      : m_scene(scene),
        m_accel(accel),
        m_integrator(make_integrator(scene.settings.integrator, scene)),
        m_count(options.count_traversal),
        m_arena(render_thread_count(options)) {}

  /// Calls `fn(index, ctx)` for every index in [0, count), in parallel, one index per task.
  template <class Fn>
  void for_each(int count, Fn&& fn) {
    m_arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(0, count, 1), [&](const tbb::blocked_range<int>& range) {
        const TraceContext ctx{m_scene, m_accel, m_stats.local(), m_count, ShadowFacing::kViewer, m_integrator.get()};
        for (int i = range.begin(); i != range.end(); ++i) fn(i, ctx);
      });
    });
  }

  /// Calls `fn(item, ctx, add)` for every item of `items` and for every item that a call passes
  /// to `add(item)`, in parallel with work stealing: for work that discovers more work. Items
  /// travel in batches of `batch` so that the task overhead stays small next to the work.
  template <class Fn>
  void for_each_growing(const std::vector<int>& items, int batch, Fn&& fn) {
    std::vector<std::vector<int>> batches;
    for (std::size_t i = 0; i < items.size(); i += static_cast<std::size_t>(batch)) {
      batches.emplace_back(items.begin() + static_cast<std::ptrdiff_t>(i),
                           items.begin() + static_cast<std::ptrdiff_t>(std::min(items.size(), i + batch)));
    }
    m_arena.execute([&] {
      tbb::parallel_for_each(
          batches.begin(), batches.end(), [&](const std::vector<int>& work, tbb::feeder<std::vector<int>>& feeder) {
            const TraceContext ctx{m_scene,           m_accel, m_stats.local(), m_count, ShadowFacing::kViewer,
                                   m_integrator.get()};
            std::vector<int> found;
            auto add = [&](int more) {
              found.push_back(more);
              if (found.size() >= static_cast<std::size_t>(batch)) {
                feeder.add(std::move(found));
                found.clear();
              }
            };
            // Breadth first within the batch: what it finds is handed back
            // to the pool, where idle threads can take it.
            for (int item : work) fn(item, ctx, add);
            if (!found.empty()) feeder.add(std::move(found));
          });
    });
  }

  /// The statistics of every thread, summed.
  RenderStats merged_stats() {
    RenderStats total;
    for (const RenderStats& s : m_stats) total += s;
    return total;
  }

 private:
  const Scene& m_scene;
  const Accelerator& m_accel;
  std::unique_ptr<Integrator> m_integrator;
  bool m_count;
  tbb::task_arena m_arena;
  tbb::enumerable_thread_specific<RenderStats> m_stats;
};

/// What a pixel loop that started at `start` reports: its wall-clock time, the statistics of
/// every worker, and the samples that went into each pixel.
inline RenderResult finish_render(RenderWorkers& workers, std::chrono::steady_clock::time_point start,
                                  std::vector<std::uint32_t> samples_per_pixel) {
  RenderResult result;
  result.seconds = seconds_since(start);
  result.stats = workers.merged_stats();
  result.samples_per_pixel = std::move(samples_per_pixel);
  return result;
}

/// A sample's radiance `c` as it goes into the image: black when some component is NaN or
/// infinite (counted in ctx.stats.nonfinite_samples), else `c` itself.
inline Color finite_radiance(const TraceContext& ctx, Color c) {
  if (std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) return c;
  ++ctx.stats.nonfinite_samples;
  return Color{0.f};
}

/// The radiance of the primary ray through image position (x, y), computed by the context's
/// integrator with every random choice along it drawn from `samples` (NaN or infinite radiance
/// counted and replaced by black); `feature` (optional) receives what the ray hit first.
inline Color trace_image_position(const TraceContext& ctx, const Camera& camera, float x, float y,
                                  SampleSource& samples, PrimaryFeature* feature = nullptr) {
  return finite_radiance(ctx, ctx.integrator->radiance(ctx, camera.generate(x, y), samples, feature));
}

/// trace_image_position with independent random numbers from `path_seed` (the adaptive loops,
/// whose samples are not addressed by an index).
inline Color trace_image_position(const TraceContext& ctx, const Camera& camera, float x, float y,
                                  std::uint64_t path_seed, PrimaryFeature* feature = nullptr) {
  SampleSource samples(path_seed);
  return trace_image_position(ctx, camera, x, y, samples, feature);
}

}  // namespace raylab::detail
