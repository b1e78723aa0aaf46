#pragma once
// Inserting primitives into the cells of a grid (internal to src/accel): the margins by which
// cell boxes are enlarged before the overlap test, and the range of cells along one axis whose
// enlarged boxes can touch an interval. Shared by the uniform grid and the irregular grid, so
// both follow one rule.
//
// Cell boxes are enlarged before the overlap test, so that rounding in the traversal never skips
// a primitive. A traversal hands each stretch [t_in, t_out] of the ray to one cell; the exact
// ray point at those parameters can stray from the cell by the rounding of the boundary
// parameters (a few ulps of the distance travelled) and, for the entry cell, of the entry
// point's coordinates (an ulp of the coordinates). Where it strays into a neighbour near an edge
// or corner, the walk may pass through that neighbour instead of the cell the exact ray crosses,
// and a primitive touching only the latter would be missed. The margin covers both sources:
//  - kGridAbsMargin times the largest coordinate magnitude of the grid box: 2^-18 is 64 float
//    ulps, enough for rays that travel up to ~20 scene sizes to their hit;
//  - kGridRelMargin times the cell size, for the overlap tests' own rounding.
// Both are far below a cell, so the extra references they add are few.

#include <vector>

namespace raylab {

/// Margin relative to the cell size (the overlap tests' rounding).
inline constexpr float kGridRelMargin = 1e-4f;
/// Margin relative to the largest coordinate magnitude of the grid box (the walk's rounding).
inline constexpr float kGridAbsMargin = 0x1p-18f;

/// The range of cells on one axis, inclusive; empty (first > last) when none.
struct AxisRange {
  int first, last;
};

/// The cells on one axis whose boxes, enlarged by `margin`, touch [lo, hi]. `planes` holds the
/// n + 1 cell boundaries in ascending order and `inv_cell` the cells per unit length (for a first
/// guess, which is then settled on the planes themselves, so the answer uses the very floats the
/// traversal uses).
inline AxisRange cells_touching(const std::vector<float>& planes, float inv_cell, float margin, float lo, float hi) {
  const int n = static_cast<int>(planes.size()) - 1;
  auto guess = [&](float x) {
    const float f = (x - planes[0]) * inv_cell;
    return f >= 0.f ? (f < float(n) ? static_cast<int>(f) : n - 1) : 0;  // NaN (a flat axis) -> 0
  };
  // first: the lowest cell whose upper face (enlarged) reaches lo.
  int first = guess(lo - margin);
  while (first > 0 && planes[first] + margin >= lo) --first;
  while (first < n && planes[first + 1] + margin < lo) ++first;
  // last: the highest cell whose lower face (enlarged) is at or below hi.
  int last = guess(hi + margin);
  while (last < n - 1 && planes[last + 1] - margin <= hi) ++last;
  while (last >= 0 && planes[last] - margin > hi) --last;
  return {first, last};
}

}  // namespace raylab
