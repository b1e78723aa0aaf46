// Building the uniform grid: the resolution rule, the cell planes, the primitives' spatial order,
// the two insertion passes (count the cells each primitive overlaps, then fill the reference
// array), and the empty-space distances.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "grid_distance.h"
#include "grid_insert.h"
#include "grid_walk.h"
#include "leaf_test.h"
#include "mailbox.h"
#include "raylab/accel/uniform_grid.h"
#include "raylab/core/error.h"
#include "raylab/core/stopwatch.h"

namespace raylab {
namespace {

// Primitive references are 32-bit offsets; a grid needing more is rebuilt coarser.
constexpr std::uint64_t kMaxReferences = std::numeric_limits<std::uint32_t>::max();

}  // namespace

std::array<int, 3> grid_resolution(const Box3& box, std::size_t count, float density) {
  std::array<int, 3> n{1, 1, 1};
  if (count == 0 || box.empty() || !(density > 0.f)) return n;
  const Vec3 e = box.extent();
  const double target = double(density) * double(count);
  bool free[3];
  for (int a = 0; a < 3; ++a) free[a] = e[a] > 0.f && std::isfinite(e[a]);
  // Solve the rule over the free axes; an axis that would get less than one cell is flat for
  // this density: it gets one, and the others share the target again.
  double r[3] = {1.0, 1.0, 1.0};
  int k = 0;
  for (;;) {
    double volume = 1.0;
    k = 0;
    for (int a = 0; a < 3; ++a) {
      if (free[a]) volume *= e[a], ++k;
    }
    if (k == 0) return n;
    const double scale = std::pow(target / volume, 1.0 / k);
    int thinnest = -1;
    double smallest = 1.0;
    for (int a = 0; a < 3; ++a) {
      r[a] = free[a] ? double(e[a]) * scale : 1.0;
      if (free[a] && r[a] < smallest) thinnest = a, smallest = r[a];
    }
    if (thinnest < 0) break;
    free[thinnest] = false;
  }
  double cells = 1.0;
  for (int a = 0; a < 3; ++a) cells *= std::max(1.0, std::round(r[a]));
  const auto cap = static_cast<double>(kGridMaxCells);
  if (cells > cap) {
    // Scale the free axes down together, rounding down, then trim the largest until it fits.
    double product = 1.0;
    for (int a = 0; a < 3; ++a) product *= r[a];
    const double shrink = std::pow(cap / product, 1.0 / k);
    for (int a = 0; a < 3; ++a) n[a] = free[a] ? static_cast<int>(std::max(1.0, std::floor(r[a] * shrink))) : 1;
    while (double(n[0]) * n[1] * n[2] > cap) {
      const int a = int(std::max_element(n.begin(), n.end()) - n.begin());
      n[a] = std::max(1, n[a] - std::max(1, n[a] / 64));
    }
    return n;
  }
  for (int a = 0; a < 3; ++a) n[a] = static_cast<int>(std::max(1.0, std::round(r[a])));
  return n;
}

UniformGrid::UniformGrid(const Geometry& geometry, const GridConfig& config)
    : UniformGrid(geometry, geometry.primitive_ids(), config) {}

UniformGrid::UniformGrid(const Geometry& geometry, std::span<const std::uint32_t> ids, const GridConfig& config)
    : UniformGrid(geometry, ids, {0, 0, 0}, config) {}

UniformGrid::UniformGrid(const Geometry& geometry, std::span<const std::uint32_t> ids, std::array<int, 3> resolution,
                         const GridConfig& config)
    : m_geometry(geometry), m_config(config), m_ids(ids.begin(), ids.end()) {
  if (!(config.density > 0.f) || !std::isfinite(config.density)) {
    throw UsageError("grid density must be a positive number (got " + std::to_string(config.density) + ")");
  }
  const auto start = std::chrono::steady_clock::now();
  build(resolution);
  m_build_seconds = seconds_since(start);
}

UniformGrid::~UniformGrid() = default;

void UniformGrid::build(std::array<int, 3> resolution) {
  // Ascending first, so that nothing below depends on the order `ids` came in (order_by_cell
  // then makes the order spatial, ties by id).
  std::sort(m_ids.begin(), m_ids.end());
  for (std::uint32_t id : m_ids) m_bounds.extend(m_geometry.bounds(id));
  if (m_ids.empty() || m_bounds.empty()) {
    m_offsets.assign(1, 0u);  // no cells; traversal returns before looking at them
    return;
  }
  const bool automatic = resolution[0] <= 0 || resolution[1] <= 0 || resolution[2] <= 0;
  if (automatic) resolution = grid_resolution(m_bounds, m_ids.size(), m_config.density);
  const Vec3 extent = m_bounds.extent();
  for (int a = 0; a < 3; ++a) {
    if (!(extent[a] > 0.f)) resolution[a] = 1;  // a flat axis: more cells would all be the same cell
  }

  float scale = 0.f;
  for (int a = 0; a < 3; ++a) scale = std::max({scale, std::fabs(m_bounds.lo[a]), std::fabs(m_bounds.hi[a])});
  const auto count = static_cast<std::uint32_t>(m_ids.size());

  for (;;) {
    // Plane positions, stored so that the build's cell boxes and the traversal's boundary
    // distances use the very same floats. The last plane is the box's upper face exactly.
    Vec3 margin;
    for (int a = 0; a < 3; ++a) {
      const int n = resolution[a];
      const float cell = extent[a] / float(n);
      m_cell[a] = cell;
      m_inv_cell[a] = cell > 0.f ? float(n) / extent[a] : 0.f;
      m_planes[a].resize(n + 1);
      for (int i = 0; i <= n; ++i) m_planes[a][i] = grid_plane(m_bounds.lo[a], m_bounds.hi[a], cell, i, n);
      margin[a] = grid_margin(cell, scale);
    }
    const std::size_t nx = resolution[0], nxy = nx * std::size_t(resolution[1]);
    const std::size_t cells = nxy * std::size_t(resolution[2]);
    order_by_cell(resolution);

    // Calls visit(cell index) for every cell that primitive `local` overlaps (enlarged boxes).
    auto planes_of = [&](int a) {
      const float* p = m_planes[a].data();
      return AxisPlanes{[p](int i) { return p[i]; }, resolution[a], m_inv_cell[a]};
    };
    const std::array axes{planes_of(0), planes_of(1), planes_of(2)};
    auto for_each_cell = [&](std::uint32_t local, auto&& visit) {
      const std::uint32_t id = m_ids[local];
      for_each_overlapped_cell(m_geometry, id, m_geometry.bounds(id), axes, margin,
                               [&](int x, int y, int z) { visit(x + nx * y + nxy * z); });
    };

    // Pass 1: how many references each cell gets (counted in m_offsets[c + 1]).
    m_offsets.assign(cells + 1, 0u);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, count, 64), [&](const auto& r) {
      for (std::uint32_t i = r.begin(); i != r.end(); ++i) {
        for_each_cell(i, [&](std::size_t c) {
          std::atomic_ref<std::uint32_t>(m_offsets[c + 1]).fetch_add(1, std::memory_order_relaxed);
        });
      }
    });
    std::uint64_t total = 0;
    for (std::size_t c = 1; c <= cells; ++c) {
      total += m_offsets[c];
      m_offsets[c] = static_cast<std::uint32_t>(std::min(total, kMaxReferences));
    }
    if (total > kMaxReferences) {
      // Too many references for 32-bit offsets (huge primitives over a fine grid): halve.
      if (resolution == std::array<int, 3>{1, 1, 1}) throw UsageError("uniform grid: too many primitive references");
      for (int& n : resolution) n = std::max(1, n / 2);
      continue;
    }
    m_resolution = resolution;

