// Adaptive sampling that does not miss what falls between corners (the `adaptive` sampler):
// a jittered base sample per pixel, refinement triggered by colour, object or normal changes in
// a pixel's neighbourhood, nested stratified subsamples weighted by area, and refinement that
// spreads along whatever the refined pixels find. The rule and its defaults are documented in
// docs/antialiasing.md.

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <vector>

#include "raylab/render/adaptive.h"
#include "raylab/sampling/pixel_sampler.h"
#include "render_workers.h"
#include "sample_contrast.h"

namespace raylab {
namespace {

using detail::PixelRect;
using detail::TileGrid;

constexpr int kMaxDepth = 8;
// Levels every refined pixel gets regardless of what it finds: 4 x 4 strata, the stratification
// of 16-spp jittered sampling; deeper levels only where a quarter's samples still differ.
constexpr int kRefinedLevels = 2;
// Refined pixels are handed to the workers in chunks of this many (load balance vs overhead).
constexpr int kChunk = 32;

// One traced sample: its colour, as displayed, and what it hit.
struct TracedSample {
  Color color;
  Color display;
  PrimaryFeature feature;
};

// Do these samples differ enough to refine: contrast above the threshold, different objects
// (or an object against the background), or normals further apart than the angle allows.
class DifferenceTest {
 public:
  explicit DifferenceTest(const AdaptiveParams& p) : m_threshold(p.threshold), m_cosine(p.normal_cosine) {}

  template <class Get>
  bool differ(int n, Get&& get) const {
    if (n < 2) return false;
    detail::ContrastRange range;
    const std::int32_t object = get(0).feature.object;
    for (int i = 0; i < n; ++i) {
      const TracedSample& s = get(i);
      if (s.feature.object != object) return true;
      range.add(s.display);
    }
    if (range.contrast() > m_threshold) return true;
    if (object < 0) return false;  // all background: no normals to compare
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if (dot(get(i).feature.normal, get(j).feature.normal) < m_cosine) return true;
      }
    }
    return false;
  }

 private:
  float m_threshold;
  float m_cosine;
};

// A sample of a pixel being refined: the stratum (cell) it stands for, 2^level cells per side.
struct CellSample {
  int level = 0;
  int cx = 0, cy = 0;
  float x = 0.5f, y = 0.5f;  // position within the pixel, [0, 1)
  TracedSample s;
};

class AdaptiveRenderer {
 public:
  AdaptiveRenderer(const Scene& scene, Film& film, const AdaptiveParams& params)
      : m_scene(scene), m_film(film), m_camera(scene.camera, film.width(), film.height()),
        m_depth(std::clamp(params.depth, 0, kMaxDepth)), m_test(params), m_seed(scene.settings.seed),
        m_base(std::size_t(film.width()) * film.height()) {}

  // The base sample of every pixel of tile `r` (cell 0 of level 0: anywhere in the pixel).
  void trace_base(const TraceContext& ctx, const PixelRect& r) {
    for (int py = r.y0; py < r.y1; ++py) {
      for (int px = r.x0; px < r.x1; ++px) {
        const CellSample c = sample_in_cell(ctx, px, py, 0, 0, 0);
        m_base[index(px, py)] = c.s;
        m_film.at(px, py) = c.s.color;
      }
    }
  }

  // Whether the base samples of the 3 x 3 pixels around (px, py) differ.
  bool neighbourhood_differs(int px, int py) const {
    std::array<const TracedSample*, 9> window{};
    int n = 0;
    for (int y = std::max(0, py - 1); y <= std::min(m_film.height() - 1, py + 1); ++y) {
      for (int x = std::max(0, px - 1); x <= std::min(m_film.width() - 1, px + 1); ++x) {
        window[static_cast<std::size_t>(n++)] = &m_base[index(x, y)];
      }
    }
    return m_test.differ(n, [&](int i) -> const TracedSample& { return *window[static_cast<std::size_t>(i)]; });
  }

