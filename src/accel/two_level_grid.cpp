// Two-level grid traversal: Cleary & Wyvill's walk on the top grid and, in each top cell with
// primitives, the same walk on its leaf grid over the ray's stretch inside the cell (both from
// grid_walk.h), with mailboxing, the closest-hit early exit and jumps over empty top cells.

#include <cmath>

#include "grid_walk.h"
#include "leaf_test.h"
#include "mailbox.h"
#include "raylab/accel/two_level_grid.h"
#include "traversal_common.h"
#include "traversal_entry_points.h"

namespace raylab {
namespace {

// The stand-in for on_cell in the queries: nothing to tell.
struct IgnoreCells {
  void operator()(std::size_t, const int*, bool, int) const {}
};

}  // namespace

template <bool kAnyHit, bool kCount, class K>
bool TwoLevelGrid::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  return run<kAnyHit, kCount>(ray, hit, stats, IgnoreCells{});
}

template <bool kAnyHit, bool kCount, class OnCell>
bool TwoLevelGrid::run(Ray& ray, Hit& hit, TraversalStats* stats, OnCell&& on_cell) const {
  GridWalk top;
  float t_in;
  if (!clip_and_enter<KernelIsa>(ray, top, t_in))
    return finish_traversal<kCount>(false, ray.tmax, hit, {}, ray, hit, stats);
  // The ray's stamp is taken only now: rays that miss the grid never touch the mailboxes.
  if (m_mailboxes) return walk<kAnyHit, kCount>(ray, hit, stats, top, t_in, m_mailboxes->begin_ray(), on_cell);
  return walk<kAnyHit, kCount>(ray, hit, stats, top, t_in, TestEverySlot{}, on_cell);
}

template <class K>
bool TwoLevelGrid::clip_and_enter(const Ray& ray, GridWalk& w, float& t_in) const {
  if (m_refs.empty()) return false;
  const Vec3 o = ray.origin, d = ray.direction;
  const Vec3 inv_d = safe_reciprocal(d);
  if (!clip_ray_to_grid(ray, m_bounds, inv_d, t_in)) return false;
  // The entry cell, from the entry point (clamped: rounding may put it just outside).
  const Vec3 entry = ray.at(t_in);
  std::ptrdiff_t stride = 1;
  w.index = 0;
  for (int a = 0; a < 3; ++a) {
    const int n = m_top_resolution[a];
    const int i = clamp_cell((entry[a] - m_bounds.lo[a]) * m_top_inv_cell[a], n);
    w.init_axis(a, i, n, stride, m_top_planes[a][i], m_top_planes[a][i + 1], o[a], d[a], inv_d[a], m_top_cell[a],
                m_top_inv_cell[a]);
    stride *= n;
  }
  return true;
}

