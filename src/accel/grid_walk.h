#pragma once
// Cleary & Wyvill's incremental cell walk through a box cut into n_x * n_y * n_z equal cells
// (internal to src/accel), shared by the uniform grid and both levels of the two-level grid:
// where a ray enters, which boundary it crosses next, one integer step at a time, and the jump
// across a cube of empty cells. One copy of the stepping and boundary rule, so that every grid
// walks the same way and the same rounding argument (the insertion margins of grid_insert.h)
// covers all of them.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "raylab/core/box.h"
#include "raylab/core/ray.h"
#include "raylab/simd/isa_namespace.h"
#include "traversal_common.h"

namespace raylab {
RAYLAB_ISA_BEGIN

/// Clips the range [t_in, t_out] of a ray from `o` with reciprocal direction `inv_d` to `box`;
/// true when something is left. The far distance is widened as in the BVH, so that a ray
/// grazing the box where a primitive lies in its face still enters.
inline bool clip_to_box(const Vec3& o, const Vec3& inv_d, const Box3& box, float& t_in, float t_out) {
  for (int a = 0; a < 3; ++a) {
    float t0 = (box.lo[a] - o[a]) * inv_d[a];
    float t1 = (box.hi[a] - o[a]) * inv_d[a];
    if (inv_d[a] < 0.f) std::swap(t0, t1);
    t_in = t0 > t_in ? t0 : t_in;  // a NaN slab (0 * inf: origin in a face plane) is ignored
    t_out = t1 < t_out ? t1 : t_out;
  }
  return t_in <= widen_exit(t_out);
}

/// Clips `ray` to a grid's box: on return true, `t_in` is where the ray's range [tmin, tmax]
/// enters the box. An infinite or NaN origin, which would make the boundary distances NaN, hits
/// nothing.
inline bool clip_ray_to_grid(const Ray& ray, const Box3& box, const Vec3& inv_d, float& t_in) {
  const Vec3 o = ray.origin;
  if (!std::isfinite(o.x + o.y + o.z)) return false;
  t_in = ray.tmin;
  return clip_to_box(o, inv_d, box, t_in, ray.tmax);
}

/// The cell along one axis that holds the offset f = (x - lo) * cells_per_unit, clamped to
/// [0, n - 1]; NaN (a flat axis, or a NaN coordinate) gives 0.
inline int clamp_cell(float f, int n) { return f >= 0.f ? (f < float(n) ? static_cast<int>(f) : n - 1) : 0; }

/// Plane i (0 .. n) of an axis cut into n cells of length `cell` from lo to hi: the build's cell
/// boxes and the walk's boundary distances both come from here. The last plane is hi exactly.
inline float grid_plane(float lo, float hi, float cell, int i, int n) {
  return i >= n ? hi : std::min(lo + float(i) * cell, hi);
}
RAYLAB_ISA_END

/// One ray's walk through one grid. Per axis: the parameter of the first cell boundary the ray
/// crosses (inf along an axis it does not move along), the parameter length of one cell, the
/// direction of travel in cells (+1, -1 or 0), the change of the linear cell index per step,
/// the number of cells, the current cell, the boundaries crossed so far and the parameter of the
/// next one; plus the linear index of the current cell.
struct GridWalk {
  float t_first[3];
  float t_delta[3];
  float inv_delta[3];  ///< 1 / t_delta (0 where t_delta is 0)
  int dir[3];
  std::ptrdiff_t index_step[3];
  int n[3];
  int cell[3];
  int crossed[3];
  float t_next[3];
  std::size_t index;

  /// Sets up axis `a` for a ray entering cell `i` of `cells`, whose planes are `lo_plane` and
  /// `hi_plane`; `stride` is the change of the linear index per cell along the axis (the walk
  /// adds i * stride to `index`, which the caller starts at its grid's base). o, d and inv_d are
  /// the ray's origin, direction and safe reciprocal along the axis; cell and inv_cell the cell
  /// length and its reciprocal.
  void init_axis(int a, int i, int cells, std::ptrdiff_t stride, float lo_plane, float hi_plane, float o, float d,
                 float inv_d, float cell_length, float inv_cell) {
    cell[a] = i;
    n[a] = cells;
    index += std::size_t(std::ptrdiff_t(i) * stride);
    crossed[a] = 0;
    // A component so small that its reciprocal overflows moves the ray across no boundary
    // within float range of t; it is treated as zero like +-0.
    if (d != 0.f && std::isfinite(inv_d)) {
      const bool up = d > 0.f;
      t_first[a] = ((up ? hi_plane : lo_plane) - o) * inv_d;
      t_delta[a] = cell_length * std::fabs(inv_d);
      inv_delta[a] = inv_cell * std::fabs(d);
      dir[a] = up ? 1 : -1;
    } else {
      t_first[a] = std::numeric_limits<float>::infinity();
      t_delta[a] = 0.f;
      inv_delta[a] = 0.f;
      dir[a] = 0;
    }
    t_next[a] = t_first[a];
    index_step[a] = dir[a] * stride;
  }

