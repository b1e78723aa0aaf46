#include "raylab/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <span>
#include <string>

#include "packet_tracing.h"
#include "raylab/core/error.h"
#include "raylab/core/thread_count.h"
#include "raylab/render/adaptive.h"
#include "raylab/render/camera.h"
#include "raylab/render/integrator.h"
#include "raylab/sampling/filter.h"
#include "raylab/sampling/pixel_sampler.h"
#include "render_workers.h"
#include "tile_samples.h"

namespace raylab {
namespace {

using detail::check_resumable;
using detail::filter_margin;
using detail::is_pixel_box;
using detail::PixelRect;
using detail::render_tile_samples;
using detail::RenderWorkers;
using detail::TileGrid;

RenderResult render_uniform(const Scene& scene, const Accelerator& accel, Film& film, const RenderOptions& options,
                            const PixelSampler& sampler, const Filter& filter) {
  const Camera camera(scene.camera, film.width(), film.height());
  const TileGrid grid(film.width(), film.height(), options.tile_size);
  const SampleDimensions dims(sampler);
  // Wider filters: each tile accumulates into its own sums (tile plus margin), added up in tile
  // order by develop(), so the image does not depend on scheduling.
  const int margin = filter_margin(filter);
  RenderProgress own;
  RenderProgress& progress = options.progress != nullptr ? *options.progress : own;
  if (progress.tiles.empty()) {
    progress = start_progress(film.width(), film.height(), grid.tile(), sampler.spp(), options.passes, margin);
  } else {
    check_resumable(progress, film.width(), film.height(), grid.tile(), sampler.spp(), margin);
  }

  RenderWorkers workers(scene, accel, options);
  std::mutex state_mutex;       // guards `progress` while tiles commit and checkpoints copy it
  std::mutex checkpoint_mutex;  // one checkpoint at a time; guards last_checkpoint
  auto last_checkpoint = std::chrono::steady_clock::now();
  auto maybe_checkpoint = [&] {
    if (!options.on_checkpoint || options.checkpoint_seconds <= 0.0) return;
    const std::unique_lock one_at_a_time(checkpoint_mutex, std::try_to_lock);
    if (!one_at_a_time.owns_lock()) return;
    const std::chrono::duration<double> since = std::chrono::steady_clock::now() - last_checkpoint;
    if (since.count() < options.checkpoint_seconds) return;
    RenderProgress copy;
    {
      const std::lock_guard lock(state_mutex);
      copy = progress;
    }
    options.on_checkpoint(copy);
    last_checkpoint = std::chrono::steady_clock::now();  // the interval counts from the last write
  };

  const int tiles_total = progress.passes * grid.count();
  std::atomic<int> tiles_done{progress.passes_done * grid.count() +
                              (grid.count() - static_cast<int>(progress.unfinished_tiles().size()))};
  std::atomic<bool> stopped{false};
  const auto start = std::chrono::steady_clock::now();
  for (int pass = progress.passes_done; pass < progress.passes; ++pass) {
    const int first = progress.samples_before(pass), end = progress.samples_before(pass + 1);
    const std::vector<int> todo =
        options.scattered_tiles ? scattered_tile_order(progress.unfinished_tiles()) : progress.unfinished_tiles();
    workers.for_each(static_cast<int>(todo.size()), [&](int k, const TraceContext& ctx) {
      if (stopped.load(std::memory_order_relaxed) || (options.should_stop && options.should_stop())) {
        stopped.store(true, std::memory_order_relaxed);
        return;
      }
      const int t = todo[static_cast<std::size_t>(k)];
      // Only this task changes tile t during this pass, so it works on a copy and commits it whole:
      // a checkpoint taken meanwhile sees the tile as it was after the previous pass.
      TileSums sums = progress.tiles[static_cast<std::size_t>(t)];
      render_tile_samples(ctx, camera, sampler, dims, filter, options.packets, grid.rect(t), first, end, sums);
      {
        const std::lock_guard lock(state_mutex);
        progress.tiles[static_cast<std::size_t>(t)] = std::move(sums);
        progress.tile_done[static_cast<std::size_t>(t)] = 1;
      }
      const int done = tiles_done.fetch_add(1, std::memory_order_relaxed) + 1;
      if (options.on_progress) options.on_progress(done, tiles_total);
      maybe_checkpoint();
    });
    if (stopped.load()) break;
    {
      const std::lock_guard lock(state_mutex);
      progress.passes_done = pass + 1;
      if (!progress.complete()) std::fill(progress.tile_done.begin(), progress.tile_done.end(), 0);
    }
    if (options.on_pass && !progress.complete()) {
      develop(progress, film);
      options.on_pass(progress.passes_done, film);
    }
  }
  develop(progress, film);

  RenderResult result = detail::finish_render(workers, start, samples_per_pixel(progress));
  result.interrupted = !progress.complete();
  return result;
}

// Throws UsageError when `options` ask an adaptive sampler for what only the uniform ones do.
void check_adaptive_options(const std::string& sampler, const RenderOptions& options) {
  if (options.passes != 1 || options.progress != nullptr || options.on_checkpoint) {
    throw UsageError("passes, checkpoints and resuming work with the uniform samplers, not with " + sampler +
                     " (its refinement needs the whole image at once)");
  }
}

}  // namespace

int render_thread_count(const RenderOptions& options) { return usable_threads(options.threads); }

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
  check_integrator_name(s.integrator);
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

RenderMemoryEstimate estimate_render_memory(const Scene& scene, const RenderOptions& options) {
  const RenderSettings& s = scene.settings;
  RenderMemoryEstimate e;
  const auto pixels =
      static_cast<std::uint64_t>(std::max(0, s.width)) * static_cast<std::uint64_t>(std::max(0, s.height));
  e.samples = pixels * static_cast<std::uint64_t>(std::max(1, s.spp));
  // The film, the samples-per-pixel counts, and the output as floats (EXR, PFM) while encoding.
  e.image = pixels * (sizeof(Color) + sizeof(std::uint32_t) + sizeof(Color));
  const std::string name = resolve_sampler_name(s);
  if (is_adaptive_sampler(name)) {
    e.sums = pixels * 2 * sizeof(Color);  // its per-pixel sample records, about the film's size twice
  } else {
    const Filter filter = make_filter(s.filter, s.filter_radius);
    const int margin = filter_margin(filter);
    e.sums = progress_memory_bytes(s.width, s.height, std::max(1, options.tile_size), margin);
    // A checkpoint copies the state, and its file's bytes are about the same size again.
    if (options.on_checkpoint) e.sums *= 3;
  }
  e.accelerator = static_cast<std::size_t>(scene.primitive_count()) * kAccelBytesPerPrimitive;
  return e;
}

RenderResult render(const Scene& scene, const Accelerator& accel, Film& film, const RenderOptions& options) {
  const RenderSettings& s = scene.settings;
  check_sampling_settings(s);
  const std::string name = resolve_sampler_name(s);
  const Filter filter = make_filter(s.filter, s.filter_radius);
  RenderResult result;
  if (is_adaptive_sampler(name)) {
    check_adaptive_options(name, options);
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
