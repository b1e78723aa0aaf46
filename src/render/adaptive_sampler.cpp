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
#include <cstdlib>
#include <memory>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/render/adaptive.h"
#include "raylab/sampling/multi_jittered_pattern.h"
#include "raylab/sampling/pixel_sampler.h"  // Sample2
#include "raylab/sampling/seed_salts.h"
#include "raylab/sampling/stratum.h"
#include "render_workers.h"
#include "sample_contrast.h"
#include "small_objects.h"

namespace raylab {
namespace {

using detail::PixelRect;
using detail::TileGrid;

constexpr int kMaxDepth = 8;
// Area of a cell of each level, as a fraction of the pixel: 4^-level.
constexpr std::array<float, kMaxDepth + 1> kCellArea = {
    1.f, 0.25f, 0.0625f, 0.015625f, 0.00390625f, 0.0009765625f, 0.000244140625f, 6.103515625e-05f, 1.52587890625e-05f};
// Every refined pixel gets the pattern's levels (as far as the depth allows) whatever it finds:
// 4 x 4 strata, the stratification of 16-spp jittered sampling; deeper levels only where a
// quarter's samples still differ. The pattern's two levels take their 16 positions from the
// pixel's MultiJitteredPattern, whose sample i lies in cell (i % 4, i / 4).
constexpr int kPatternSize = MultiJitteredPattern::kSize;
constexpr int kPatternLevels = 2;
// Refined pixels go to the workers in batches of this many.
constexpr int kBatch = 64;

// One traced sample: its colour and what it hit.
struct TracedSample {
  Color color;
  PrimaryFeature feature;
};

// Do these samples differ enough to refine: contrast above the threshold, different objects
// (or an object against the background), or normals further apart than the angle allows.
class DifferenceTest {
 public:
  explicit DifferenceTest(const AdaptiveParams& p) : m_threshold(p.threshold), m_cosine(p.normal_cosine) {}

