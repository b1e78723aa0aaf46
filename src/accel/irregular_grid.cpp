// Irregular grid traversal: look the ray's current lattice voxel up, test the cell's references
// over the ray's whole range, and jump to the voxel just beyond the cell's expanded box where the
// ray leaves it.
//
// Why it is right: every primitive meeting the ray inside a cell's expanded box is in that cell's
// references (the expansion only covers cells whose references the cell holds, and insertion
// enlarges cells by the grid margins, which absorb the rounding of the exit point). So when the
// closest hit so far lies before the exit, nothing beyond can be closer.
//
// Why it ends: the voxel coordinates only ever move in the ray's direction. Along the exit axis
// the next voxel lies just beyond the expanded box; along the others it is computed from the exit
// point, clamped into the expanded box and never moved backwards. The walk can thus never come
// back into a cell it left, and it stops when it leaves the lattice.

#include "raylab/accel/irregular_grid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "leaf_test.h"
#include "mailbox.h"
#include "raylab/core/stopwatch.h"
#include "traversal_common.h"
#include "traversal_entry_points.h"

namespace raylab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Stands in for cells_on_ray's recorder in the timed walk.
struct NoVisit {
  void operator()(const IrregularCell&, bool) const {}
};

}  // namespace

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
IrregularGrid::IrregularGrid(const Geometry& geometry, const IrregularGridConfig& config)
    : IrregularGrid(geometry, geometry.primitive_ids(), config) {}

IrregularGrid::IrregularGrid(const Geometry& geometry, std::span<const std::uint32_t> ids,
                             const IrregularGridConfig& config)
    : m_geometry(geometry), m_config(config) {
  const auto start = std::chrono::steady_clock::now();
  m_data = build_irregular_grid(geometry, ids, config);
  // The cells' own boxes are for tests of the builder; the walk needs only the expanded ones.
  m_data.boxes = {};
  // Copies of the triangles and spheres in the grid's spatial order: a cell's references then
  // point to neighbouring entries instead of all over the scene (on the armadillo, whose
  // triangles are stored in no spatial order, testing them in place cost most of the time).
  copy_slot_primitives(geometry, m_data.ids, m_triangles, m_spheres);
  m_cylinder_frames = CylinderFrames::of(geometry, m_data.ids);
  if (config.mailbox && !m_data.ids.empty()) {
    m_mailboxes = std::make_unique<Mailboxes>(static_cast<std::uint32_t>(m_data.ids.size()));
  }
  m_build_seconds = seconds_since(start);
}

IrregularGrid::~IrregularGrid() = default;

#endif  // RAYLAB_KERNEL_VARIANT

template <bool kAnyHit, bool kCount, class K>
bool IrregularGrid::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  if (m_mailboxes) {
    return walk<kAnyHit, kCount>(
        ray, hit, stats, [&] { return m_mailboxes->begin_ray(); }, NoVisit{});
  }
  return walk<kAnyHit, kCount>(
      ray, hit, stats, [] { return TestEverySlot{}; }, NoVisit{});
}

