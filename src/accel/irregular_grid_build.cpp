// Building the irregular grid: the parameters, the lattice, and the virtual grid (top cells by
// the density rule, each cut into 2^s cells per axis by its own primitive count). Merging and
// expansion are in irregular_grid_build_merge.cpp and irregular_grid_build_expand.cpp.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

#include <tbb/parallel_for.h>

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
    throw UsageError("irregular grid densities must be positive numbers (got " + std::to_string(c.top_density) +
                     ", " + std::to_string(c.sub_density) + ")");
  }
  if (!(c.step_cost >= 0.f) || !(c.prim_cost >= 0.f) || !std::isfinite(c.step_cost + c.prim_cost)) {
    throw UsageError("irregular grid cost constants must be finite and >= 0");
  }
  if (c.max_shift < 0 || c.max_shift > 6 || c.merge_rounds < 0 || c.expand_rounds < 0) {
    throw UsageError("irregular grid: max_shift must be in [0, 6], merge and expand rounds >= 0");
  }
}

// The subdivision level of a top cell holding `count` references: about sub_density * count
// cells, i.e. 2^s = cbrt(sub_density * count) per axis.
int subdivision_level(std::uint32_t count, float sub_density, int max_shift) {
  if (count == 0) return 0;
  const double s = std::round(std::log2(double(sub_density) * count) / 3.0);
  return static_cast<int>(std::clamp(s, 0.0, double(max_shift)));
}

}  // namespace

