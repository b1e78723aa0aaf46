#include "raylab/render/spd_protocol.h"
#include "raylab/core/stopwatch.h"
#include "raylab/core/thread_count.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <utility>
#include <vector>

#include "packet_tracing.h"
#include "raylab/render/camera.h"
#include "raylab/render/whitted.h"
#include "raylab/sampling/seed_salts.h"

namespace raylab {

std::vector<std::string> spd_facing_names() { return {"viewer", "outward"}; }

std::optional<ShadowFacing> parse_spd_facing(std::string_view name) {
  if (name == "viewer") return ShadowFacing::kViewer;
  if (name == "outward") return ShadowFacing::kOutward;
  return std::nullopt;
}

std::string_view spd_facing_name(ShadowFacing facing) {
  return facing == ShadowFacing::kOutward ? "outward" : "viewer";
}

SpdProtocolCounts spd_protocol_counts(const RenderStats& stats) {
  const auto kind = [](RayKind k) { return static_cast<int>(k); };
  SpdProtocolCounts c;
  c.primary = stats.rays[kind(RayKind::kPrimary)];
  c.primary_hits = stats.ray_hits[kind(RayKind::kPrimary)];
  c.reflection = stats.rays[kind(RayKind::kReflection)];
  c.reflection_hits = stats.ray_hits[kind(RayKind::kReflection)];
  c.refraction = stats.rays[kind(RayKind::kRefraction)];
  c.refraction_hits = stats.ray_hits[kind(RayKind::kRefraction)];
  c.shadow = stats.rays[kind(RayKind::kShadow)];
  c.shadow_hits = stats.ray_hits[kind(RayKind::kShadow)];
  c.total_internal_reflections = stats.total_internal_reflections;
  return c;
}

SpdProtocolResult render_spd_protocol(Scene& scene, const Accelerator& accel, Film& film, const RenderOptions& options,
                                      ShadowFacing facing) {
  const int n = kSpdProtocolSize;
  RenderSettings& settings = scene.settings;
  settings.width = n;
  settings.height = n;
  settings.max_depth = 5;
  CameraSpec spec = scene.camera;
  spec.fov_span = CameraSpec::FovSpan::kImageEdges;
  const Camera camera(spec, n, n);

  const int corners = n + 1;
  Film::Pixels corner(static_cast<std::size_t>(corners) * corners);
  tbb::enumerable_thread_specific<RenderStats> thread_stats;
  std::atomic<int> rows_done{0};
  const int threads = usable_threads(options.threads);
  tbb::task_arena arena(threads);
  const auto start = std::chrono::steady_clock::now();
  // Corners go to the accelerator as packets of kBlock x kBlock (the pixel loops' 4 x 4 blocks),
  // each corner shaded with the generator and the arithmetic of a single ray, so the image and
  // the ray counts are those of tracing the corners one by one.
  constexpr int kBlock = 4;
  static_assert(kBlock * kBlock <= detail::kPacketSize);
  const int block_rows = (corners + kBlock - 1) / kBlock;
  // Each corner's generator is seeded from its position only when some light draws random
  // numbers (an area light): with single-sample lights alone, as in every SPD scene, no number
  // is ever drawn, and hashing 263,169 seeds was 5.5% of the whole process on SPD tetra.
  const bool seeded =
      std::ranges::any_of(scene.lights, [](const Light& light) { return !WhittedIntegrator::is_single_sample(light); });
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, block_rows, 1), [&](const tbb::blocked_range<int>& range) {
      RenderStats& stats = thread_stats.local();
      const TraceContext ctx{scene, accel, stats, options.count_traversal, facing};
      detail::PrimaryPacketTracer tracer(ctx, /*replace_nonfinite=*/false);
      std::array<Ray, detail::kPacketSize> rays;
      std::array<std::uint64_t, detail::kPacketSize> seeds;
      std::array<std::size_t, detail::kPacketSize> slots;
      std::array<Color, detail::kPacketSize> colors;
      for (int block = range.begin(); block != range.end(); ++block) {
        const int y0 = block * kBlock, y1 = std::min(y0 + kBlock, corners);
        for (int x0 = 0; x0 < corners; x0 += kBlock) {
          std::size_t count = 0;
          for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < std::min(x0 + kBlock, corners); ++x) {
              // SPD scenes have point lights only; the generator is there for area lights,
              // seeded by the corner so the image is the same for any thread count.
              slots[count] = static_cast<std::size_t>(y) * corners + x;
              seeds[count] = seeded ? hash_seed(settings.seed ^ kUnsaltedSeed, slots[count]) : 0;
              rays[count++] = camera.generate(static_cast<float>(x), static_cast<float>(y));
            }
          }
          tracer.trace(std::span<const Ray>(rays.data(), count), std::span<const std::uint64_t>(seeds.data(), count),
                       std::span<Color>(colors.data(), count));
          for (std::size_t k = 0; k < count; ++k) corner[slots[k]] = colors[k];
        }
        const int done = rows_done.fetch_add(y1 - y0, std::memory_order_relaxed) + (y1 - y0);
        if (options.on_progress) options.on_progress(done, corners);
      }
    });
  });

  SpdProtocolResult result;
  result.seconds = seconds_since(start);
  // Each pixel is written over the corners, in place: pixel (x, y) goes to y * n + x, and every
  // corner a later pixel reads lies at (y' + dy) * (n + 1) + x' + dx > y * n + x. The image so
  // takes no fresh memory (on a virtual machine each fresh page is a costly fault on first
  // touch: docs/performance.md, "Page faults on a virtual machine").
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const auto c = [&](int dx, int dy) { return corner[static_cast<std::size_t>(y + dy) * corners + x + dx]; };
      corner[static_cast<std::size_t>(y) * n + x] = (c(0, 0) + c(1, 0) + c(0, 1) + c(1, 1)) * 0.25f;
    }
  }
  corner.resize(static_cast<std::size_t>(n) * n);
  film = Film(n, n, std::move(corner));
  for (const RenderStats& st : thread_stats) result.stats += st;
  result.counts = spd_protocol_counts(result.stats);
  return result;
}

}  // namespace raylab
