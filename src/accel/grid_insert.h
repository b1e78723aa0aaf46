#pragma once
// Inserting primitives into the cells of a grid (internal to src/accel), shared by the uniform
// grid and both levels of the two-level grid: the margins by which cell boxes are enlarged, the
// range of cells a primitive's box can touch, and the exact overlap test per cell.

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "grid_walk.h"
#include "raylab/geometry/geometry.h"
#include "raylab/geometry/overlap.h"

namespace raylab {

// Cell boxes are enlarged before the overlap test, so that rounding in the traversal never skips
// a primitive. The traversal hands each stretch [t_in, t_out] of the ray to one cell; the
// exact ray point at those parameters can stray from the cell by the rounding of the boundary
// parameters t_first + k * t_delta (a few ulps of the distance travelled) and, for the entry
// cell, of the entry point's coordinates (an ulp of the coordinates). Where it strays into a
// neighbour near an edge or corner, the walk may pass through that neighbour instead of the cell
// the exact ray crosses, and a primitive touching only the latter would be missed. The margin
// covers both sources:
//  - kGridAbsMargin times the largest coordinate magnitude of the grid box: 2^-18 is 64 float
//    ulps, enough for rays that travel up to ~20 scene sizes to their hit;
//  - kGridRelMargin times the cell size, for the overlap tests' own rounding.
// Both are far below a cell, so the extra references they add are few. The two-level grid's
// leaf walks start from a computed entry point in each top cell and end where they step out of
// their leaf grid, both a few ulps from the exact crossing, which the same margins cover.
inline constexpr float kGridRelMargin = 1e-4f;
inline constexpr float kGridAbsMargin = 0x1p-18f;

/// The insertion margin of a cell of length `cell` in a grid whose box has largest coordinate
/// magnitude `scale`.
inline float grid_margin(float cell, float scale) { return kGridRelMargin * cell + kGridAbsMargin * scale; }

/// The planes of one axis of a grid: n cells, plane(i) for i in 0 .. n, and the reciprocal cell
/// length for a first guess of the cell holding a coordinate.
template <class Plane>
struct AxisPlanes {
  Plane plane;     ///< plane(i), ascending, i in 0 .. n
  int n;           ///< cells
  float inv_cell;  ///< cells per unit length (0 on a flat axis)
};

/// Deduces Plane from the brace initializer; clang before 17 has no class template argument
/// deduction for aggregates, so without this guide `AxisPlanes{lambda, n, inv}` fails there.
template <class Plane>
AxisPlanes(Plane, int, float) -> AxisPlanes<Plane>;

/// A range of cells on one axis (inclusive); empty when first > last.
struct AxisRange {
  int first, last;
};

/// The range of cells on one axis whose boxes, enlarged by `margin`, touch [lo, hi].
template <class Plane>
AxisRange cells_touching(const AxisPlanes<Plane>& axis, float margin, float lo, float hi) {
  const int n = axis.n;
  const float origin = axis.plane(0);
  auto guess = [&](float x) {
    const float f = (x - origin) * axis.inv_cell;
    return f >= 0.f ? (f < float(n) ? static_cast<int>(f) : n - 1) : 0;  // NaN (a flat axis) -> 0
  };
  // first: the lowest cell whose upper face (enlarged) reaches lo.
  int first = guess(lo - margin);
  while (first > 0 && axis.plane(first) + margin >= lo) --first;
  while (first < n && axis.plane(first + 1) + margin < lo) ++first;
  // last: the highest cell whose lower face (enlarged) is at or below hi.
  int last = guess(hi + margin);
  while (last < n - 1 && axis.plane(last + 1) - margin <= hi) ++last;
  while (last >= 0 && axis.plane(last) - margin > hi) --last;
  return {first, last};
}

/// Calls visit(x, y, z) for every cell of a grid whose box, enlarged by `margin`, overlaps
/// primitive (or group) `id` of `geometry`, found by its box `b` and then the exact shape test.
template <class Plane, class Visit>
void for_each_overlapped_cell(const Geometry& geometry, std::uint32_t id, const Box3& b,
                              const std::array<AxisPlanes<Plane>, 3>& axes, const Vec3& margin, Visit&& visit) {
  AxisRange range[3];
  for (int a = 0; a < 3; ++a) {
    // A NaN or empty box (a degenerate primitive) touches nothing: no ray can hit it.
    if (!(b.lo[a] <= b.hi[a])) return;
    range[a] = cells_touching(axes[a], margin[a], b.lo[a], b.hi[a]);
    if (range[a].first > range[a].last) return;
  }
  // A primitive whose box lies in a single cell overlaps it: no test needed.
  const bool single =
      range[0].first == range[0].last && range[1].first == range[1].last && range[2].first == range[2].last;
  for (int z = range[2].first; z <= range[2].last; ++z) {
    for (int y = range[1].first; y <= range[1].last; ++y) {
      for (int x = range[0].first; x <= range[0].last; ++x) {
        if (!single) {
          const Box3 cell{
              {axes[0].plane(x) - margin.x, axes[1].plane(y) - margin.y, axes[2].plane(z) - margin.z},
              {axes[0].plane(x + 1) + margin.x, axes[1].plane(y + 1) + margin.y, axes[2].plane(z + 1) + margin.z}};
          if (!overlaps_box(geometry, id, cell)) continue;
        }
        visit(x, y, z);
      }
    }
  }
}

/// Sorts `ids` by the cell of a grid (low corner `lo`, `inv_cell` cells per unit length,
/// `resolution` cells per axis) holding the centre of each primitive's box, x fastest, ties by
/// id: a deterministic spatial order in which a cell's primitives lie together, so the copies
/// made in this order (copy_slot_primitives) are read together.
inline void order_by_grid_cell(const Geometry& geometry, std::vector<std::uint32_t>& ids, const Vec3& lo,
                               const Vec3& inv_cell, const std::array<int, 3>& resolution) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(ids.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size(), 1024), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const Vec3 c = geometry.bounds(ids[i]).center();
      std::uint64_t key = 0;
      for (int a = 2; a >= 0; --a) {
        const int cell = clamp_cell((c[a] - lo[a]) * inv_cell[a], resolution[a]);
        key = key * std::uint64_t(resolution[a]) + std::uint64_t(cell);
      }
      keyed[i] = {key, ids[i]};
    }
  });
  tbb::parallel_sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < keyed.size(); ++i) ids[i] = keyed[i].second;
}

}  // namespace raylab