IrregularBuildCells build_virtual_grid(const Geometry& geometry, IrregularGridData& data,
                                       const IrregularGridConfig& config) {
  IrregularBuildCells out;
  const auto count = static_cast<std::uint32_t>(data.ids.size());
  std::array<int, 3> res = grid_resolution(data.bounds, count, config.top_density);
  const Vec3 extent = data.bounds.extent();
  int shift = config.max_shift;
  for (int a = 0; a < 3; ++a) {
    if (!(extent[a] > 0.f)) res[a] = 1;
    res[a] = std::min(res[a], kIrregularMaxLattice);
  }
  // Coordinates are 16-bit: fewer levels, then fewer top cells, until the lattice fits.
  while (shift > 0 && std::max({res[0], res[1], res[2]}) << shift > kIrregularMaxLattice) --shift;
  data.top_res = res;
  data.max_shift = shift;

  // The lattice planes: every cell boundary of every level is one of these floats, so the
  // build's cell boxes and the traversal's exits agree bit for bit.
  float scale = 0.f;
  for (int a = 0; a < 3; ++a) scale = std::max({scale, std::fabs(data.bounds.lo[a]), std::fabs(data.bounds.hi[a])});
  Vec3 margin;
  for (int a = 0; a < 3; ++a) {
    const int n = res[a] << shift;
    data.lattice[a] = n;
    const float step = extent[a] / float(n);
    data.inv_step[a] = step > 0.f ? float(n) / extent[a] : 0.f;
    auto& p = data.planes[a];
    p.resize(n + 1);
    for (int i = 0; i < n; ++i) p[i] = std::min(data.bounds.lo[a] + float(i) * step, data.bounds.hi[a]);
    p[n] = data.bounds.hi[a];
    // One margin for both levels, so a primitive touching an enlarged virtual cell always
    // touches its enlarged top cell and reaches the second pass.
    margin[a] = kGridRelMargin * step + kGridAbsMargin * scale;
  }

  // Top level: which top cells each primitive overlaps (counted, then filled).
  std::array<std::vector<float>, 3> top_planes;
  Vec3 top_inv;
  for (int a = 0; a < 3; ++a) {
    top_planes[a].resize(res[a] + 1);
    for (int i = 0; i <= res[a]; ++i) top_planes[a][i] = data.planes[a][i << shift];
    top_inv[a] = data.inv_step[a] / float(1 << shift);
  }
  const std::size_t nx = res[0], nxy = nx * res[1], top_cells = nxy * res[2];
  auto for_each_top_cell = [&](std::uint32_t slot, auto&& visit) {
    const std::uint32_t id = data.ids[slot];
    const Box3 b = geometry.bounds(id);
    AxisRange r[3];
    for (int a = 0; a < 3; ++a) {
      if (!(b.lo[a] <= b.hi[a])) return;  // NaN or empty: a degenerate primitive no ray hits
      r[a] = cells_touching(top_planes[a], top_inv[a], margin[a], b.lo[a], b.hi[a]);
      if (r[a].first > r[a].last) return;
    }
    const bool single = r[0].first == r[0].last && r[1].first == r[1].last && r[2].first == r[2].last;
    for (int z = r[2].first; z <= r[2].last; ++z) {
      for (int y = r[1].first; y <= r[1].last; ++y) {
        for (int x = r[0].first; x <= r[0].last; ++x) {
          if (!single) {
            const Box3 cell{{top_planes[0][x] - margin.x, top_planes[1][y] - margin.y, top_planes[2][z] - margin.z},
                            {top_planes[0][x + 1] + margin.x, top_planes[1][y + 1] + margin.y,
                             top_planes[2][z + 1] + margin.z}};
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

  // The lookup map: each top cell's level, and its block of virtual cells. Virtual cell i is
  // cell i until merging renumbers them.
  data.top.resize(top_cells);
  std::size_t virtual_cells = 0;
  for (std::size_t t = 0; t < top_cells; ++t) {
    const int s = subdivision_level(top_begin[t + 1] - top_begin[t], config.sub_density, shift);
    data.top[t] = {static_cast<std::uint32_t>(virtual_cells), static_cast<std::uint32_t>(s)};
    virtual_cells += std::size_t{1} << (3 * s);
  }
  if (virtual_cells >= std::numeric_limits<std::uint32_t>::max()) throw UsageError("irregular grid: too many cells");
  data.sub.resize(virtual_cells);
  out.boxes.resize(virtual_cells);
  out.begin.assign(virtual_cells + 1, 0u);

  // Second level, per top cell in parallel: the virtual cells each of its primitives overlaps,
  // listed by a counting sort that keeps the primitives ascending in every cell.
  std::vector<std::vector<std::uint32_t>> local_refs(top_cells);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, top_cells, 16), [&](const auto& range) {
    std::array<std::vector<float>, 3> planes;
    std::vector<std::uint32_t> pairs;  // (local cell, slot), flattened
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      std::sort(top_refs.begin() + top_begin[t], top_refs.begin() + top_begin[t + 1]);
      const int s = static_cast<int>(data.top[t].shift);
      const int m = 1 << s, stride = 1 << (shift - s);
      const std::uint32_t base = data.top[t].begin;
      const int corner[3] = {int(t % nx) << shift, int((t / nx) % res[1]) << shift, int(t / nxy) << shift};
      Vec3 inv;
      for (int a = 0; a < 3; ++a) {
        planes[a].resize(m + 1);
        for (int j = 0; j <= m; ++j) planes[a][j] = data.planes[a][corner[a] + j * stride];
        inv[a] = data.inv_step[a] / float(stride);
      }
      for (int l = 0; l < m * m * m; ++l) {
        const int lx = l & (m - 1), ly = (l >> s) & (m - 1), lz = l >> (2 * s);
        auto& box = out.boxes[base + l];
        box = {std::uint16_t(corner[0] + lx * stride),       std::uint16_t(corner[1] + ly * stride),
               std::uint16_t(corner[2] + lz * stride),       std::uint16_t(corner[0] + (lx + 1) * stride),
               std::uint16_t(corner[1] + (ly + 1) * stride), std::uint16_t(corner[2] + (lz + 1) * stride)};
        data.sub[base + l] = base + l;
      }
      pairs.clear();
      for (std::uint32_t k = top_begin[t]; k < top_begin[t + 1]; ++k) {
        const std::uint32_t slot = top_refs[k];
        const std::uint32_t id = data.ids[slot];
        if (s == 0) {
          pairs.insert(pairs.end(), {0u, slot});
          continue;
        }
        const Box3 b = geometry.bounds(id);
        AxisRange r[3];
        for (int a = 0; a < 3; ++a) r[a] = cells_touching(planes[a], inv[a], margin[a], b.lo[a], b.hi[a]);
        const bool single = r[0].first == r[0].last && r[1].first == r[1].last && r[2].first == r[2].last;
        for (int z = r[2].first; z <= r[2].last; ++z) {
          for (int y = r[1].first; y <= r[1].last; ++y) {
            for (int x = r[0].first; x <= r[0].last; ++x) {
              if (!single) {
                const Box3 cell{{planes[0][x] - margin.x, planes[1][y] - margin.y, planes[2][z] - margin.z},
                                {planes[0][x + 1] + margin.x, planes[1][y + 1] + margin.y, planes[2][z + 1] + margin.z}};
                if (!overlaps_box(geometry, id, cell)) continue;
              }
              pairs.insert(pairs.end(), {std::uint32_t(x + (y << s) + (z << (2 * s))), slot});
            }
          }
        }
      }
      // Counting sort by local cell; stable, so each cell's slots stay ascending.
      for (std::size_t p = 0; p < pairs.size(); p += 2) ++out.begin[base + pairs[p] + 1];
      std::vector<std::uint32_t> offset(m * m * m + 1, 0u);
      for (int l = 0; l < m * m * m; ++l) offset[l + 1] = offset[l] + out.begin[base + l + 1];
      auto& mine = local_refs[t];
      mine.resize(pairs.size() / 2);
      for (std::size_t p = 0; p < pairs.size(); p += 2) mine[offset[pairs[p]]++] = pairs[p + 1];
    }
  });
  for (std::size_t c = 1; c <= virtual_cells; ++c) out.begin[c] += out.begin[c - 1];
  out.refs.resize(out.begin[virtual_cells]);
  tbb::parallel_for(std::size_t{0}, top_cells, [&](std::size_t t) {
    std::copy(local_refs[t].begin(), local_refs[t].end(), out.refs.begin() + out.begin[data.top[t].begin]);
  });
  return out;
}

IrregularGridData build_irregular_grid(const Geometry& geometry, std::span<const std::uint32_t> ids,
                                       const IrregularGridConfig& config) {
  check_config(config);
  IrregularGridData data;
  data.ids.assign(ids.begin(), ids.end());
  // Ascending, so references (positions here) order the primitives by id in every cell: the
  // result does not depend on the order `ids` came in, and any-hit queries meet a cell's
  // primitives in id order, as brute force does.
  std::sort(data.ids.begin(), data.ids.end());
  for (std::uint32_t id : data.ids) data.bounds.extend(geometry.bounds(id));
  if (data.ids.empty() || data.bounds.empty()) return data;  // no cells: every ray misses

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