  /// Boundary k along axis a lies at t_first + k * t_delta, computed with one rounding (fma)
  /// rather than accumulated (t_next += t_delta), which would drift by a rounding per step.
  float boundary(int a, int k) const { return std::fma(float(k), t_delta[a], t_first[a]); }

  /// Where the ray leaves the current cell: the nearest boundary. An axis the ray does not move
  /// along has t_next = inf, so it is only the exit when the ray never leaves the cell.
  float exit() const { return std::min(t_next[0], std::min(t_next[1], t_next[2])); }

  /// One step along the axis of the nearest boundary (ties to the later axis); false when the
  /// step leaves the grid (the walk is then over and the state is not to be used again).
  bool step() {
    const int a = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
    cell[a] += dir[a];
    if (unsigned(cell[a]) >= unsigned(n[a])) return false;
    index += index_step[a];
    t_next[a] = boundary(a, ++crossed[a]);
    return true;
  }

  /// What a jump did.
  enum class Jump {
    kStop,   ///< the range [.., tmax] ends inside the empty cube: nothing more to find
    kLeft,   ///< the cube's far face was the grid's: the walk is over
    kMoved,  ///< the walk is now in the first cell after the cube, entered at `t_leave`
  };

  /// Crosses the cube of cells within `reach` (>= 1) of the current one, all known to be empty,
  /// in one jump (Cohen & Sheffer's proximity clouds), arriving in the very cell that stepping
  /// would have reached. `t_leave` receives the parameter where the ray leaves the cube.
  Jump jump(int reach, float tmax, float& t_leave) {
    // Per axis, the boundaries until the cube's face ahead (or the grid's last boundary, if
    // nearer; none along an axis the ray does not move along, whose boundaries are all at inf)...
    int to_face[3];
    float t_face[3];
    for (int a = 0; a < 3; ++a) {
      to_face[a] = dir[a] > 0 ? std::min(reach, n[a] - 1 - cell[a]) : (dir[a] < 0 ? std::min(reach, cell[a]) : 0);
      t_face[a] = boundary(a, crossed[a] + to_face[a]);
    }
    // ...the ray leaves the cube through the nearest face...
    t_leave = std::min(t_face[0], std::min(t_face[1], t_face[2]));
    if (tmax <= t_leave) return Jump::kStop;
    const int out = t_face[0] == t_leave ? 0 : (t_face[1] == t_leave ? 1 : 2);
    // ...and on the way crosses the other axes' boundaries that come before that face: their
    // number is estimated from the distance, then settled on the boundaries' own values, so
    // that the walk arrives in the very cell it would have reached step by step. The estimate
    // is capped before it becomes an int: for a huge direction component (|d| near FLT_MAX)
    // inv_delta overflows to inf and the estimate with it, and converting inf (undefined
    // behaviour) gave INT_MIN and a cell index far outside the grid. The settling then walks
    // as far as such an estimate is off (at most to_face steps; one for ordinary rays).
    for (int a = 0; a < 3; ++a) {
      int k = to_face[a] + 1;
      if (a != out) {
        const float estimate = (t_leave - t_next[a]) * inv_delta[a];
        k = estimate > 0.f ? static_cast<int>(std::ceil(std::min(estimate, float(to_face[a])))) : 0;
        while (k > 0 && boundary(a, crossed[a] + k - 1) >= t_leave) --k;
        while (k < to_face[a] && boundary(a, crossed[a] + k) < t_leave) ++k;
      }
      crossed[a] += k;
      cell[a] += k * dir[a];
      index += std::size_t(k * index_step[a]);
      t_next[a] = boundary(a, crossed[a]);
    }
    return unsigned(cell[out]) >= unsigned(n[out]) ? Jump::kLeft : Jump::kMoved;
  }
};

}  // namespace raylab