    // Pass 2: each primitive claims slots in its cells, then each cell is sorted by primitive id,
    // so that the result does not depend on thread scheduling and any-hit queries meet a cell's
    // primitives in id order, as brute force does (scene generators tend to emit big occluders
    // first, which ends shadow rays sooner).
    m_refs.assign(total, 0u);
    std::vector<std::uint32_t> cursor(m_offsets.begin(), m_offsets.end() - 1);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, count, 64), [&](const auto& r) {
      for (std::uint32_t i = r.begin(); i != r.end(); ++i) {
        for_each_cell(i, [&](std::size_t c) {
          m_refs[std::atomic_ref<std::uint32_t>(cursor[c]).fetch_add(1, std::memory_order_relaxed)] = i;
        });
      }
    });
    std::atomic<std::size_t> nonempty{0};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells, 4096), [&](const auto& r) {
      std::size_t local_nonempty = 0;
      for (std::size_t c = r.begin(); c != r.end(); ++c) {
        if (m_offsets[c] == m_offsets[c + 1]) continue;
        ++local_nonempty;
        std::sort(m_refs.begin() + m_offsets[c], m_refs.begin() + m_offsets[c + 1],
                  [&](std::uint32_t a, std::uint32_t b) { return m_ids[a] < m_ids[b]; });
      }
      nonempty += local_nonempty;
    });
    m_nonempty_cells = nonempty;
    fill_skip_distances();
    break;
  }
  // Copies of the triangles and spheres in the grid's own order, which is spatial: the
  // references of one cell then point to neighbouring entries instead of all over the scene.
  copy_slot_primitives(m_geometry, m_ids, m_triangles, m_spheres);
  m_cylinder_frames = CylinderFrames::of(m_geometry, m_ids);
  if (m_config.mailbox) m_mailboxes = std::make_unique<Mailboxes>(count);
}