template <bool kAnyHit, bool kCount, class Mailbox, class OnCell>
bool TwoLevelGrid::walk(Ray& ray, Hit& hit, TraversalStats* stats, GridWalk& top, float t_enter, Mailbox mailbox,
                        OnCell& on_cell) const {
  const WatertightRay wr(ray);
  const Vec3 o = ray.origin, d = ray.direction;
  const Vec3 inv_d = safe_reciprocal(d);
  const std::uint32_t* const offsets = m_offsets.data();
  const std::uint8_t* const skip = m_top_skip.data();
  const std::uint8_t* const leaf_skip = m_leaf_skip.data();
  const std::uint32_t* const refs = m_refs.data();
  const TopCell* const cells = m_top.data();
  const SlotPrimitives prims(m_ids.data(), m_triangles, m_spheres, m_cylinder_frames, m_geometry);
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  Hit best = hit;
  bool found = false;
  TraversalCounters counters;  // nodes_visited: top cells, leaf cells and jumps

  // Tests leaf cell `c`; true when the query is over (an any-hit query found something).
  auto test_cell = [&](std::size_t c) {
    const std::uint32_t begin = offsets[c], end = offsets[c + 1];
    if (begin == end) return false;
    if (intersect_references<kAnyHit, kCount>(prims, begin, end, SlotFromList{refs}, mailbox, wr, ray, tmin, tmax, best,
                                              counters)) {
      found = true;
      return kAnyHit;
    }
    return false;
  };

  for (;;) {
    if constexpr (kCount) ++counters.nodes_visited;
    const float t_exit = top.exit();
    const std::size_t index = top.index;
    // 0: primitives overlap the top cell; else the (chessboard) distance in cells to one they do.
    const int distance = skip[index];
    if (distance == 0) {
      const TopCell& cell = cells[index];
      on_cell(index, nullptr, offsets[cell.list] != offsets[cell.list + 1], 0);
      // The big primitives first: they span the cell, so they are likely to be hit.
      if (test_cell(cell.list)) break;
      // The leaf walk over the ray's stretch through the leaf grid's box inside this top cell.
      float t_leaf = t_enter;
      if (cell.res[0] > 0 && clip_to_box(o, inv_d, Box3{cell.lo, cell.hi}, t_leaf, std::min(t_exit, tmax))) {
        bool over = false;
        if ((cell.res[0] | cell.res[1] | cell.res[2]) == 1) {
          // A leaf grid of one cell: nothing to walk.
          if constexpr (kCount) ++counters.nodes_visited;
          static constexpr int kOrigin[3] = {0, 0, 0};
          on_cell(index, kOrigin, offsets[cell.list + 1] != offsets[cell.list + 2], 0);
          over = test_cell(cell.list + 1);
        } else {
          // From the point where the ray enters the leaf box (clamped to the leaf grid:
          // rounding may put it just outside) until it steps out of the leaf grid.
          const Vec3 entry = ray.at(t_leaf);
          GridWalk leaf;
          leaf.index = cell.list + 1;
          std::ptrdiff_t stride = 1;
          for (int a = 0; a < 3; ++a) {
            const int n = cell.res[a];
            const int i = clamp_cell((entry[a] - cell.lo[a]) * cell.inv_cell[a], n);
            leaf.init_axis(a, i, n, stride, grid_plane(cell.lo[a], cell.hi[a], cell.cell[a], i, n),
                           grid_plane(cell.lo[a], cell.hi[a], cell.cell[a], i + 1, n), o[a], d[a], inv_d[a],
                           cell.cell[a], cell.inv_cell[a]);
            stride *= n;
          }
          for (;;) {
            if constexpr (kCount) ++counters.nodes_visited;
            const float t_leaf_exit = leaf.exit();
            // 0: the leaf cell holds primitives; else the distance in cells to one that does.
            const int leaf_distance = leaf_skip[leaf.index];
            on_cell(index, leaf.cell, leaf_distance == 0, std::max(leaf_distance - 1, 0));
            if (leaf_distance > 1) {
              // Every leaf cell within leaf_distance - 1 is empty: cross that cube in one jump.
              float t_leave;
              const GridWalk::Jump jump = leaf.jump(leaf_distance - 1, tmax, t_leave);
              if (jump == GridWalk::Jump::kStop) over = true;  // the ray's range ends in it
              if (jump != GridWalk::Jump::kMoved) break;
              continue;
            }
            // The same early exit as in a uniform grid: a hit no farther than this leaf cell's
            // exit is the closest (every primitive is in every leaf cell it touches, or in the
            // list of a top cell already entered).
            if ((leaf_distance == 0 && test_cell(leaf.index)) || tmax <= t_leaf_exit) {
              over = true;
              break;
            }
            if (!leaf.step()) break;  // out of the leaf grid: back to the top walk
          }
        }
        if (over) break;
      }
    } else {
      on_cell(index, nullptr, false, std::max(distance - 1, 0));
      if (distance > 1) {
        // Every top cell within distance - 1 of this one is empty: cross that cube in one jump.
        float t_leave;
        if (top.jump(distance - 1, tmax, t_leave) != GridWalk::Jump::kMoved) break;
        t_enter = t_leave;
        continue;
      }
    }
    if (tmax <= t_exit) break;
    if (!top.step()) break;  // stepped out of the grid
    t_enter = t_exit;
  }
  return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
}

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
std::vector<WalkedCell> TwoLevelGrid::cells_on_ray(const Ray& ray) const {
  std::vector<WalkedCell> cells;
  const std::size_t nx = m_top_resolution[0], ny = m_top_resolution[1];
  // A top or leaf cell; with reach > 0, the cube of empty cells within reach of it that the walk
  // crosses in one jump (clipped to its grid), as the union of the cube's two corner cells.
  auto record = [&](std::size_t index, const int* leaf, bool tested, int reach) {
    const int x = int(index % nx), y = int((index / nx) % ny), z = int(index / (nx * ny));
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      const int at = leaf == nullptr ? (a == 0 ? x : a == 1 ? y : z) : leaf[a];
      const int n = leaf == nullptr ? m_top_resolution[a] : std::max(m_top[index].res[a], 1);
      lo[a] = std::max(at - reach, 0);
      hi[a] = std::min(at + reach, n - 1);
    }
    Box3 box = leaf == nullptr ? top_cell_box(lo[0], lo[1], lo[2]) : leaf_cell_box(x, y, z, lo[0], lo[1], lo[2]);
    box.extend(leaf == nullptr ? top_cell_box(hi[0], hi[1], hi[2]) : leaf_cell_box(x, y, z, hi[0], hi[1], hi[2]));
    cells.push_back({box, tested});
  };
  Ray probe = ray;
  Hit hit;
  TraversalStats stats;
  run<false, true>(probe, hit, &stats, record);
  return cells;
}

// The four entry points, which call the kernel of the structure's instruction set.
RAYLAB_INSTANTIATE_ENTRY_POINTS(TwoLevelGrid);

#endif  // RAYLAB_KERNEL_VARIANT

// The kernel, compiled here for this translation unit's instruction set.
RAYLAB_INSTANTIATE_TRAVERSE(TwoLevelGrid);

}  // namespace raylab
