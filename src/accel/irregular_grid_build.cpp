// Building the irregular grid: the parameters, the lattice, and the virtual grid (top cells by
// the density rule, each cut into 2^s cells per axis by its own primitive count). Merging and
// expansion are in irregular_grid_build_merge.cpp and irregular_grid_build_expand.cpp.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "grid_insert.h"
#include "irregular_grid_build.h"
#include "raylab/accel/uniform_grid.h"
#include "raylab/core/error.h"
#include "raylab/geometry/overlap.h"

namespace raylab {
namespace {

void check_config(const IrregularGridConfig& c) {
  auto positive = [](float x) { return x > 0.f && std::isfinite(x); };
  if (!positive(c.top_density) || !positive(c.sub_density)) {
    throw UsageError("irregular grid densities must be positive numbers (got " + std::to_string(c.top_density) + ", " +
                     std::to_string(c.sub_density) + ")");
  }
  if (!(c.step_cost >= 0.f) || !(c.prim_cost >= 0.f) || !std::isfinite(c.step_cost + c.prim_cost)) {
    throw UsageError("irregular grid cost constants must be finite and >= 0");
  }
  if (c.max_shift < 1 || c.max_shift > 6 || c.max_depth < 0 || c.max_depth > 16 || c.merge_rounds < 0 ||
      c.expand_rounds < 0) {
    throw UsageError("irregular grid: max_shift must be in [1, 6], max_depth in [0, 16], rounds >= 0");
  }
}

// Top cells are cut into 2^s cells per axis by the count rule (the paper's second level). Cells
// of that level that still hold many references are halved again and again, like octree cells
// (2 x 2 x 2), as long as it pays: this is what reaches down to a small dense object in a big
// scene. Halving is kept for the deeper levels because the cut at a mesh vertex, where many
// triangles meet, never stops paying by the test count alone, and each level of 2^s cells per
// axis around it would add 8^s cells; halves add 8.

// A cell holding this many references or fewer is not halved (the octree's K: a mesh vertex is
// shared by about six triangles).
constexpr std::size_t kSplitMinRefs = 8;

// A halving is kept only when the eight halves together hold fewer than this many times the
// parent's references. A ray through the parent meets a given half with probability about 1/4,
// so the split is expected to leave it sum(halves) / 4 tests instead of n. The octree allows 3n
// (kOctreeSplitGainRatio), but here the rule is applied level after level down to 16 levels
// and the references compound: on spd:gears 3n gave 316 B/prim and a 1.5 s build, 2n gives
// 126 B/prim and 0.45 s for about the same trace speed (docs/accelerators.md, "Irregular grid").
constexpr double kSplitGainRatio = 2.0;

// A top cell's cut is kept unless its children hold this many times the cell's references: only
// primitives that the cut cannot separate at all (a thousand coincident triangles, each in dozens
// of the children) reach it, and for them a cut multiplies the work of everything below.
constexpr double kTopSplitLimitRatio = 8.0;

// One top cell's share of the virtual grid, built on its own thread and spliced in afterwards.
struct Local {
  std::vector<std::array<std::uint16_t, 6>> boxes;  // per cell
  std::vector<std::uint32_t> counts;                // references per cell
  std::vector<std::uint32_t> refs;                  // cell by cell
  std::vector<IrregularGridData::Node> nodes;       // begin: into `map`
  std::vector<std::uint32_t> map;                   // leaves: local cell indices; else local nodes
};

// Cuts cells recursively, by the count rule, into 2^s cells per axis.
class Subdivider {
 public:
  Subdivider(const Geometry& geometry, const IrregularGridData& data, const IrregularGridConfig& config, Vec3 margin)
      : m_geometry(geometry), m_data(data), m_config(config), m_margin(margin) {}