void UniformGrid::order_by_cell(std::array<int, 3> resolution) {
  order_by_grid_cell(m_geometry, m_ids, m_bounds.lo, m_inv_cell, resolution);
}

void UniformGrid::fill_skip_distances() {
  // With skipping off, every empty cell gets distance 1: the walk never jumps.
  m_skip = chessboard_distances(m_resolution, m_config.skip_empty ? kMaxSkip : 1,
                                [&](std::size_t c) { return m_offsets[c] != m_offsets[c + 1]; });
}

std::vector<std::uint32_t> UniformGrid::cell_primitives(int x, int y, int z) const {
  std::vector<std::uint32_t> out;
  if (m_offsets.size() < 2) return out;  // an empty grid has no cells
  const std::size_t c = x + std::size_t(m_resolution[0]) * (y + std::size_t(m_resolution[1]) * z);
  for (std::uint32_t r = m_offsets[c]; r < m_offsets[c + 1]; ++r) out.push_back(m_ids[m_refs[r]]);
  std::sort(out.begin(), out.end());
  return out;
}

std::size_t UniformGrid::mailbox_bytes_per_thread() const { return m_mailboxes ? m_mailboxes->bytes_per_thread() : 0; }

AccelInfo UniformGrid::info() const {
  AccelInfo info;
  info.name = "grid";
  info.build_seconds = m_build_seconds;
  std::size_t planes = 0;
  for (const auto& p : m_planes) planes += p.size();
  info.memory_bytes = sizeof(*this) + (m_offsets.size() + m_refs.size() + m_ids.size()) * sizeof(std::uint32_t) +
                      planes * sizeof(float) + m_skip.size() + m_triangles.size() * sizeof(Triangle) +
                      m_spheres.size() * sizeof(Sphere) + m_cylinder_frames.bytes();
  info.node_count = m_offsets.size() - 1;
  info.leaf_count = m_nonempty_cells;
  info.primitive_count = m_ids.size();
  info.max_depth = 0;
  return info;
}

}  // namespace raylab
