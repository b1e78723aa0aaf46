// Building the two-level grid by sorting (cell, primitive) pairs, as Kalojanov & Slusallek
// build grids in parallel: the top grid's pairs give each top cell's primitives and so its leaf
// grid's resolution; the leaf grids' pairs, keyed by the leaf grid's offset plus the leaf cell,
// give one reference array with one offset per leaf cell.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "grid_distance.h"
#include "grid_insert.h"
#include "grid_walk.h"
#include "leaf_test.h"
#include "mailbox.h"
#include "raylab/accel/two_level_grid.h"
#include "raylab/accel/uniform_grid.h"
#include "raylab/core/error.h"
#include "raylab/core/stopwatch.h"

namespace raylab {
namespace {

// Pairs are 64-bit keys: the cell in the high half, the primitive in the low half, so that one
// sort orders them by cell and, within a cell, by primitive. Cells, references and leaf
// offsets are 32-bit; a grid needing more is refused.
constexpr std::uint64_t kMax32 = std::numeric_limits<std::uint32_t>::max();

// The exponent of N in the number of top cells (Ize, Shirley & Parker's rule for the top level).
constexpr double kTopExponent = 0.6;

// A primitive spanning at least this fraction of a top cell along two axes goes to the cell's
// list instead of its leaf grid.
constexpr float kBigFraction = 0.5f;

// ...but only when the other primitives' box has at most this fraction of the surface area of
// the box of all of them.
constexpr float kListGain = 0.5f;

// Emits pairs in parallel through emit(local vector, item) for items [0, count), then gathers
// and sorts them.
template <class Emit>
std::vector<std::uint64_t> sorted_pairs(std::size_t count, Emit&& emit) {
  tbb::enumerable_thread_specific<std::vector<std::uint64_t>> local;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 64), [&](const auto& r) {
    std::vector<std::uint64_t>& out = local.local();
    for (std::size_t i = r.begin(); i != r.end(); ++i) emit(out, i);
  });
  std::size_t total = 0;
  for (const auto& v : local) total += v.size();
  std::vector<std::uint64_t> pairs;
  pairs.reserve(total);
  for (const auto& v : local) pairs.insert(pairs.end(), v.begin(), v.end());
  tbb::parallel_sort(pairs.begin(), pairs.end());
  return pairs;
}

void check_density(float value, const char* what) {
  if (!(value > 0.f) || !std::isfinite(value)) {
    throw UsageError(std::string("grid2 ") + what + " must be a positive number (got " + std::to_string(value) + ")");
  }
}

}  // namespace

TwoLevelGrid::TwoLevelGrid(const Geometry& geometry, const TwoLevelGridConfig& config)
    : TwoLevelGrid(geometry, geometry.primitive_ids(), config) {}

TwoLevelGrid::TwoLevelGrid(const Geometry& geometry, std::span<const std::uint32_t> ids,
                           const TwoLevelGridConfig& config)
    : m_geometry(geometry), m_config(config), m_ids(ids.begin(), ids.end()) {
  check_density(config.top_density, "top density");
  check_density(config.leaf_density, "leaf density");
  const auto start = std::chrono::steady_clock::now();
  build();
  m_build_seconds = seconds_since(start);
}

TwoLevelGrid::~TwoLevelGrid() = default;

Vec3 TwoLevelGrid::top_lo(int x, int y, int z) const {
  return {m_top_planes[0][x], m_top_planes[1][y], m_top_planes[2][z]};
}

Vec3 TwoLevelGrid::top_hi(int x, int y, int z) const {
  return {m_top_planes[0][x + 1], m_top_planes[1][y + 1], m_top_planes[2][z + 1]};
}