  /// Whether samples get(0) .. get(n - 1) differ; with `colour` false, only in object or normal.
  template <class Get>
  bool differ(int n, Get&& get, bool colour = true) const {
    if (n < 2) return false;
    detail::ContrastRange range;
    const std::int32_t object = get(0).feature.object;
    for (int i = 0; i < n; ++i) {
      const TracedSample& s = get(i);
      if (s.feature.object != object) return true;
      range.add(s.color);
    }
    if (colour && range.contrast() > m_threshold) return true;
    if (object < 0) return false;  // all background: no normals to compare
    // On a flat surface every normal is the same: skip the pairwise comparison.
    const Vec3 n0 = get(0).feature.normal;
    bool same = true;
    for (int i = 1; i < n && same; ++i) {
      const Vec3 ni = get(i).feature.normal;
      same = ni.x == n0.x && ni.y == n0.y && ni.z == n0.z;
    }
    if (same) return false;
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

// The cell of `level` that position u (in [0, 1)) falls in.
int cell_of(float u, int level) {
  const int cells = 1 << level;
  return std::clamp(static_cast<int>(u * static_cast<float>(cells)), 0, cells - 1);
}

class AdaptiveRenderer {
 public:
  AdaptiveRenderer(const Scene& scene, Film& film, const AdaptiveParams& params)
      : m_film(film),
        m_camera(scene.camera, film.width(), film.height()),
        m_depth(std::clamp(params.depth, 0, kMaxDepth)),
        m_test(params),
        m_seed(scene.settings.seed),
        m_base(std::size_t(film.width()) * film.height()) {}

  const Camera& camera() const { return m_camera; }

  // The base sample of every pixel of tile `r`: one of the pixel's 16 pattern samples, chosen at
  // random, so on its own it is a uniformly jittered sample.
  void trace_base(const TraceContext& ctx, const PixelRect& r) {
    for (int py = r.y0; py < r.y1; ++py) {
      for (int px = r.x0; px < r.x1; ++px) {
        const CellSample c = pattern_sample(ctx, px, py, base_index(px, py), 0);
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
    const int b = base_index(px, py);
    CellSample base;
    base.s = m_base[index(px, py)];
    const MultiJitteredPattern pattern_of_pixel(m_seed, px, py);
    const Sample2 bu = pattern_of_pixel.sample(b);
    base.x = bu.x;
    base.y = bu.y;
    samples.push_back(base);
    if (m_depth >= 1) {
      std::array<Sample2, kPatternSize> pattern;
      for (int i = 0; i < kPatternSize; ++i) pattern[static_cast<std::size_t>(i)] = pattern_of_pixel.sample(i);
      // Level 1: one pattern sample in each quarter (the base sample's quarter keeps it).
      const int levels = std::min(m_depth, kPatternLevels);
      std::array<bool, kPatternSize> used{};
      used[static_cast<std::size_t>(b)] = true;
      std::array<bool, 4> quarter_done{};
      quarter_done[static_cast<std::size_t>(quarter(bu))] = true;
      for (int k = 1; k < kPatternSize; ++k) {
        const int i = (b + k) % kPatternSize;
        const Sample2 u = pattern[static_cast<std::size_t>(i)];
        if (quarter_done[static_cast<std::size_t>(quarter(u))]) continue;
        quarter_done[static_cast<std::size_t>(quarter(u))] = true;
        samples.push_back(trace_at(ctx, px, py, u, 1, static_cast<std::uint64_t>(i)));
        used[static_cast<std::size_t>(i)] = true;
      }
      samples[0].level = 1;
      samples[0].cx = cell_of(samples[0].x, 1);
      samples[0].cy = cell_of(samples[0].y, 1);
      if (levels >= 2) {
        // Level 2: the rest of the pattern, one sample in each of the 4 x 4 strata.
        for (CellSample& c : samples) {
          c.level = 2;
          c.cx = cell_of(c.x, 2);
          c.cy = cell_of(c.y, 2);
        }
        for (int i = 0; i < kPatternSize; ++i) {
          if (!used[static_cast<std::size_t>(i)]) {
            samples.push_back(
                trace_at(ctx, px, py, pattern[static_cast<std::size_t>(i)], 2, static_cast<std::uint64_t>(i)));
          }
        }
        if (m_depth > kPatternLevels) refine_quarters(ctx, px, py, samples);
      }
    }
    Color sum{0.f};
    for (const CellSample& c : samples) sum += c.s.color * kCellArea[static_cast<std::size_t>(c.level)];
    m_film.at(px, py) = sum;
    found = m_test.differ(static_cast<int>(samples.size()),
                          [&](int i) -> const TracedSample& { return samples[static_cast<std::size_t>(i)].s; });
    return static_cast<int>(samples.size());
  }

  std::size_t index(int px, int py) const { return std::size_t(py) * m_film.width() + px; }

 private:
  static int quarter(Sample2 u) { return (u.x >= 0.5f ? 1 : 0) + (u.y >= 0.5f ? 2 : 0); }

  int base_index(int px, int py) const {
    return static_cast<int>(
        hash_seed(m_seed ^ kAdaptiveBaseSampleSalt, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py)) %
        kPatternSize);
  }

  std::uint64_t path_seed(int px, int py, std::uint64_t key) const {
    return hash_seed(m_seed ^ kAdaptivePathSalt, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py), key);
  }

  CellSample trace_at(const TraceContext& ctx, int px, int py, Sample2 u, int level, std::uint64_t key) const {
    CellSample c;
    c.level = level;
    c.cx = cell_of(u.x, level);
    c.cy = cell_of(u.y, level);
    c.x = u.x;
    c.y = u.y;
    c.s.color = detail::trace_image_position(ctx, m_camera, static_cast<float>(px) + u.x, static_cast<float>(py) + u.y,
                                             path_seed(px, py, key), &c.s.feature);
    return c;
  }

  // Sample `i` of the pixel's 16-sample pattern, standing for a cell of `level`.
  CellSample pattern_sample(const TraceContext& ctx, int px, int py, int i, int level) const {
    return trace_at(ctx, px, py, MultiJitteredPattern(m_seed, px, py).sample(i), level, static_cast<std::uint64_t>(i));
  }

  // A jittered sample in cell (level, cx, cy) (levels beyond the pattern).
  CellSample jittered_sample(const TraceContext& ctx, int px, int py, int level, int cx, int cy) const {
    const std::uint64_t key = (std::uint64_t(level) << 40) | (std::uint64_t(cy) << 20) | std::uint64_t(cx);
    Pcg32 rng(hash_seed(m_seed ^ kUnsaltedSeed, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py), key));
    const float u = rng.next_float();
    const float v = rng.next_float();
    const Sample2 p{point_in_interval(cx, u, 1 << level), point_in_interval(cy, v, 1 << level)};
    CellSample c = trace_at(ctx, px, py, p, level, key);
    c.cx = cx;
    c.cy = cy;
    return c;
  }

  // After the 4 x 4 level: each quarter whose four samples see different objects or normals
  // (a silhouette, a crease, a small object) is split further, and so on inside it, down to the
  // depth limit. Colour alone (texture, shadow, reflection) stops at 4 x 4: an edge's error lies
  // in the few sub-cells it crosses, so each deeper sample there pays, while detail that varies
  // across the whole pixel would need every sub-cell split for the same gain.
  void refine_quarters(const TraceContext& ctx, int px, int py, std::vector<CellSample>& samples) const {
    std::array<std::array<int, 4>, 4> quarters{};
    for (int i = 0; i < static_cast<int>(samples.size()); ++i) {
      const CellSample& c = samples[static_cast<std::size_t>(i)];
      const int q = (c.cx >> 1) + 2 * (c.cy >> 1);
      const int child = (c.cx & 1) + 2 * (c.cy & 1);
      quarters[static_cast<std::size_t>(q)][static_cast<std::size_t>(child)] = i;
    }
    for (const std::array<int, 4>& quarter : quarters) refine_cell(ctx, px, py, samples, quarter);
  }

  bool geometry_differs(const std::vector<CellSample>& samples, const std::array<int, 4>& children) const {
    return m_test.differ(
        4,
        [&](int i) -> const TracedSample& {
          return samples[static_cast<std::size_t>(children[static_cast<std::size_t>(i)])].s;
        },
        /*colour=*/false);
  }

  // Splits the cell of samples[k] into its four children: the sample keeps its place in the
  // child it lies in, the other three children get new jittered samples. Returns the four
  // samples' indices (child order: (0,0), (1,0), (0,1), (1,1)).
  std::array<int, 4> split(const TraceContext& ctx, int px, int py, std::vector<CellSample>& samples, int k) const {
    const CellSample parent = samples[static_cast<std::size_t>(k)];
    const int level = parent.level + 1;
    const int kx = std::clamp(cell_of(parent.x, level), 2 * parent.cx, 2 * parent.cx + 1);
    const int ky = std::clamp(cell_of(parent.y, level), 2 * parent.cy, 2 * parent.cy + 1);
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
        samples.push_back(jittered_sample(ctx, px, py, level, cx, cy));
        out[static_cast<std::size_t>(child)] = static_cast<int>(samples.size()) - 1;
      }
    }
    return out;
  }

