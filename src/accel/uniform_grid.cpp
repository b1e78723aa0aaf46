// Uniform grid traversal: Cleary & Wyvill's incremental cell walk, with mailboxing and jumps
// across empty space.

#include "raylab/accel/uniform_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "leaf_test.h"
#include "mailbox.h"
#include "traversal_common.h"

namespace raylab {

// The fixed part of a ray's walk, per axis: the parameter of the first cell boundary the ray
// crosses (inf along an axis it does not move along), the parameter length of one cell, the
// direction of travel in cells (+1, -1 or 0), the change of the linear cell index per step and
// the number of cells; plus the entry cell.
struct UniformGrid::Walk {
  float t_first[3];
  float t_delta[3];
  float inv_delta[3];  // 1 / t_delta (0 where t_delta is 0)
  int dir[3];
  std::ptrdiff_t index_step[3];
  int n[3];
  int cell[3];
  std::size_t index;
};

template <bool kAnyHit, bool kCount>
bool UniformGrid::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  Walk w;
  if (!clip_and_enter(ray, w)) return finish_traversal<kCount>(false, ray.tmax, hit, {}, ray, hit, stats);
  // The ray's stamp is taken only now: rays that miss the grid never touch the mailboxes.
  if (m_mailboxes) return walk_cells<kAnyHit, kCount>(ray, hit, stats, w, m_mailboxes->begin_ray());
  return walk_cells<kAnyHit, kCount>(ray, hit, stats, w, TestEverySlot{});
}

bool UniformGrid::clip_and_enter(const Ray& ray, Walk& w) const {
  if (m_refs.empty()) return false;
  const Vec3 o = ray.origin, d = ray.direction;
  // An infinite or NaN origin would make the boundary distances NaN; such a ray hits nothing.
  if (!std::isfinite(o.x + o.y + o.z)) return false;
  // Clip to the grid box. The far distance is widened as in the BVH, so that a ray grazing the
  // box where a primitive lies in its face still enters.
  const Vec3 inv_d = safe_reciprocal(d);
  float t_in = ray.tmin, t_out = ray.tmax;
  for (int a = 0; a < 3; ++a) {
    float t0 = (m_bounds.lo[a] - o[a]) * inv_d[a];
    float t1 = (m_bounds.hi[a] - o[a]) * inv_d[a];
    if (inv_d[a] < 0.f) std::swap(t0, t1);
    t_in = t0 > t_in ? t0 : t_in;  // a NaN slab (0 * inf: origin in a face plane) is ignored
    t_out = t1 < t_out ? t1 : t_out;
  }
  if (!(t_in <= t_out * kSlabWiden)) return false;

  // The entry cell, from the entry point (clamped: rounding may put it just outside).
  const Vec3 entry = ray.at(t_in);
  std::ptrdiff_t stride = 1;
  w.index = 0;
  for (int a = 0; a < 3; ++a) {
    const int n = m_resolution[a];
    const float f = (entry[a] - m_bounds.lo[a]) * m_inv_cell[a];
    const int i = f >= 0.f ? (f < float(n) ? static_cast<int>(f) : n - 1) : 0;  // NaN -> 0
    w.cell[a] = i;
    w.n[a] = n;
    w.index += i * stride;
    // A component so small that its reciprocal overflows moves the ray across no boundary
    // within float range of t; it is treated as zero like +-0.
    if (d[a] != 0.f && std::isfinite(inv_d[a])) {
      const bool up = d[a] > 0.f;
      w.t_first[a] = (m_planes[a][up ? i + 1 : i] - o[a]) * inv_d[a];
      w.t_delta[a] = m_cell[a] * std::fabs(inv_d[a]);
      w.inv_delta[a] = m_inv_cell[a] * std::fabs(d[a]);
      w.dir[a] = up ? 1 : -1;
    } else {
      w.t_first[a] = std::numeric_limits<float>::infinity();
      w.t_delta[a] = 0.f;
      w.inv_delta[a] = 0.f;
      w.dir[a] = 0;
    }
    w.index_step[a] = w.dir[a] * stride;
    stride *= n;
  }
  return true;
}

