// The lecture's adaptive supersampling: rays through the pixel corners first, subdivision where
// the corner colours differ, area-weighted cell colours.

#include <atomic>
#include <chrono>
#include <cmath>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/render/adaptive.h"
#include "raylab/sampling/seed_salts.h"
#include "render_workers.h"
#include "sample_contrast.h"

namespace raylab {
namespace {

using detail::PixelRect;
using detail::TileGrid;

// Deepest subdivision: 2^8 x 2^8 cells in a pixel is already far beyond any useful budget.
constexpr int kMaxDepth = 8;

// The traced points of one pixel on its (2^depth + 1)^2 lattice; reused across pixels.
class PixelLattice {
 public:
  explicit PixelLattice(int n) : m_n(n), m_points(std::size_t(n + 1) * (n + 1)), m_valid(m_points.size(), 0) {}

  void clear() {
    std::fill(m_valid.begin(), m_valid.end(), 0);
    m_count = 0;
  }
  bool has(int i, int j) const { return m_valid[index(i, j)] != 0; }
  const Color& at(int i, int j) const { return m_points[index(i, j)]; }
  void set(int i, int j, Color p) {
    const std::size_t k = index(i, j);
    m_count += m_valid[k] ? 0 : 1;
    m_points[k] = p;
    m_valid[k] = 1;
  }
  int count() const { return m_count; }

 private:
  std::size_t index(int i, int j) const { return std::size_t(j) * (m_n + 1) + i; }
  int m_n;
  std::vector<Color> m_points;
  std::vector<unsigned char> m_valid;
  int m_count = 0;
};

class CornerRenderer {
 public:
  CornerRenderer(const Scene& scene, Film& film, const AdaptiveParams& params)
      : m_scene(scene),
        m_film(film),
        m_camera(scene.camera, film.width(), film.height()),
        m_depth(std::clamp(params.depth, 0, kMaxDepth)),
        m_n(1 << m_depth),
        m_threshold(params.threshold),
        m_corners(std::size_t(film.width() + 1) * (film.height() + 1)) {}

  // A point on the global lattice (2^depth points per pixel side): its random choices (area
  // lights) are seeded by its position, so a point shared by two pixels has one colour.
  Color trace(const TraceContext& ctx, long gx, long gy) const {
    const float scale = 1.f / static_cast<float>(m_n);
    return detail::trace_image_position(
        ctx, m_camera, static_cast<float>(gx) * scale, static_cast<float>(gy) * scale,
        hash_seed(m_scene.settings.seed ^ kAdaptiveCornersPathSalt, static_cast<std::uint64_t>(gx),
                  static_cast<std::uint64_t>(gy), static_cast<std::uint64_t>(m_n)));
  }

  // Corners of tile `r`: those at (x, y) with x0 <= x < x1 and y0 <= y < y1, plus the image's
  // last corner column and row for the tiles that touch them, so every corner is traced once.
  void trace_corners(const TraceContext& ctx, const PixelRect& r) {
    const int w = m_film.width();
    const int h = m_film.height();
    const int x_end = r.x1 == w ? w + 1 : r.x1;
    const int y_end = r.y1 == h ? h + 1 : r.y1;
    for (int y = r.y0; y < y_end; ++y) {
      for (int x = r.x0; x < x_end; ++x) {
        m_corners[std::size_t(y) * (w + 1) + x] = trace(ctx, long(x) * m_n, long(y) * m_n);
      }
    }
  }

  // Colour of pixel (px, py); returns the number of lattice points it used.
  int shade_pixel(const TraceContext& ctx, PixelLattice& lattice, int px, int py) {
    lattice.clear();
    const int w = m_film.width();
    auto corner = [&](int x, int y) { return m_corners[std::size_t(y) * (w + 1) + x]; };
    lattice.set(0, 0, corner(px, py));
    lattice.set(m_n, 0, corner(px + 1, py));
    lattice.set(0, m_n, corner(px, py + 1));
    lattice.set(m_n, m_n, corner(px + 1, py + 1));
    const Color sum = cell(ctx, lattice, px, py, 0, 0, m_n);
    m_film.at(px, py) = sum * (1.f / (static_cast<float>(m_n) * static_cast<float>(m_n)));
    return lattice.count();
  }