void TwoLevelGrid::build() {
  // Ascending first, so that nothing below depends on the order `ids` came in.
  std::sort(m_ids.begin(), m_ids.end());
  for (std::uint32_t id : m_ids) m_bounds.extend(m_geometry.bounds(id));
  if (m_ids.empty() || m_bounds.empty()) {
    m_offsets.assign(1, 0u);  // no cells; traversal returns before looking at them
    return;
  }
  const auto count = static_cast<std::uint32_t>(m_ids.size());

  // The top grid: top_density * N^0.6 cells, as near cubes as the box allows.
  const double top_cells = double(m_config.top_density) * std::pow(double(count), kTopExponent);
  std::array<int, 3> res = grid_resolution(m_bounds, count, static_cast<float>(top_cells / count));
  const Vec3 extent = m_bounds.extent();
  float scale = 0.f;
  for (int a = 0; a < 3; ++a) scale = std::max({scale, std::fabs(m_bounds.lo[a]), std::fabs(m_bounds.hi[a])});
  Vec3 margin;
  for (int a = 0; a < 3; ++a) {
    if (!(extent[a] > 0.f)) res[a] = 1;
    const int n = res[a];
    const float cell = extent[a] / float(n);
    m_top_cell[a] = cell;
    m_top_inv_cell[a] = cell > 0.f ? float(n) / extent[a] : 0.f;
    m_top_planes[a].resize(n + 1);
    for (int i = 0; i <= n; ++i) m_top_planes[a][i] = grid_plane(m_bounds.lo[a], m_bounds.hi[a], cell, i, n);
    margin[a] = grid_margin(cell, scale);
  }
  m_top_resolution = res;
  const std::size_t nx = res[0], nxy = nx * std::size_t(res[1]);
  const std::size_t cells = nxy * std::size_t(res[2]);
  order_by_top_cell();

  // Pass 1: a (top cell, slot) pair for every top cell each primitive overlaps.
  auto top_axis = [&](int a) {
    const float* p = m_top_planes[a].data();
    return AxisPlanes{[p](int i) { return p[i]; }, res[a], m_top_inv_cell[a]};
  };
  const std::array top_axes{top_axis(0), top_axis(1), top_axis(2)};
  const std::vector<std::uint64_t> top_pairs = sorted_pairs(count, [&](std::vector<std::uint64_t>& out, std::size_t i) {
    const std::uint32_t id = m_ids[i];
    for_each_overlapped_cell(m_geometry, id, m_geometry.bounds(id), top_axes, margin, [&](int x, int y, int z) {
      out.push_back(std::uint64_t(x + nx * y + nxy * z) << 32 | i);
    });
  });

  // Each top cell's range of pairs. A primitive whose part inside the cell spans at least
  // kBigFraction of the cell along two axes or more is "big": it goes to the cell's list, tested
  // on entry, and the leaf grid covers the box of the other ("small") primitives' parts only,
  // with leaf_density cells per small primitive by the uniform grid's rule.
  std::vector<std::uint32_t> first(cells + 1, 0u);
  for (std::uint64_t p : top_pairs) ++first[(p >> 32) + 1];
  for (std::size_t c = 0; c < cells; ++c) first[c + 1] += first[c];
  std::vector<std::uint8_t> big(top_pairs.size(), 0);
  m_top.assign(cells, TopCell{});
  tbb::parallel_for(std::size_t{0}, cells, [&](std::size_t c) {
    if (first[c] == first[c + 1]) return;
    const int x = int(c % nx), y = int((c / nx) % res[1]), z = int(c / nxy);
    const Box3 cell_box{top_lo(x, y, z), top_hi(x, y, z)};
    const Box3 enlarged{cell_box.lo - margin, cell_box.hi + margin};  // as inserted: never an empty part
    const Vec3 e = cell_box.extent();
    Box3 small_box, all_box;
    std::uint32_t small = 0;
    for (std::uint32_t k = first[c]; k < first[c + 1]; ++k) {
      const Box3 b = m_geometry.bounds(m_ids[top_pairs[k] & kMax32]);
      const Box3 part{max(b.lo, enlarged.lo), min(b.hi, enlarged.hi)};
      all_box.extend(part);
      int spanned = 0;
      for (int a = 0; a < 3; ++a) spanned += part.hi[a] - part.lo[a] >= kBigFraction * e[a];
      if (spanned >= 2) {
        big[k] = 1;
      } else {
        small_box.extend(part);
        ++small;
      }
    }
    // The list pays only where leaving its primitives out shrinks the leaf grid's box (a ray
    // meets a box in proportion to its surface area); elsewhere (the big faces of a gear among
    // its small ones) every primitive stays in the leaf grid, where a ray tests only those near
    // its path.
    if (small > 0 && small < first[c + 1] - first[c] && !(small_box.area() <= kListGain * all_box.area())) {
      for (std::uint32_t k = first[c]; k < first[c + 1]; ++k) big[k] = 0;
      small_box = all_box;
      small = first[c + 1] - first[c];
    }
    if (small == 0 || small_box.empty()) return;
    // Enlarged by the margin, so that clipping the ray to it never loses a primitive in its
    // faces, but never beyond the cell (whose neighbours list what lies beyond).
    TopCell& t = m_top[c];
    for (int a = 0; a < 3; ++a) {
      t.lo[a] = std::max(small_box.lo[a] - margin[a], cell_box.lo[a]);
      t.hi[a] = std::min(small_box.hi[a] + margin[a], cell_box.hi[a]);
    }
    const Box3 leaf_box{t.lo, t.hi};
    t.res = grid_resolution(leaf_box, small, m_config.leaf_density);
    const Vec3 le = leaf_box.extent();
    for (int a = 0; a < 3; ++a) {
      if (!(le[a] > 0.f)) t.res[a] = 1;
      t.cell[a] = le[a] / float(t.res[a]);
      t.inv_cell[a] = t.cell[a] > 0.f ? float(t.res[a]) / le[a] : 0.f;
    }
  });
  // Offsets: per occupied top cell, its list, then its leaf cells.
  std::uint64_t slots = 0;
  m_leaf_cells = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    if (first[c] == first[c + 1]) continue;
    TopCell& t = m_top[c];
    t.list = static_cast<std::uint32_t>(std::min(slots, kMax32));
    const std::uint64_t leaves = std::uint64_t(t.res[0]) * t.res[1] * t.res[2];
    slots += 1 + leaves;
    m_leaf_cells += leaves;
  }
  if (slots >= kMax32) throw UsageError("two-level grid: too many leaf cells (lower --grid2-leaf-density)");

  // Pass 2: a (list or leaf cell, primitive id) pair for every leaf cell each small (top cell,
  // primitive) pair overlaps, and one for the list of each big one. Keyed by the rank of the
  // global id, so that each cell lists its primitives in id order as brute force meets them
  // (the uniform grid's rule for any-hit queries).
  // The rank of each slot's id among all ids (ids themselves may be sparse: a two-level
  // structure's groups have ids from kGroupIdBase up), and the slot of each rank.
  std::vector<std::uint32_t> slot_of_rank(count), rank_of_slot(count);
  for (std::uint32_t i = 0; i < count; ++i) slot_of_rank[i] = i;
  tbb::parallel_sort(slot_of_rank.begin(), slot_of_rank.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return m_ids[a] < m_ids[b]; });
  for (std::uint32_t r = 0; r < count; ++r) rank_of_slot[slot_of_rank[r]] = r;
  const std::vector<std::uint64_t> leaf_pairs =
      sorted_pairs(top_pairs.size(), [&](std::vector<std::uint64_t>& out, std::size_t k) {
        const std::size_t c = top_pairs[k] >> 32;
        const auto slot = static_cast<std::uint32_t>(top_pairs[k] & kMax32);
        const std::uint32_t id = m_ids[slot], rank = rank_of_slot[slot];
        const TopCell& t = m_top[c];
        if (big[k]) {
          out.push_back(std::uint64_t(t.list) << 32 | rank);
          return;
        }
        auto leaf_axis = [&](int a) {
          const float l = t.lo[a], h = t.hi[a], cell = t.cell[a];
          const int n = t.res[a];
          return AxisPlanes{[=](int i) { return grid_plane(l, h, cell, i, n); }, n, t.inv_cell[a]};
        };
        const std::array axes{leaf_axis(0), leaf_axis(1), leaf_axis(2)};
        Vec3 leaf_margin;
        for (int a = 0; a < 3; ++a) leaf_margin[a] = grid_margin(t.cell[a], scale);
        const std::size_t rx = t.res[0], rxy = rx * std::size_t(t.res[1]);
        for_each_overlapped_cell(m_geometry, id, m_geometry.bounds(id), axes, leaf_margin, [&](int i, int j, int l) {
          out.push_back(std::uint64_t(t.list + 1 + i + rx * j + rxy * l) << 32 | rank);
        });
      });
  if (leaf_pairs.size() >= kMax32) throw UsageError("two-level grid: too many primitive references");

  // One offset per list and leaf cell; references are slots (positions in m_ids).
  m_offsets.assign(slots + 1, 0u);
  m_refs.resize(leaf_pairs.size());
  for (std::size_t r = 0; r < leaf_pairs.size(); ++r) {
    ++m_offsets[(leaf_pairs[r] >> 32) + 1];
    m_refs[r] = slot_of_rank[leaf_pairs[r] & kMax32];
  }
  for (std::size_t c = 1; c <= slots; ++c) m_offsets[c] += m_offsets[c - 1];
  m_nonempty_leaf_cells = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const TopCell& t = m_top[c];
    const std::size_t leaves = std::size_t(t.res[0]) * t.res[1] * t.res[2];
    for (std::size_t l = t.list + 1; l < t.list + 1 + leaves; ++l)
      m_nonempty_leaf_cells += m_offsets[l] != m_offsets[l + 1];
  }
  std::vector<std::uint8_t> occupied(cells, 0);
  for (std::size_t c = 0; c < cells; ++c) occupied[c] = first[c] != first[c + 1];

  // Empty-space distances within each leaf grid (lists get 0: the walk never reads them).
  m_leaf_skip.assign(slots, 0);
  tbb::parallel_for(std::size_t{0}, cells, [&](std::size_t c) {
    const TopCell& t = m_top[c];
    if (t.res[0] == 0) return;
    const std::size_t begin = t.list + 1;
    const std::vector<std::uint8_t> d =
        chessboard_distances(t.res, m_config.skip_empty ? kMaxSkip : 1,
                             [&](std::size_t l) { return m_offsets[begin + l] != m_offsets[begin + l + 1]; });
    std::copy(d.begin(), d.end(), m_leaf_skip.begin() + std::ptrdiff_t(begin));
  });

  // Empty-space distances over the top grid (with skipping off, every empty cell gets 1).
  m_top_skip =
      chessboard_distances(res, m_config.skip_empty ? kMaxSkip : 1, [&](std::size_t c) { return occupied[c] != 0; });

  // Copies of the triangles and spheres in the grid's own (spatial) order.
  copy_slot_primitives(m_geometry, m_ids, m_triangles, m_spheres);
  m_cylinder_frames = CylinderFrames::of(m_geometry, m_ids);
  if (m_config.mailbox) m_mailboxes = std::make_unique<Mailboxes>(count);
}