  // The map entry for the cell with lattice corner `lo`, 2^level steps per axis, holding `refs`
  // (slots, ascending); `top`: it is a top cell.
  std::uint32_t build(const int lo[3], int level, std::vector<std::uint32_t> refs, bool top, Local& out) const {
    const std::size_t n = refs.size();
    int s = 0;
    if (n > 0 && (top || n > kSplitMinRefs)) {
      const double want = std::round(std::log2(double(m_config.sub_density) * double(n)) / 3.0);
      s = static_cast<int>(std::clamp(want, 0.0, double(std::min(m_config.max_shift, level))));
    }
    std::vector<std::vector<std::uint32_t>> children;
    // Below the top, a cut is kept only under kSplitGainRatio * n references in all, so the split
    // can stop counting once it reaches that: a thousand coincident triangles, each in dozens of
    // the 512 children of a cut, took 147 s to build when every cut was counted to the end.
    const std::size_t limit = static_cast<std::size_t>((top ? kTopSplitLimitRatio : kSplitGainRatio) * double(n));
    while (s > 0) {
      if (split(lo, level, s, refs, limit, children)) break;
      // No gain: primitives this big for the children (a fan around a vertex) are halved at
      // most, and left alone when even that does not pay.
      s = s > 1 ? 1 : 0;
    }
    if (s == 0) {
      const int size = 1 << level;
      out.boxes.push_back({std::uint16_t(lo[0]), std::uint16_t(lo[1]), std::uint16_t(lo[2]),
                           std::uint16_t(lo[0] + size), std::uint16_t(lo[1] + size), std::uint16_t(lo[2] + size)});
      out.counts.push_back(static_cast<std::uint32_t>(n));
      out.refs.insert(out.refs.end(), refs.begin(), refs.end());
      return static_cast<std::uint32_t>(out.boxes.size() - 1) | IrregularGridData::kLeaf;
    }
    refs = {};  // the children hold them now
    const int m = 1 << s, child_level = level - s;
    const auto node = static_cast<std::uint32_t>(out.nodes.size());
    const auto block = static_cast<std::uint32_t>(out.map.size());
    out.nodes.push_back({block, static_cast<std::uint32_t>(s)});
    out.map.resize(block + std::size_t(m) * m * m);
    for (int l = 0; l < m * m * m; ++l) {
      const int corner[3] = {lo[0] + ((l & (m - 1)) << child_level), lo[1] + (((l >> s) & (m - 1)) << child_level),
                             lo[2] + ((l >> (2 * s)) << child_level)};
      const std::uint32_t entry = build(corner, child_level, std::move(children[l]), false, out);
      out.map[block + l] = entry;
    }
    return node;
  }

 private:
  // The references of each of the m^3 children (x fastest) of the cell, ascending, into
  // `children`; false (and `children` incomplete) as soon as they reach `limit` in all.
  bool split(const int lo[3], int level, int s, const std::vector<std::uint32_t>& refs, std::size_t limit,
             std::vector<std::vector<std::uint32_t>>& children) const {
    const int m = 1 << s, stride = 1 << (level - s);
    std::array<std::vector<float>, 3> planes;
    Vec3 inv;
    for (int a = 0; a < 3; ++a) {
      planes[a].resize(m + 1);
      for (int j = 0; j <= m; ++j) planes[a][j] = m_data.plane(a, lo[a] + j * stride);
      inv[a] = m_data.inv_step[a] / float(stride);
    }
    const Vec3 margin = m_margin;
    children.assign(std::size_t(m) * m * m, {});
    std::size_t total = 0;
    for (const std::uint32_t slot : refs) {  // ascending, so every child's list is too
      const std::uint32_t id = m_data.ids[slot];
      const Box3 b = m_geometry.bounds(id);
      AxisRange r[3];
      for (int a = 0; a < 3; ++a) {
        const float* p = planes[a].data();
        r[a] = cells_touching(AxisPlanes{[p](int i) { return p[i]; }, m, inv[a]}, margin[a], b.lo[a], b.hi[a]);
      }
      // A primitive whose box touches one child only lies in it (it touches the parent, which
      // the enlarged children cover): no test needed.
      const bool single = r[0].first == r[0].last && r[1].first == r[1].last && r[2].first == r[2].last;
      for (int z = r[2].first; z <= r[2].last; ++z) {
        for (int y = r[1].first; y <= r[1].last; ++y) {
          for (int x = r[0].first; x <= r[0].last; ++x) {
            if (!single) {
              const Box3 cell{{planes[0][x] - margin.x, planes[1][y] - margin.y, planes[2][z] - margin.z},
                              {planes[0][x + 1] + margin.x, planes[1][y + 1] + margin.y, planes[2][z + 1] + margin.z}};
              if (!overlaps_box(m_geometry, id, cell)) continue;
            }
            children[x + (y << s) + (z << (2 * s))].push_back(slot);
            if (++total >= limit) return false;
          }
        }
      }
    }
    return true;
  }