 private:
  const Color& point(const TraceContext& ctx, PixelLattice& lattice, int px, int py, int i, int j) {
    if (!lattice.has(i, j)) lattice.set(i, j, trace(ctx, long(px) * m_n + i, long(py) * m_n + j));
    return lattice.at(i, j);
  }

  // Area-weighted colour (in lattice-cell units) of the cell with corner (i, j) and side `s`.
  Color cell(const TraceContext& ctx, PixelLattice& lattice, int px, int py, int i, int j, int s) {
    const Color& a = lattice.at(i, j);
    const Color& b = lattice.at(i + s, j);
    const Color& c = lattice.at(i, j + s);
    const Color& d = lattice.at(i + s, j + s);
    detail::ContrastRange range;
    range.add(a);
    range.add(b);
    range.add(c);
    range.add(d);
    const float area = static_cast<float>(s) * static_cast<float>(s);
    if (s == 1 || range.contrast() <= m_threshold) return (a + b + c + d) * (0.25f * area);
    const int h = s / 2;
    // The four edge midpoints and the centre (those already traced by a neighbour are reused).
    point(ctx, lattice, px, py, i + h, j);
    point(ctx, lattice, px, py, i, j + h);
    point(ctx, lattice, px, py, i + s, j + h);
    point(ctx, lattice, px, py, i + h, j + s);
    point(ctx, lattice, px, py, i + h, j + h);
    return cell(ctx, lattice, px, py, i, j, h) + cell(ctx, lattice, px, py, i + h, j, h) +
           cell(ctx, lattice, px, py, i, j + h, h) + cell(ctx, lattice, px, py, i + h, j + h, h);
  }

  const Scene& m_scene;
  Film& m_film;
  Camera m_camera;
  int m_depth;
  int m_n;  // lattice points per pixel side, 2^depth
  float m_threshold;
  std::vector<Color> m_corners;  // (width + 1) x (height + 1), shared by neighbouring pixels
};

}  // namespace

RenderResult render_adaptive_corners(const Scene& scene, const Accelerator& accel, Film& film,
                                     const RenderOptions& options, const AdaptiveParams& params) {
  CornerRenderer renderer(scene, film, params);
  const TileGrid grid(film.width(), film.height(), options.tile_size);
  detail::RenderWorkers workers(scene, accel, options);
  std::vector<std::uint32_t> counts(std::size_t(film.width()) * film.height());
  const int lattice_side = 1 << std::clamp(params.depth, 0, kMaxDepth);
  std::atomic<int> done{0};
  const int total = 2 * grid.count();
  auto progress = [&] {
    const int d = done.fetch_add(1, std::memory_order_relaxed) + 1;
    if (options.on_progress) options.on_progress(d, total);
  };

  const auto start = std::chrono::steady_clock::now();
  workers.for_each(grid.count(), [&](int t, const TraceContext& ctx) {
    renderer.trace_corners(ctx, grid.rect(t));
    progress();
  });
  workers.for_each(grid.count(), [&](int t, const TraceContext& ctx) {
    thread_local std::unique_ptr<PixelLattice> lattice;
    thread_local int lattice_n = -1;
    if (lattice_n != lattice_side) {
      lattice = std::make_unique<PixelLattice>(lattice_side);
      lattice_n = lattice_side;
    }
    const PixelRect r = grid.rect(t);
    for (int py = r.y0; py < r.y1; ++py) {
      for (int px = r.x0; px < r.x1; ++px) {
        counts[std::size_t(py) * film.width() + px] =
            static_cast<std::uint32_t>(renderer.shade_pixel(ctx, *lattice, px, py));
      }
    }
    progress();
  });

  return detail::finish_render(workers, start, std::move(counts));
}

}  // namespace raylab