void TwoLevelGrid::order_by_top_cell() {
  order_by_grid_cell(m_geometry, m_ids, m_bounds.lo, m_top_inv_cell, m_top_resolution);
}

Box3 TwoLevelGrid::top_cell_box(int x, int y, int z) const { return {top_lo(x, y, z), top_hi(x, y, z)}; }

std::array<int, 3> TwoLevelGrid::leaf_resolution(int x, int y, int z) const {
  if (m_top.empty()) return {0, 0, 0};
  return m_top[x + std::size_t(m_top_resolution[0]) * (y + std::size_t(m_top_resolution[1]) * z)].res;
}

Box3 TwoLevelGrid::leaf_grid_box(int x, int y, int z) const {
  if (leaf_resolution(x, y, z)[0] == 0) return {};
  const TopCell& t = m_top[x + std::size_t(m_top_resolution[0]) * (y + std::size_t(m_top_resolution[1]) * z)];
  return {t.lo, t.hi};
}

Box3 TwoLevelGrid::leaf_cell_box(int x, int y, int z, int i, int j, int k) const {
  const TopCell& t = m_top[x + std::size_t(m_top_resolution[0]) * (y + std::size_t(m_top_resolution[1]) * z)];
  const int c[3] = {i, j, k};
  Box3 box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = grid_plane(t.lo[a], t.hi[a], t.cell[a], c[a], t.res[a]);
    box.hi[a] = grid_plane(t.lo[a], t.hi[a], t.cell[a], c[a] + 1, t.res[a]);
  }
  return box;
}