  const Geometry& m_geometry;
  const IrregularGridData& m_data;
  const IrregularGridConfig& m_config;
  Vec3 m_margin;
};

// Puts data.ids in Morton order of the primitives' box centres (10 bits per axis over the scene
// box), ties by id, so that the result does not depend on the order the ids came in.
void order_spatially(const Geometry& geometry, IrregularGridData& data) {
  const Vec3 lo = data.bounds.lo, extent = data.bounds.extent();
  auto spread = [](std::uint64_t v) {  // the 10 bits of v to every third bit
    v = (v | (v << 16)) & 0x030000FFull;
    v = (v | (v << 8)) & 0x0300F00Full;
    v = (v | (v << 4)) & 0x030C30C3ull;
    v = (v | (v << 2)) & 0x09249249ull;
    return v;
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(data.ids.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, keyed.size(), 1024), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const Vec3 c = geometry.bounds(data.ids[i]).center();
      std::uint64_t key = 0;
      for (int a = 0; a < 3; ++a) {
        const float f = extent[a] > 0.f ? (c[a] - lo[a]) / extent[a] * 1023.f : 0.f;
        const auto q = static_cast<std::uint64_t>(f >= 0.f ? std::min(f, 1023.f) : 0.f);  // NaN -> 0
        key |= spread(q) << a;
      }
      keyed[i] = {key, data.ids[i]};
    }
  });
  tbb::parallel_sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < keyed.size(); ++i) data.ids[i] = keyed[i].second;
}

}  // namespace