  // A cell whose four children hold one sample each: where they see different geometry and
  // depth allows, split every child and look again inside each.
  void refine_cell(const TraceContext& ctx, int px, int py, std::vector<CellSample>& samples,
                   const std::array<int, 4>& children) const {
    if (samples[static_cast<std::size_t>(children[0])].level >= m_depth) return;
    if (!geometry_differs(samples, children)) return;
    for (int child : children) refine_cell(ctx, px, py, samples, split(ctx, px, py, samples, child));
  }

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

  // Pixels whose neighbourhood differs, and the footprints of objects small enough to fall
  // between base samples, start the refinement.
  std::vector<std::atomic<unsigned char>> claimed(pixels);  // queued or refined
  std::vector<int> seeds;
  if (params.depth > 0) {
    std::vector<unsigned char> flagged(pixels, 0);
    workers.for_each(h, [&](int y, const TraceContext&) {
      for (int x = 0; x < w; ++x) flagged[renderer.index(x, y)] = renderer.neighbourhood_differs(x, y) ? 1 : 0;
    });
    for (const PixelRect& r :
         detail::small_object_footprints(scene, renderer.camera(), w, h, params.small_object_pixels)) {
      for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) flagged[renderer.index(x, y)] = 1;
      }
    }
    for (std::size_t i = 0; i < pixels; ++i) {
      if (flagged[i]) {
        seeds.push_back(static_cast<int>(i));
        claimed[i].store(1, std::memory_order_relaxed);
      }
    }
  }
  total.fetch_add(static_cast<long>(seeds.size()), std::memory_order_relaxed);
  // Refinement spreads: a refined pixel whose own samples differ queues its unrefined
  // neighbours, so a thin line missed by the base samples is followed from wherever it was
  // found. The set refined is the closure of the seeds under that rule, whatever the order the
  // workers take pixels in, and each pixel's samples depend only on the pixel: the image is
  // deterministic.
  workers.for_each_growing(seeds, kBatch, [&](int i, const TraceContext& ctx, auto&& add) {
    thread_local std::vector<CellSample> samples;
    const int px = i % w;
    const int py = i / w;
    bool differs = false;
    counts[static_cast<std::size_t>(i)] =
        static_cast<std::uint32_t>(renderer.refine_pixel(ctx, px, py, samples, differs));
    if (differs) {
      for (int y = std::max(0, py - 1); y <= std::min(h - 1, py + 1); ++y) {
        for (int x = std::max(0, px - 1); x <= std::min(w - 1, px + 1); ++x) {
          const std::size_t j = renderer.index(x, y);
          unsigned char expected = 0;
          if (claimed[j].compare_exchange_strong(expected, 1, std::memory_order_relaxed)) {
            total.fetch_add(1, std::memory_order_relaxed);
            add(static_cast<int>(j));
          }
        }
      }
    }
    progress(1);
  });

  return detail::finish_render(workers, start, std::move(counts));
}

}  // namespace raylab
