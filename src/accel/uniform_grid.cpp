// Uniform grid traversal: Cleary & Wyvill's incremental cell walk, with mailboxing and jumps
// across empty space.

#include "raylab/accel/uniform_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "grid_walk.h"
#include "leaf_test.h"
#include "mailbox.h"
#include "traversal_common.h"
#include "traversal_entry_points.h"

namespace raylab {

namespace {

// The stand-in for on_cell in the queries: nothing to tell.
struct IgnoreCells {
  void operator()(const GridWalk&, int) const {}
};

}  // namespace

template <bool kAnyHit, bool kCount, class K>
bool UniformGrid::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  return run<kAnyHit, kCount>(ray, hit, stats, IgnoreCells{});
}

template <bool kAnyHit, bool kCount, class OnCell>
bool UniformGrid::run(Ray& ray, Hit& hit, TraversalStats* stats, OnCell&& on_cell) const {
  GridWalk w;
  if (!clip_and_enter<KernelIsa>(ray, w)) return finish_traversal<kCount>(false, ray.tmax, hit, {}, ray, hit, stats);
  // The ray's stamp is taken only now: rays that miss the grid never touch the mailboxes.
  if (m_mailboxes) return walk_cells<kAnyHit, kCount>(ray, hit, stats, w, m_mailboxes->begin_ray(), on_cell);
  return walk_cells<kAnyHit, kCount>(ray, hit, stats, w, TestEverySlot{}, on_cell);
}

template <class K>
bool UniformGrid::clip_and_enter(const Ray& ray, GridWalk& w) const {
  if (m_refs.empty()) return false;
  const Vec3 o = ray.origin, d = ray.direction;
  const Vec3 inv_d = safe_reciprocal(d);
  float t_in;
  if (!clip_ray_to_grid(ray, m_bounds, inv_d, t_in)) return false;

  // The entry cell, from the entry point (clamped: rounding may put it just outside).
  const Vec3 entry = ray.at(t_in);
  std::ptrdiff_t stride = 1;
  w.index = 0;
  for (int a = 0; a < 3; ++a) {
    const int n = m_resolution[a];
    const int i = clamp_cell((entry[a] - m_bounds.lo[a]) * m_inv_cell[a], n);
    w.init_axis(a, i, n, stride, m_planes[a][i], m_planes[a][i + 1], o[a], d[a], inv_d[a], m_cell[a], m_inv_cell[a]);
    stride *= n;
  }
  return true;
}

template <bool kAnyHit, bool kCount, class Mailbox, class OnCell>
bool UniformGrid::walk_cells(Ray& ray, Hit& hit, TraversalStats* stats, GridWalk& w, Mailbox mailbox,
                             OnCell& on_cell) const {
  const WatertightRay wr(ray);
  const std::uint32_t* const offsets = m_offsets.data();
  const std::uint8_t* const skip = m_skip.data();
  const std::uint32_t* const refs = m_refs.data();
  const SlotPrimitives prims(m_ids.data(), m_triangles, m_spheres, m_cylinder_frames, m_geometry);
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  Hit best = hit;
  bool found = false;
  TraversalCounters counters;  // nodes_visited: the cells walked and the jumps

  for (;;) {
    if constexpr (kCount) ++counters.nodes_visited;
    const float t_exit = w.exit();
    // 0: the cell holds primitives; else the (chessboard) distance in cells to one that does.
    const std::size_t index = w.index;
    const int distance = skip[index];
    on_cell(w, distance);
    if (distance == 0) {
      if (intersect_references<kAnyHit, kCount>(prims, offsets[index], offsets[index + 1], SlotFromList{refs}, mailbox,
                                                wr, ray, tmin, tmax, best, counters)) {
        found = true;
        if constexpr (kAnyHit) break;
      }
    } else if (distance > 1) {
      // Every cell within distance - 1 of this one is empty: cross that cube in one jump.
      float t_leave;
      if (w.jump(distance - 1, tmax, t_leave) != GridWalk::Jump::kMoved) break;
      continue;
    }
    // Anything hit before the cell's exit lies in a cell already walked (each primitive is in
    // every cell it touches, with a margin), so the closest hit is known; and a ray whose range
    // ends inside this cell has nothing farther to look at. An axis the ray does not move along
    // has t_next = inf, so it is only picked when the ray never leaves the cell, and stops here.
    if (tmax <= t_exit) break;
    if (!w.step()) break;  // stepped out of the grid
  }
  return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
}

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
std::vector<WalkedCell> UniformGrid::cells_on_ray(const Ray& ray) const {
  std::vector<WalkedCell> cells;
  // A cell holding primitives, a single empty cell, or (distance > 1) the cube of empty cells
  // within distance - 1 that the walk crosses in one jump, clipped to the grid.
  auto record = [&](const GridWalk& w, int distance) {
    const int reach = distance > 1 ? distance - 1 : 0;
    Box3 box;
    for (int a = 0; a < 3; ++a) {
      box.lo[a] = m_planes[a][std::max(w.cell[a] - reach, 0)];
      box.hi[a] = m_planes[a][std::min(w.cell[a] + reach + 1, m_resolution[a])];
    }
    cells.push_back({box, distance == 0});
  };
  Ray probe = ray;
  Hit hit;
  TraversalStats stats;
  run<false, true>(probe, hit, &stats, record);
  return cells;
}

// The four entry points, which call the kernel of the structure's instruction set.
RAYLAB_INSTANTIATE_ENTRY_POINTS(UniformGrid);

#endif  // RAYLAB_KERNEL_VARIANT

// The kernel, compiled here for this translation unit's instruction set.
RAYLAB_INSTANTIATE_TRAVERSE(UniformGrid);

}  // namespace raylab