template <bool kAnyHit, bool kCount, class Mailbox>
bool UniformGrid::walk_cells(Ray& ray, Hit& hit, TraversalStats* stats, Walk& w, Mailbox mailbox) const {
  const WatertightRay wr(ray);
  const std::uint32_t* const offsets = m_offsets.data();
  const std::uint8_t* const skip = m_skip.data();
  const std::uint32_t* const refs = m_refs.data();
  const SlotPrimitives prims{m_ids.data(),     m_triangles.data(), m_spheres.data(),
                             m_triangle_count, m_sphere_end,       &m_geometry};
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  Hit best = hit;
  bool found = false;
  TraversalCounters counters;  // nodes_visited: the cells walked and the jumps

  // Per axis: boundaries crossed so far, and the parameter of the next one. Boundary k lies at
  // t_first + k * t_delta, computed with one rounding (fma) rather than accumulated
  // (t_next += t_delta), which would drift by a rounding per step.
  int crossed[3] = {0, 0, 0};
  float t_next[3] = {w.t_first[0], w.t_first[1], w.t_first[2]};
  auto boundary = [&](int a, int k) { return std::fma(float(k), w.t_delta[a], w.t_first[a]); };
  std::size_t index = w.index;
  for (;;) {
    if constexpr (kCount) ++counters.nodes_visited;
    // The ray leaves the cell at the nearest boundary (ties to the later axis).
    const float t_exit = std::min(t_next[0], std::min(t_next[1], t_next[2]));
    // 0: the cell holds primitives; else the (chessboard) distance in cells to one that does.
    const int distance = skip[index];
    if (distance == 0) {
      if (intersect_references<kAnyHit, kCount>(prims, offsets[index], offsets[index + 1], SlotFromList{refs}, mailbox,
                                                wr, ray, tmin, tmax, best, counters)) {
        found = true;
        if constexpr (kAnyHit) break;
      }
    } else if (distance > 1) {
      // Every cell within distance - 1 of this one is empty: cross that cube in one jump. Per
      // axis, the boundaries until its face ahead (or the grid's last boundary, if nearer; none
      // along an axis the ray does not move along, whose boundaries are all at inf)...
      const int reach = distance - 1;
      int to_face[3];
      float t_face[3];
      for (int a = 0; a < 3; ++a) {
        to_face[a] =
            w.dir[a] > 0 ? std::min(reach, w.n[a] - 1 - w.cell[a]) : (w.dir[a] < 0 ? std::min(reach, w.cell[a]) : 0);
        t_face[a] = boundary(a, crossed[a] + to_face[a]);
      }
      // ...the ray leaves the cube through the nearest face...
      const float t_leave = std::min(t_face[0], std::min(t_face[1], t_face[2]));
      if (tmax <= t_leave) break;
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
          const float estimate = (t_leave - t_next[a]) * w.inv_delta[a];
          k = estimate > 0.f ? static_cast<int>(std::ceil(std::min(estimate, float(to_face[a])))) : 0;
          while (k > 0 && boundary(a, crossed[a] + k - 1) >= t_leave) --k;
          while (k < to_face[a] && boundary(a, crossed[a] + k) < t_leave) ++k;
        }
        crossed[a] += k;
        w.cell[a] += k * w.dir[a];
        index += k * w.index_step[a];
        t_next[a] = boundary(a, crossed[a]);
      }
      if (unsigned(w.cell[out]) >= unsigned(w.n[out])) break;  // the face was the grid's
      continue;
    }
    // Anything hit before the cell's exit lies in a cell already walked (each primitive is in
    // every cell it touches, with a margin), so the closest hit is known; and a ray whose range
    // ends inside this cell has nothing farther to look at. An axis the ray does not move along
    // has t_next = inf, so it is only picked when the ray never leaves the cell, and stops here.
    if (tmax <= t_exit) break;
    // One step along the axis of the nearest boundary (ties to the later axis).
    const int a = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
    w.cell[a] += w.dir[a];
    if (unsigned(w.cell[a]) >= unsigned(w.n[a])) break;  // stepped out of the grid
    index += w.index_step[a];
    t_next[a] = boundary(a, ++crossed[a]);
  }
  return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
}

// The four entry points, compiled here where the kernel is defined.
template class TraversalAccelerator<UniformGrid>;

}  // namespace raylab