namespace {

// The global ids of references [begin, end), ascending.
std::vector<std::uint32_t> ids_of(const std::vector<std::uint32_t>& ids, const std::vector<std::uint32_t>& refs,
                                  std::uint32_t begin, std::uint32_t end) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t r = begin; r < end; ++r) out.push_back(ids[refs[r]]);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

std::vector<std::uint32_t> TwoLevelGrid::leaf_cell_primitives(int x, int y, int z, int i, int j, int k) const {
  if (leaf_resolution(x, y, z)[0] == 0) return {};
  const TopCell& t = m_top[x + std::size_t(m_top_resolution[0]) * (y + std::size_t(m_top_resolution[1]) * z)];
  const std::size_t c = t.list + 1 + i + std::size_t(t.res[0]) * (j + std::size_t(t.res[1]) * k);
  return ids_of(m_ids, m_refs, m_offsets[c], m_offsets[c + 1]);
}

std::vector<std::uint32_t> TwoLevelGrid::top_cell_primitives(int x, int y, int z) const {
  const std::size_t c = x + std::size_t(m_top_resolution[0]) * (y + std::size_t(m_top_resolution[1]) * z);
  if (m_top.empty() || m_top_skip[c] != 0) return {};
  return ids_of(m_ids, m_refs, m_offsets[m_top[c].list], m_offsets[m_top[c].list + 1]);
}

AccelInfo TwoLevelGrid::info() const {
  AccelInfo info;
  info.name = "grid2";
  info.build_seconds = m_build_seconds;
  std::size_t planes = 0;
  for (const auto& p : m_top_planes) planes += p.size();
  info.memory_bytes = sizeof(*this) + (m_offsets.size() + m_refs.size() + m_ids.size()) * sizeof(std::uint32_t) +
                      planes * sizeof(float) + m_top_skip.size() + m_leaf_skip.size() + m_top.size() * sizeof(TopCell) +
                      m_triangles.size() * sizeof(Triangle) + m_spheres.size() * sizeof(Sphere) +
                      m_cylinder_frames.bytes();
  info.node_count = m_top.size() + leaf_cell_count();
  info.leaf_count = m_nonempty_leaf_cells;
  info.primitive_count = m_ids.size();
  info.max_depth = m_top.empty() ? 0 : 1;
  return info;
}

}  // namespace raylab
