#include "raylab/render/tile_renderer.h"

#include <chrono>

#include "raylab/core/error.h"
#include "raylab/render/adaptive.h"
#include "raylab/render/camera.h"
#include "raylab/sampling/filter.h"
#include "raylab/sampling/pixel_sampler.h"
#include "render_workers.h"
#include "tile_samples.h"

namespace raylab {

struct TileRenderer::State {
  State(const Scene& scene, const Accelerator& accel, const RenderOptions& options, const std::string& name)
      : camera(scene.camera, scene.settings.width, scene.settings.height),
        sampler(make_pixel_sampler(name, scene.settings.spp, scene.settings.seed)),
        dimensions(*sampler),
        filter(make_filter(scene.settings.filter, scene.settings.filter_radius)),
        grid(scene.settings.width, scene.settings.height, options.tile_size),
        workers(scene, accel, options),
        thread_count(render_thread_count(options)),
        packets(options.packets),
        notice(spp_rounding_notice(name, scene.settings.spp)),
        width(scene.settings.width),
        height(scene.settings.height) {}

  Camera camera;
  std::unique_ptr<PixelSampler> sampler;
  SampleDimensions dimensions;
  Filter filter;
  detail::TileGrid grid;
  detail::RenderWorkers workers;
  int thread_count;
  bool packets;
  std::string notice;
  int width, height;
};

namespace {

// The sampler's name, after refusing what render() would refuse and what only render() can do.
std::string uniform_sampler_name(const RenderSettings& settings) {
  check_sampling_settings(settings);
  std::string name = resolve_sampler_name(settings);
  if (is_adaptive_sampler(name)) {
    throw UsageError("the " + name + " sampler refines the whole image at once; it cannot be rendered tile by tile");
  }
  return name;
}

}  // namespace

TileRenderer::TileRenderer(const Scene& scene, const Accelerator& accel, const RenderOptions& options)
    : m_state(std::make_unique<State>(scene, accel, options, uniform_sampler_name(scene.settings))) {}

TileRenderer::~TileRenderer() = default;

RenderProgress TileRenderer::start_progress(int passes) const {
  const State& s = *m_state;
  return raylab::start_progress(s.width, s.height, s.grid.tile(), s.sampler->spp(), passes,
                                detail::filter_margin(s.filter));
}

void TileRenderer::check_progress(const RenderProgress& progress) const {
  const State& s = *m_state;
  detail::check_resumable(progress, s.width, s.height, s.grid.tile(), s.sampler->spp(),
                          detail::filter_margin(s.filter));
}

void TileRenderer::run(TileJobSource& source) {
  State& s = *m_state;
  // One long-lived task per thread, each asking the source for job after job: the source, not
  // the thread pool, decides the order, so that jobs can arrive while others run.
  s.workers.for_each(s.thread_count, [&](int, const TraceContext& ctx) {
    while (std::optional<TileJob> job = source.next()) {
      const auto start = std::chrono::steady_clock::now();
      detail::render_tile_samples(ctx, s.camera, *s.sampler, s.dimensions, s.filter, s.packets, s.grid.rect(job->tile),
                                  job->first, job->end, job->sums);
      const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
      source.done(std::move(*job), took.count());
    }
  });
}

RenderStats TileRenderer::stats() { return m_state->workers.merged_stats(); }

int TileRenderer::threads() const { return m_state->thread_count; }

int TileRenderer::spp() const { return m_state->sampler->spp(); }

const std::string& TileRenderer::notice() const { return m_state->notice; }

}  // namespace raylab
