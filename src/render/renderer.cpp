#include "raylab/render/renderer.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>

#include "raylab/render/camera.h"
#include "raylab/render/whitted.h"
#include "raylab/sampling/jittered.h"

namespace raylab {

RenderResult render(const Scene& scene, const Accelerator& accel, Film& film, const RenderOptions& options) {
  const RenderSettings& s = scene.settings;
  const Camera camera(scene.camera, film.width(), film.height());
  const JitteredSampler sampler(s.spp, s.seed);
  const int tile = std::max(1, options.tile_size);
  const int tiles_x = (film.width() + tile - 1) / tile;
  const int tiles_y = (film.height() + tile - 1) / tile;
  const int tile_count = tiles_x * tiles_y;
  const float inv_spp = 1.f / static_cast<float>(sampler.spp());

  tbb::enumerable_thread_specific<RenderStats> thread_stats;
  std::atomic<int> tiles_done{0};
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);

  const auto start = std::chrono::steady_clock::now();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& range) {
      RenderStats& stats = thread_stats.local();
      const TraceContext ctx{scene, accel, stats, options.count_traversal};
      for (int t = range.begin(); t != range.end(); ++t) {
        const int x0 = (t % tiles_x) * tile;
        const int y0 = (t / tiles_x) * tile;
        const int x1 = std::min(x0 + tile, film.width());
        const int y1 = std::min(y0 + tile, film.height());
        for (int py = y0; py < y1; ++py) {
          for (int px = x0; px < x1; ++px) {
            Color sum{0.f};
            for (int i = 0; i < sampler.spp(); ++i) {
              // Every random choice of this sample comes from (pixel, index, seed): no shared state.
              const Sample2 u = sampler.pixel_sample(px, py, i);
              Pcg32 rng(sampler.path_seed(px, py, i));
              const Ray ray = camera.generate(static_cast<float>(px) + u.x, static_cast<float>(py) + u.y);
              sum += WhittedIntegrator::trace(ctx, ray, 1, RayKind::kPrimary, rng);
            }
            film.at(px, py) = sum * inv_spp;  // box filter over the pixel: the plain average
          }
        }
        const int done = tiles_done.fetch_add(1, std::memory_order_relaxed) + 1;
        if (options.on_progress) options.on_progress(done, tile_count);
      }
    });
  });

  RenderResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const RenderStats& st : thread_stats) result.stats += st;
  return result;
}

}  // namespace raylab