template <bool kAnyHit, bool kCount, class MakeMailbox, class Visit>
bool IrregularGrid::walk(Ray& ray, Hit& hit, TraversalStats* stats, MakeMailbox make_mailbox, Visit&& visit) const {
  const IrregularGridData& g = m_data;
  TraversalCounters counters;  // nodes_visited: the cells looked up
  const Vec3 o = ray.origin, d = ray.direction;
  // An infinite or NaN origin makes every distance NaN; such a ray hits nothing.
  if (g.cells.empty() || !std::isfinite(o.x + o.y + o.z)) {
    return finish_traversal<kCount>(false, ray.tmax, hit, counters, ray, hit, stats);
  }
  // Clip to the grid box, the far distance widened as in the BVH so that a ray grazing the box
  // where a primitive lies in its face still enters.
  const Vec3 inv_d = safe_reciprocal(d);
  float t_in = ray.tmin, t_out = ray.tmax;
  for (int a = 0; a < 3; ++a) {
    float t0 = (g.bounds.lo[a] - o[a]) * inv_d[a];
    float t1 = (g.bounds.hi[a] - o[a]) * inv_d[a];
    if (inv_d[a] < 0.f) std::swap(t0, t1);
    t_in = t0 > t_in ? t0 : t_in;  // a NaN slab (0 * inf: origin in a face plane) is ignored
    t_out = t1 < t_out ? t1 : t_out;
  }
  if (!(t_in <= widen_exit(t_out))) return finish_traversal<kCount>(false, ray.tmax, hit, counters, ray, hit, stats);

  // The entry voxel, from the entry point (clamped: rounding may put it just outside). A
  // component so small that its reciprocal overflows moves the ray across no plane within float
  // range of t; it is treated as zero, like +-0 ("still" axes never give the exit).
  const Vec3 entry = ray.at(t_in);
  // Per-ray constants of one step:
  //  - the ray's point at t lies at lattice coordinate p_base[a] + t * p_step[a];
  //  - far[a] picks the plane the ray leaves through from the cell's six bounds (lo x, y, z,
  //    hi x, y, z): hi[a] moving up, lo[a] moving down; the voxel beyond it is that plane's
  //    index plus beyond[a] (0 up, -1 down).
  // The exit distances stay (plane - o) / d per plane: the incremental form t_base + k * t_step
  // overflows to inf - inf for a component near FLT_MIN (tests/accel/robustness_test.cpp).
  int voxel[3];
  bool still[3];
  float p_base[3], p_step[3];
  int far[3], beyond[3];
  for (int a = 0; a < 3; ++a) {
    const int n = g.lattice[a];
    const float f = (entry[a] - g.origin[a]) * g.inv_step[a];
    voxel[a] = f >= 0.f ? (f < float(n) ? static_cast<int>(f) : n - 1) : 0;  // NaN -> 0
    const bool up = d[a] > 0.f;
    still[a] = d[a] == 0.f || !std::isfinite(inv_d[a]);
    p_base[a] = (o[a] - g.origin[a]) * g.inv_step[a];
    p_step[a] = d[a] * g.inv_step[a];
    far[a] = up ? 3 + a : a;
    beyond[a] = up ? 0 : -1;
  }
  const IrregularCell* const cells = g.cells.data();
  auto mailbox = make_mailbox();
  const WatertightRay wr(ray);
  const SlotPrimitives prims(g.ids.data(), m_triangles, m_spheres, m_cylinder_frames, m_geometry);
  const SlotFromList slots{g.refs.data()};
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  Hit best = hit;
  bool found = false;
  for (;;) {
    const std::uint32_t c = g.cell_at(voxel[0], voxel[1], voxel[2]);
    const IrregularCell& cell = cells[c];
    const std::uint32_t end = cells[c + 1].first;
    if constexpr (kCount) ++counters.nodes_visited;
    visit(cell, cell.first != end);
    if (cell.first != end && intersect_references<kAnyHit, kCount>(prims, cell.first, end, slots, mailbox, wr, ray,
                                                                   tmin, tmax, best, counters)) {
      found = true;
      if constexpr (kAnyHit) break;
    }
    // Where the ray leaves the expanded box: the nearest of its three far planes.
    std::uint16_t bound[6];
    std::memcpy(bound, &cell, sizeof(bound));
    float t[3];
    for (int a = 0; a < 3; ++a) t[a] = still[a] ? kInf : (g.plane(a, bound[far[a]]) - o[a]) * inv_d[a];
    const float t_exit = std::min(t[0], std::min(t[1], t[2]));
    // A hit before the exit is the closest (see the top of the file); a range ending inside the
    // box has nothing farther to look at. A ray that moves along no axis has t_exit = inf.
    if (tmax <= t_exit) break;
    const int x = t[0] == t_exit ? 0 : (t[1] == t_exit ? 1 : 2);
    const int next = int(bound[far[x]]) + beyond[x];
    if (next < 0 || next >= g.lattice[x]) break;  // left the lattice
    for (int a = 0; a < 3; ++a) {
      if (a == x || still[a]) continue;
      const int n = g.lattice[a];
      const float f = p_base[a] + t_exit * p_step[a];
      int k = f >= 0.f ? (f < float(n) ? static_cast<int>(f) : n - 1) : 0;
      k = std::clamp(k, int(bound[a]), int(bound[3 + a]) - 1);
      voxel[a] = beyond[a] == 0 ? std::max(k, voxel[a]) : std::min(k, voxel[a]);
    }
    voxel[x] = next;
  }
  return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
}

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
std::vector<WalkedCell> IrregularGrid::cells_on_ray(const Ray& ray) const {
  std::vector<WalkedCell> out;
  Ray probe = ray;
  Hit scratch;
  auto record = [&](const IrregularCell& cell, bool has_primitives) {
    out.push_back({m_data.lattice_box(cell.lo, cell.hi), has_primitives});
  };
  if (m_mailboxes) {
    walk<false, false>(
        probe, scratch, nullptr, [&] { return m_mailboxes->begin_ray(); }, record);
  } else {
    walk<false, false>(
        probe, scratch, nullptr, [] { return TestEverySlot{}; }, record);
  }
  return out;
}

AccelInfo IrregularGrid::info() const {
  AccelInfo info;
  info.name = "irregular";
  info.build_seconds = m_build_seconds;
  info.memory_bytes =
      sizeof(*this) + m_data.cells.size() * sizeof(IrregularCell) +
      (m_data.refs.size() + m_data.ids.size() + m_data.top.size() + m_data.map.size()) * sizeof(std::uint32_t) +
      m_data.nodes.size() * sizeof(IrregularGridData::Node) + m_triangles.size() * sizeof(Triangle) +
      m_spheres.size() * sizeof(Sphere) + m_cylinder_frames.bytes();
  info.node_count = m_data.cell_count();
  info.leaf_count = m_data.nonempty_cells;
  info.primitive_count = m_data.ids.size();
  info.max_depth = 0;
  return info;
}

// The four entry points, which call the kernel of the structure's instruction set.
RAYLAB_INSTANTIATE_ENTRY_POINTS(IrregularGrid);

#endif  // RAYLAB_KERNEL_VARIANT

// The kernel, compiled here for this translation unit's instruction set.
RAYLAB_INSTANTIATE_TRAVERSE(IrregularGrid);

}  // namespace raylab