IrregularBuildCells build_virtual_grid(const Geometry& geometry, IrregularGridData& data,
                                       const IrregularGridConfig& config) {
  IrregularBuildCells out;
  const auto count = static_cast<std::uint32_t>(data.ids.size());
  std::array<int, 3> res = grid_resolution(data.bounds, count, config.top_density);
  const Vec3 extent = data.bounds.extent();
  for (int a = 0; a < 3; ++a) {
    if (!(extent[a] > 0.f)) res[a] = 1;
    res[a] = std::min(res[a], kIrregularMaxLattice);
  }
  // Coordinates are 16-bit: fewer levels below the top cells until the lattice fits.
  int depth = config.max_depth;
  while (depth > 0 && std::max({res[0], res[1], res[2]}) << depth > kIrregularMaxLattice) --depth;
  data.top_res = res;
  data.depth = depth;

  // The lattice: plane k at origin + k * step, the step rounded up until the last plane reaches
  // the box's upper face, so the lattice covers every primitive.
  float scale = 0.f;
  for (int a = 0; a < 3; ++a) scale = std::max({scale, std::fabs(data.bounds.lo[a]), std::fabs(data.bounds.hi[a])});
  Vec3 margin;
  data.origin = data.bounds.lo;
  for (int a = 0; a < 3; ++a) {
    const int n = res[a] << depth;
    data.lattice[a] = n;
    float step = extent[a] / float(n);
    while (data.bounds.lo[a] + float(n) * step < data.bounds.hi[a]) step = std::nextafter(step, INFINITY);
    data.step[a] = step;
    data.inv_step[a] = step > 0.f ? 1.f / step : 0.f;
    // One margin for every level, so a primitive touching an enlarged cell always touches its
    // enlarged parent and reaches the level below.
    margin[a] = grid_margin(step, scale);
  }

  // Top level: which top cells each primitive overlaps (counted, then filled).
  std::array<std::vector<float>, 3> top_planes;
  Vec3 top_inv;
  for (int a = 0; a < 3; ++a) {
    top_planes[a].resize(res[a] + 1);
    for (int i = 0; i <= res[a]; ++i) top_planes[a][i] = data.plane(a, i << depth);
    top_inv[a] = data.inv_step[a] / float(1 << depth);
  }
  const std::size_t nx = res[0], nxy = nx * res[1], top_cells = nxy * res[2];
  auto for_each_top_cell = [&](std::uint32_t slot, auto&& visit) {
    const std::uint32_t id = data.ids[slot];
    const Box3 b = geometry.bounds(id);
    AxisRange r[3];
    for (int a = 0; a < 3; ++a) {
      if (!(b.lo[a] <= b.hi[a])) return;  // NaN or empty: a degenerate primitive no ray hits
      const float* p = top_planes[a].data();
      r[a] = cells_touching(AxisPlanes{[p](int i) { return p[i]; }, res[a], top_inv[a]}, margin[a], b.lo[a], b.hi[a]);
      if (r[a].first > r[a].last) return;
    }
    const bool single = r[0].first == r[0].last && r[1].first == r[1].last && r[2].first == r[2].last;
    for (int z = r[2].first; z <= r[2].last; ++z) {
      for (int y = r[1].first; y <= r[1].last; ++y) {
        for (int x = r[0].first; x <= r[0].last; ++x) {
          if (!single) {
            const Box3 cell{
                {top_planes[0][x] - margin.x, top_planes[1][y] - margin.y, top_planes[2][z] - margin.z},
                {top_planes[0][x + 1] + margin.x, top_planes[1][y + 1] + margin.y, top_planes[2][z + 1] + margin.z}};
            if (!overlaps_box(geometry, id, cell)) continue;
          }
          visit(x + nx * y + nxy * z);
        }
      }
    }
  };
  std::vector<std::uint32_t> top_begin(top_cells + 1, 0u);
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, count, 256), [&](const auto& r) {
    for (std::uint32_t i = r.begin(); i != r.end(); ++i) {
      for_each_top_cell(i, [&](std::size_t c) {
        std::atomic_ref<std::uint32_t>(top_begin[c + 1]).fetch_add(1, std::memory_order_relaxed);
      });
    }
  });
  for (std::size_t c = 1; c <= top_cells; ++c) top_begin[c] += top_begin[c - 1];
  std::vector<std::uint32_t> top_refs(top_begin[top_cells]);
  {
    std::vector<std::uint32_t> cursor(top_begin.begin(), top_begin.end() - 1);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, count, 256), [&](const auto& r) {
      for (std::uint32_t i = r.begin(); i != r.end(); ++i) {
        for_each_top_cell(i, [&](std::size_t c) {
          top_refs[std::atomic_ref<std::uint32_t>(cursor[c]).fetch_add(1, std::memory_order_relaxed)] = i;
        });
      }
    });
  }

  // Below the top cells, each on its own, in parallel.
  const Subdivider subdivider(geometry, data, config, margin);
  std::vector<Local> locals(top_cells);
  data.top.resize(top_cells);
  tbb::parallel_for(std::size_t{0}, top_cells, [&](std::size_t t) {
    std::vector<std::uint32_t> refs(top_refs.begin() + top_begin[t], top_refs.begin() + top_begin[t + 1]);
    std::sort(refs.begin(), refs.end());
    const int corner[3] = {int(t % nx) << depth, int((t / nx) % res[1]) << depth, int(t / nxy) << depth};
    data.top[t] = subdivider.build(corner, depth, std::move(refs), true, locals[t]);
  });

  // Splice the top cells' shares together: cells, references, nodes and map, in top cell order.
  std::vector<std::size_t> cell_off(top_cells + 1, 0), node_off(top_cells + 1, 0), map_off(top_cells + 1, 0),
      ref_off(top_cells + 1, 0);
  for (std::size_t t = 0; t < top_cells; ++t) {
    cell_off[t + 1] = cell_off[t] + locals[t].boxes.size();
    node_off[t + 1] = node_off[t] + locals[t].nodes.size();
    map_off[t + 1] = map_off[t] + locals[t].map.size();
    ref_off[t + 1] = ref_off[t] + locals[t].refs.size();
  }
  if (cell_off[top_cells] >= IrregularGridData::kLeaf || node_off[top_cells] >= IrregularGridData::kLeaf ||
      map_off[top_cells] >= IrregularGridData::kLeaf || ref_off[top_cells] >= IrregularGridData::kLeaf) {
    throw UsageError("irregular grid: too many cells or references");
  }
  const std::size_t cells = cell_off[top_cells];
  out.boxes.resize(cells);
  out.begin.resize(cells + 1);
  out.refs.resize(ref_off[top_cells]);
  data.nodes.resize(node_off[top_cells]);
  data.map.resize(map_off[top_cells]);
  tbb::parallel_for(std::size_t{0}, top_cells, [&](std::size_t t) {
    const Local& l = locals[t];
    auto relocate = [&](std::uint32_t e) {
      return (e & IrregularGridData::kLeaf)
                 ? std::uint32_t((e & ~IrregularGridData::kLeaf) + cell_off[t]) | IrregularGridData::kLeaf
                 : std::uint32_t(e + node_off[t]);
    };
    data.top[t] = relocate(data.top[t]);
    for (std::size_t i = 0; i < l.map.size(); ++i) data.map[map_off[t] + i] = relocate(l.map[i]);
    for (std::size_t i = 0; i < l.nodes.size(); ++i) {
      data.nodes[node_off[t] + i] = {std::uint32_t(l.nodes[i].begin + map_off[t]), l.nodes[i].shift};
    }
    std::copy(l.boxes.begin(), l.boxes.end(), out.boxes.begin() + cell_off[t]);
    std::copy(l.refs.begin(), l.refs.end(), out.refs.begin() + ref_off[t]);
    std::uint32_t at = static_cast<std::uint32_t>(ref_off[t]);
    for (std::size_t i = 0; i < l.counts.size(); ++i) {
      out.begin[cell_off[t] + i] = at;
      at += l.counts[i];
    }
  });
  out.begin[cells] = static_cast<std::uint32_t>(out.refs.size());
  return out;
}

IrregularGridData build_irregular_grid(const Geometry& geometry, std::span<const std::uint32_t> ids,
                                       const IrregularGridConfig& config) {
  check_config(config);
  IrregularGridData data;
  data.ids.assign(ids.begin(), ids.end());
  for (std::uint32_t id : data.ids) data.bounds.extend(geometry.bounds(id));
  if (data.ids.empty() || data.bounds.empty()) return data;  // no cells: every ray misses
  order_spatially(geometry, data);

  IrregularBuildCells cells = build_virtual_grid(geometry, data, config);
  merge_cells(cells, data, config);
  data.cells = expand_cells(cells, data, config);
  data.refs = std::move(cells.refs);
  data.boxes = std::move(cells.boxes);
  std::size_t nonempty = 0;
  for (std::size_t c = 0; c + 1 < cells.begin.size(); ++c) nonempty += cells.begin[c] != cells.begin[c + 1];
  data.nonempty_cells = nonempty;
  return data;
}

}  // namespace raylab