  // Refines pixel (px, py): writes its colour, returns its sample count; `found` tells whether
  // its own samples differ (then its neighbours are refined too).
  int refine_pixel(const TraceContext& ctx, int px, int py, std::vector<CellSample>& samples, bool& found) const {
    samples.clear();
    CellSample base;
    base.s = m_base[index(px, py)];
    base.x = base_position(px, py).x;
    base.y = base_position(px, py).y;
    samples.push_back(base);
    if (m_depth >= 1) {
      std::array<int, 4> quarters = split(ctx, px, py, samples, 0);
      for (int q : quarters) {
        if (m_depth >= kRefinedLevels) refine_cell(ctx, px, py, samples, split(ctx, px, py, samples, q));
      }
    }
    Color sum{0.f};
    for (const CellSample& c : samples) sum += c.s.color * std::ldexp(1.f, -2 * c.level);
    m_film.at(px, py) = sum;
    found = m_test.differ(static_cast<int>(samples.size()),
                          [&](int i) -> const TracedSample& { return samples[static_cast<std::size_t>(i)].s; });
    return static_cast<int>(samples.size());
  }

  int width() const { return m_film.width(); }
  int height() const { return m_film.height(); }
  std::size_t index(int px, int py) const { return std::size_t(py) * m_film.width() + px; }

 private:
  // The cell's random position and path seed come from (seed, pixel, cell): deterministic.
  std::uint64_t cell_key(int level, int cx, int cy) const {
    return (std::uint64_t(level) << 40) | (std::uint64_t(cy) << 20) | std::uint64_t(cx);
  }

  Sample2 position_in_cell(int px, int py, int level, int cx, int cy) const {
    Pcg32 rng(hash_seed(m_seed, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py),
                        cell_key(level, cx, cy)));
    const float side = std::ldexp(1.f, -level);
    const float u = rng.next_float();
    const float v = rng.next_float();
    // Clamped so that float rounding never puts the sample in the next cell.
    return {std::min((static_cast<float>(cx) + u) * side, std::nextafter((static_cast<float>(cx) + 1.f) * side, 0.f)),
            std::min((static_cast<float>(cy) + v) * side, std::nextafter((static_cast<float>(cy) + 1.f) * side, 0.f))};
  }

  Sample2 base_position(int px, int py) const { return position_in_cell(px, py, 0, 0, 0); }

  CellSample sample_in_cell(const TraceContext& ctx, int px, int py, int level, int cx, int cy) const {
    CellSample c;
    c.level = level;
    c.cx = cx;
    c.cy = cy;
    const Sample2 u = position_in_cell(px, py, level, cx, cy);
    c.x = u.x;
    c.y = u.y;
    c.s.color = detail::trace_image_position(
        ctx, m_camera, static_cast<float>(px) + u.x, static_cast<float>(py) + u.y,
        hash_seed(m_seed ^ 0xada9717eull, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py),
                  cell_key(level, cx, cy)),
        &c.s.feature);
    c.s.display = detail::display_encoded(c.s.color);
    return c;
  }

  // Splits the cell of samples[k] into its four children: the sample keeps its place in the
  // child it lies in, the other three children get new samples. Returns the four samples'
  // indices (child order: (0,0), (1,0), (0,1), (1,1)).
  std::array<int, 4> split(const TraceContext& ctx, int px, int py, std::vector<CellSample>& samples, int k) const {
    const CellSample parent = samples[static_cast<std::size_t>(k)];
    const int level = parent.level + 1;
    const float cells = std::ldexp(1.f, level);
    const int kx = std::clamp(static_cast<int>(parent.x * cells), 2 * parent.cx, 2 * parent.cx + 1);
    const int ky = std::clamp(static_cast<int>(parent.y * cells), 2 * parent.cy, 2 * parent.cy + 1);
    std::array<int, 4> out{};
    for (int child = 0; child < 4; ++child) {
      const int cx = 2 * parent.cx + (child & 1);
      const int cy = 2 * parent.cy + (child >> 1);
      if (cx == kx && cy == ky) {
        CellSample& kept = samples[static_cast<std::size_t>(k)];
        kept.level = level;
        kept.cx = cx;
        kept.cy = cy;
        out[static_cast<std::size_t>(child)] = k;
      } else {
        samples.push_back(sample_in_cell(ctx, px, py, level, cx, cy));
        out[static_cast<std::size_t>(child)] = static_cast<int>(samples.size()) - 1;
      }
    }
    return out;
  }

  // A cell whose four children hold one sample each: where they differ and depth allows, split
  // every child and look again inside each.
  void refine_cell(const TraceContext& ctx, int px, int py, std::vector<CellSample>& samples,
                   const std::array<int, 4>& children) const {
    if (samples[static_cast<std::size_t>(children[0])].level >= m_depth) return;
    const bool differ = m_test.differ(4, [&](int i) -> const TracedSample& {
      return samples[static_cast<std::size_t>(children[static_cast<std::size_t>(i)])].s;
    });
    if (!differ) return;
    for (int child : children) refine_cell(ctx, px, py, samples, split(ctx, px, py, samples, child));
  }

  const Scene& m_scene;
  Film& m_film;
  Camera m_camera;
  int m_depth;
  DifferenceTest m_test;
  std::uint64_t m_seed;
  std::vector<TracedSample> m_base;  // one per pixel, row-major
};

}  // namespace

RenderResult render_adaptive(const Scene& scene, const Accelerator& accel, Film& film, const RenderOptions& options,
                             const AdaptiveParams& params) {
  AdaptiveRenderer renderer(scene, film, params);
  const int w = film.width();
  const int h = film.height();
  const std::size_t pixels = std::size_t(w) * h;
  const TileGrid grid(w, h, options.tile_size);
  detail::RenderWorkers workers(scene, accel, options);
  std::vector<std::uint32_t> counts(pixels, 1u);
  // Progress in pixels: the base pass, then every refined pixel once more; the total grows as the
  // refinement finds more to do.
  std::atomic<long> done{0};
  std::atomic<long> total{static_cast<long>(pixels)};
  auto progress = [&](long amount) {
    const long d = done.fetch_add(amount, std::memory_order_relaxed) + amount;
    if (options.on_progress) {
      options.on_progress(static_cast<int>(std::min<long>(d, INT32_MAX)),
                          static_cast<int>(std::min<long>(total.load(std::memory_order_relaxed), INT32_MAX)));
    }
  };

  const auto start = std::chrono::steady_clock::now();
  workers.for_each(grid.count(), [&](int t, const TraceContext& ctx) {
    const PixelRect r = grid.rect(t);
    renderer.trace_base(ctx, r);
    progress(long(r.x1 - r.x0) * (r.y1 - r.y0));
  });

  // Pixels whose neighbourhood differs start the refinement.
  std::vector<unsigned char> state(pixels, 0);  // 0: base only, 1: queued, 2: refined
  std::vector<unsigned char> found(pixels, 0);
  std::vector<int> queue;
  if (params.depth > 0) {
    std::vector<unsigned char> flagged(pixels, 0);
    workers.for_each(h, [&](int y, const TraceContext&) {
      for (int x = 0; x < w; ++x) flagged[renderer.index(x, y)] = renderer.neighbourhood_differs(x, y) ? 1 : 0;
    });
    for (std::size_t i = 0; i < pixels; ++i) {
      if (flagged[i]) {
        queue.push_back(static_cast<int>(i));
        state[i] = 1;
      }
    }
  }
  // Refine in rounds; each round queues the unrefined neighbours of the pixels whose own samples
  // differed, so a thin line missed by the base samples is followed from where it was found.
  // The final set does not depend on the order, only on the samples, so the image is
  // deterministic.
  while (!queue.empty()) {
    total.fetch_add(static_cast<long>(queue.size()), std::memory_order_relaxed);
    const int chunks = static_cast<int>((queue.size() + kChunk - 1) / kChunk);
    workers.for_each(chunks, [&](int c, const TraceContext& ctx) {
      thread_local std::vector<CellSample> samples;
      const std::size_t begin = std::size_t(c) * kChunk;
      const std::size_t end = std::min(queue.size(), begin + kChunk);
      for (std::size_t k = begin; k < end; ++k) {
        const int i = queue[k];
        bool differs = false;
        counts[static_cast<std::size_t>(i)] =
            static_cast<std::uint32_t>(renderer.refine_pixel(ctx, i % w, i / w, samples, differs));
        found[static_cast<std::size_t>(i)] = differs ? 1 : 0;
      }
      progress(static_cast<long>(end - begin));
    });
    std::vector<int> next;
    for (int i : queue) state[static_cast<std::size_t>(i)] = 2;
    for (int i : queue) {
      if (!found[static_cast<std::size_t>(i)]) continue;
      const int px = i % w;
      const int py = i / w;
      for (int y = std::max(0, py - 1); y <= std::min(h - 1, py + 1); ++y) {
        for (int x = std::max(0, px - 1); x <= std::min(w - 1, px + 1); ++x) {
          const std::size_t j = renderer.index(x, y);
          if (state[j] == 0) {
            state[j] = 1;
            next.push_back(static_cast<int>(j));
          }
        }
      }
    }
    std::sort(next.begin(), next.end());
    queue = std::move(next);
  }

  RenderResult result;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.stats = workers.merged_stats();
  result.samples_per_pixel = std::move(counts);
  return result;
}

}  // namespace raylab
