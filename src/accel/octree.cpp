// The octree accelerator: parametric top-down traversal in ray order (Revelles, Urena & Lastra
// 2000, "An efficient parametric algorithm for octree traversal"), iterative, with mailboxes.
//
// The ray's direction is mirrored so that every component is positive: axes where it is negative
// (bit set in the octant mask `a`, -0 included) swap their near and far planes, and a child
// numbered c in the mirrored frame is child c ^ a in memory. Per axis, a node's far plane is
// crossed at t1 and its centre plane at tm; the ray is in the upper half of the node along an axis
// once t > tm. Entering a node at parameter t, the first child is the one whose bit is set for
// every axis with tm <= t; leaving a child through the nearest of its exit planes (tm where its
// bit is clear, t1 where set), the next child sets the bits of the axes crossed there, or, when
// one of them is already set, the ray leaves the parent too (Revelles' exit-plane table).
//
// Unlike the paper, tm is computed from the centre plane itself, (mid - origin) / direction, not
// as (t0 + t1) / 2: the mean of two large opposite values (a ray nearly parallel to an axis's
// planes) loses every digit of a small tm, and the mean of -inf and +inf (a zero direction
// component) is NaN. Computed from the plane, each crossing is within a few ulps of its own
// distance, zero components give infinities of the right sign (also for -0, whose reciprocal is
// -inf), and the one NaN left, an origin exactly on a plane it runs parallel to, is given a side
// (either is right: the build's margin puts what lies on the plane in both).

#include "raylab/accel/octree.h"
#include "raylab/core/stopwatch.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <type_traits>

#include "leaf_test.h"
#include "mailbox.h"
#include "raylab/simd/float4.h"
#include "traversal_common.h"
#include "traversal_entry_points.h"
#include "wide_bvh_leaf.h"

namespace raylab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// A hit closer than the exit of the current cell ends the traversal, but only when it lies clearly
// inside: a hit within this relative distance of the exit may be matched by a lower-id primitive
// at the same distance that the next cell holds (the tie rule), or be a rounding away from a
// closer hit there. Testing one more cell costs nothing measurable.
constexpr float kExitSlack = 0x1p-16f;

// The closest-hit limit beyond which no cell needs visiting.
inline float visit_limit(float tmax) { return tmax + std::fabs(tmax) * kExitSlack; }

inline float min3(float a, float b, float c) {
  const float m = a < b ? a : b;
  return m < c ? m : c;
}

// One interior node on the way down: its crossings, the children worth entering and the child
// being visited. Crossings of its near planes are not kept: the traversal only needs where the
// ray is now.
struct Frame {
  // Per axis in lanes 0-2 (lane 3 stays 0), loaded and stored as simd::Float4.
  alignas(16) float tm[4];    // crossings of its middle planes, mirrored frame
  alignas(16) float t1[4];    // crossings of its far planes, mirrored frame
  alignas(16) float lo[4];    // its low corner on the lattice (integers, exact in float up to 2^24)
  float half;                 // half its edge, in lattice steps
  std::uint32_t first_child;  // index of its child 0
  unsigned enter;             // bit c: the ray enters child c's content box (memory numbering)
  unsigned ahead;             // the same children in the mirrored numbering, for the walk's order
  int child;                  // the child being visited, in the mirrored numbering
  float t_enter[8];           // where the ray enters each child's content box (memory numbering)
};

// Where the ray crosses the tree's lattice planes. Usually step * k + b, an affine function of
// the step that is monotonic like the planes themselves, so children never overlap or leave
// gaps along the ray; its rounding (a few ulps of the root's size and of the origin's distance)
// is what the build's margin covers. A zero or tiny direction component makes k or b infinite
// and that form inf - inf, so such rays compute (plane - origin) / direction instead, where
// 0 * inf (the origin in a plane it runs parallel to) picks a side: `if_on_plane`.
class LatticeCrossings {
 public:
  LatticeCrossings(const OctreeTree& tree, Vec3 origin, Vec3 inv) : m_tree(tree), m_origin(origin), m_inv(inv) {
    for (int i = 0; i < 3; ++i) {
      m_k[i] = tree.root_size * 0x1p-24f * inv[i];
      m_b[i] = (tree.root_lo[i] - origin[i]) * inv[i];
      m_affine = m_affine && std::isfinite(m_k[i]) && std::isfinite(m_b[i]);
    }
  }

  // The crossing of lattice plane `step` along axis i.
  float at(int i, float step, float if_on_plane) const {
    if (m_affine) return step * m_k[i] + m_b[i];
    const float t = (m_tree.plane(i, static_cast<std::uint32_t>(step)) - m_origin[i]) * m_inv[i];
    return std::isnan(t) ? if_on_plane : t;
  }

  // The crossings of the planes `step[0..2]` of the three axes into t[0..2] (t[3] = 0): the same
  // numbers as `at`, the affine form four lanes at once.
  void at3(const float* step, float if_on_plane, float* t) const {
    if (m_affine) {
      (simd::Float4::load(step) * simd::Float4::load(m_k) + simd::Float4::load(m_b)).store(t);
      return;
    }
    for (int i = 0; i < 3; ++i) t[i] = at(i, step[i], if_on_plane);
    t[3] = 0.f;
  }

 private:
  const OctreeTree& m_tree;
  Vec3 m_origin, m_inv;
  alignas(16) float m_k[4] = {0.f, 0.f, 0.f, 0.f};  // lane 3 stays 0, so at3's lane 3 is 0
  alignas(16) float m_b[4] = {0.f, 0.f, 0.f, 0.f};
  bool m_affine = true;
};

// Per child c, lane i: 1 where bit i of c is set (lane 3: 0). A child's lattice corner is its
// parent's plus these times half the parent's edge.
constexpr float kChildBits[8][4] = {{0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {1, 1, 0, 0},
                                    {0, 0, 1, 0}, {1, 0, 1, 0}, {0, 1, 1, 0}, {1, 1, 1, 0}};
// Per child c, lane i: +inf where bit i of c is set, else 0. min(tm + this, t1) picks, per axis,
// t1 where the child is in the upper half and tm where it is in the lower one, as
// `bit ? t1 : tm` does: tm <= t1 always (crossings are monotonic in the plane), tm + inf is inf
// or, for tm = -inf, NaN, and min returns its second operand on NaN.
constexpr float kChildInf[8][4] = {{0, 0, 0, 0},    {kInf, 0, 0, 0},    {0, kInf, 0, 0},    {kInf, kInf, 0, 0},
                                   {0, 0, kInf, 0}, {kInf, 0, kInf, 0}, {0, kInf, kInf, 0}, {kInf, kInf, kInf, 0}};

// The exit planes of child c of frame `f`: per axis t1 where c is in the upper half, else tm.
inline simd::Float4 child_far(const float* tm, const float* t1, int c) {
  return min(simd::Float4::load(tm) + simd::Float4::load(kChildInf[c]), simd::Float4::load(t1));
}

// Completes frame `g` for interior node `node` of edge `size` (its far crossings and lattice
// corner are set): the middle crossings, and the child holding the ray at t_cur. Which children
// are worth entering is the caller's (the box test). A ray in a
// centre plane and parallel to it may take either half (the margin put what lies on the plane in
// both); it takes the lower one of the mirrored frame.
inline void open_frame(Frame& g, const OctreeNode& node, float size, const LatticeCrossings& crossing, float t_cur) {
  g.first_child = node.first;
  g.half = 0.5f * size;
  alignas(16) float mid[4];
  (simd::Float4::load(g.lo) + simd::Float4::broadcast(g.half)).store(mid);
  crossing.at3(mid, kInf, g.tm);
  g.child = less_equal_mask(simd::Float4::load(g.tm), simd::Float4::broadcast(t_cur)) & 7;
}

// kMirrored[octant][mask]: `mask` with bit c moved to bit c ^ octant, the mirrored numbering of a
// set of children. One table lookup per opened node (2 KiB, which stays in the L1 cache) where
// three conditional bit-group swaps cost 5% of a mesh ray's instructions (callgrind).
struct MirroredMasks {
  std::uint8_t bits[8][256];
  constexpr MirroredMasks() : bits{} {
    for (int octant = 0; octant < 8; ++octant) {
      for (int mask = 0; mask < 256; ++mask) {
        int m = 0;
        for (int c = 0; c < 8; ++c) m |= ((mask >> c) & 1) << (c ^ octant);
        bits[octant][mask] = static_cast<std::uint8_t>(m);
      }
    }
  }
};
constexpr MirroredMasks kMirrored;

inline unsigned mirrored_mask(unsigned mask, int octant) { return kMirrored.bits[octant][mask]; }

// The children (mirrored numbering) the walk can still reach after child c: the ray only ever
// moves to higher halves, so those whose bits include all of c's, c excluded.
constexpr unsigned kLaterChildren[8] = {0xfeu, 0xa8u, 0xc8u, 0x80u, 0xe0u, 0x80u, 0x80u, 0x00u};

// Edge of the root in lattice steps.
constexpr float kRootLatticeSteps = static_cast<float>(kOctreeLatticeSteps);

// Sets the root's frame `root` (far crossings, lattice corner) for a ray of direction octant
// `octant`; returns where the ray enters the root. An origin in a face plane counts as inside
// (the root is larger than the primitives, so nothing can be lost either way).
inline float enter_root(Frame& root, const LatticeCrossings& crossing, int octant) {
  float t_enter = -kInf;
  for (int i = 0; i < 3; ++i) {
    const bool mirrored = (octant >> i) & 1;
    const float t = crossing.at(i, mirrored ? kRootLatticeSteps : 0.f, -kInf);  // never NaN
    t_enter = t > t_enter ? t : t_enter;
    root.t1[i] = crossing.at(i, mirrored ? 0.f : kRootLatticeSteps, kInf);
    root.lo[i] = 0.f;
  }
  root.t1[3] = root.lo[3] = 0.f;  // the unused lane
  return t_enter;
}

// The ray's mailbox stamp, or none when mailboxing is off (then every reference is tested). The
// stamp is taken only when the ray enters the tree: rays that miss never touch the mailboxes.
struct OptionalMailbox {
  std::optional<Mailboxes::RayStamp> stamp;
  bool first_visit(std::uint32_t slot) { return !stamp || stamp->first_visit(slot); }
};

// The `on_cell` of a query: hears nothing, costs nothing.
struct IgnoreCells {
  void operator()(const Box3&, bool) const {}
};

}  // namespace

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
Octree::Octree(const Geometry& geometry, const OctreeConfig& config)
    : Octree(geometry, geometry.primitive_ids(), config) {}

Octree::Octree(const Geometry& geometry, std::span<const std::uint32_t> ids, const OctreeConfig& config)
    : m_geometry(geometry), m_config(config) {
  const auto start = std::chrono::steady_clock::now();
  m_config.max_items = std::max(m_config.max_items, 0);
  m_config.max_depth = std::clamp(m_config.max_depth, 0, kOctreeDepthLimit);
  m_tree = build_octree(geometry, ids, m_config);
  m_cylinder_frames = CylinderFrames::of(geometry, m_tree.ids);
  m_mailboxes = std::make_unique<Mailboxes>(static_cast<std::uint32_t>(m_tree.ids.size()));
  m_build_seconds = seconds_since(start);
}

Octree::~Octree() = default;

#endif  // RAYLAB_KERNEL_VARIANT

template <bool kAnyHit, bool kCount, class K>
bool Octree::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  return walk<kAnyHit, kCount>(ray, hit, stats, IgnoreCells{});
}

template <bool kAnyHit, bool kCount, class OnCell>
bool Octree::walk(Ray& ray, Hit& hit, TraversalStats* stats, OnCell&& on_cell) const {
  constexpr bool kRecord = !std::is_same_v<std::decay_t<OnCell>, IgnoreCells>;
  TraversalCounters counters;
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  Hit best = hit;
  bool found = false;
  if (m_tree.nodes.empty()) return finish_traversal<kCount>(false, tmax, best, {}, ray, hit, stats);

  const int octant = direction_octant(ray.direction);
  const Vec3 o = ray.origin;
  const Vec3 inv = safe_reciprocal(ray.direction);

  const WatertightRay tri_ray(ray);
  const OctreeNode* const nodes = m_tree.nodes.data();
  const std::uint32_t* const refs = m_tree.refs.data();
  const GeometryPrimitives prims(m_tree.ids.data(), m_cylinder_frames, m_geometry);
  OptionalMailbox mailbox;

  // Tests the primitives of leaf `node` against the whole remaining ray (not just the cell's
  // stretch of it), so a hit found here counts wherever it lies. True on an any-hit.
  auto test_leaf = [&](const OctreeNode& node) {
    if (!intersect_references<kAnyHit, kCount>(prims, node.first, node.first + node.count, SlotFromList{refs}, mailbox,
                                               tri_ray, ray, tmin, tmax, best, counters)) {
      return false;
    }
    found = true;
    return kAnyHit;
  };

  const LatticeCrossings crossing(m_tree, o, inv);

  Frame stack[kOctreeDepthLimit];
  Frame* f = stack;
  // Tells on_cell of child `actual` (memory numbering) of the innermost open node.
  auto report_child = [&](int actual, bool tested) {
    if constexpr (kRecord) {
      std::uint32_t lo[3];
      for (int i = 0; i < 3; ++i) lo[i] = static_cast<std::uint32_t>(f->lo[i] + (((actual >> i) & 1) ? f->half : 0.f));
      const std::uint32_t size = static_cast<std::uint32_t>(f->half);
      on_cell(Box3{{m_tree.plane(0, lo[0]), m_tree.plane(1, lo[1]), m_tree.plane(2, lo[2])},
                   {m_tree.plane(0, lo[0] + size), m_tree.plane(1, lo[1] + size), m_tree.plane(2, lo[2] + size)}},
              tested);
    }
  };

  const float t_enter = enter_root(*f, crossing, octant);
  const float t_leave = min3(f->t1[0], f->t1[1], f->t1[2]);
  const float limit = visit_limit(tmax);
  // Where the ray is now: it enters each cell at the parameter it left the previous one.
  float t_cur = t_enter > tmin ? t_enter : tmin;
  if (!(t_cur <= (t_leave < limit ? t_leave : limit))) {
    return finish_traversal<kCount>(false, tmax, best, {}, ray, hit, stats);
  }
  if constexpr (kCount) ++counters.nodes_visited;
  if (nodes[0].is_leaf()) {
    if constexpr (kRecord) on_cell(m_tree.cell_box(std::array<std::uint32_t, 3>{0, 0, 0}.data(), 0), true);
    if (m_config.mailbox) mailbox.stamp.emplace(m_mailboxes->begin_ray());
    test_leaf(nodes[0]);
    return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
  }

  // The children's content boxes decide which children the ray enters at all: one 8-wide slab
  // test per interior node (the wide BVH's), conservative as the BVH's is.
  const WideBoxRay<8> box_ray(ray);
  auto test_children = [&](const OctreeChildBoxes& boxes, Frame& g) {
    g.enter = box_ray.test(boxes, tmin, tmax, g.t_enter);
  };
  open_frame(*f, nodes[0], kRootLatticeSteps, crossing, t_cur);
  test_children(m_tree.boxes[0], *f);
  f->ahead = mirrored_mask(f->enter, octant);
  if (f->enter == 0) {
    if constexpr (kRecord) on_cell(m_tree.cell_box(std::array<std::uint32_t, 3>{0, 0, 0}.data(), 0), false);
    return finish_traversal<kCount>(false, tmax, best, counters, ray, hit, stats);
  }
  // The stamp is taken only once the ray reaches some content: rays that miss never touch the mailboxes.
  if (m_config.mailbox) mailbox.stamp.emplace(m_mailboxes->begin_ray());

  for (;;) {
    // Visit the current child of the innermost open node, unless the ray misses its content or,
    // since the node was opened, a hit closer than the content was found.
    const int actual = f->child ^ octant;
    if (((f->enter >> actual) & 1) && f->t_enter[actual] <= widen_exit(tmax)) {
      const OctreeNode node = nodes[f->first_child + static_cast<std::uint32_t>(actual)];
      if constexpr (kCount) ++counters.nodes_visited;
      if (!node.is_leaf()) {
        Frame& g = f[1];
        child_far(f->tm, f->t1, f->child).store(g.t1);
        (simd::Float4::load(f->lo) + simd::Float4::load(kChildBits[actual]) * simd::Float4::broadcast(f->half))
            .store(g.lo);
        open_frame(g, node, f->half, crossing, t_cur);
        test_children(m_tree.child_boxes(node), g);
        if (g.enter != 0) {
          g.ahead = mirrored_mask(g.enter, octant);
          ++f;
          continue;
        }
        report_child(actual, false);
      } else {
        report_child(actual, true);
        if (test_leaf(node)) return finish_traversal<kCount>(true, tmax, best, counters, ray, hit, stats);
      }
    } else {
      report_child(actual, false);
    }

    // Step to the next cell along the ray: leave the current child through its nearest exit
    // plane; a child already in the upper half along that axis leaves its parent too.
    for (;;) {
      const int c = f->child;
      // No child the ray enters lies ahead in this node: leave it without stepping through the rest.
      if ((f->ahead & kLaterChildren[c]) == 0) {
        if (f == stack) return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
        --f;
        continue;
      }
      alignas(16) float exits[4];
      const simd::Float4 exit4 = child_far(f->tm, f->t1, c);
      exit4.store(exits);
      const float t_exit = min3(exits[0], exits[1], exits[2]);
      // Cells beyond the closest hit cannot hold a closer one; an exit at infinity means the ray
      // never leaves (a zero direction).
      if (!(t_exit <= visit_limit(tmax)) || t_exit == kInf) {
        return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
      }
      // Every axis that reaches the exit at once (a ray through an edge or a corner).
      const int crossed = equal_mask(exit4, simd::Float4::broadcast(t_exit)) & 7;
      if ((crossed & c) == 0) {
        f->child = c | crossed;
        t_cur = t_exit;
        break;
      }
      if (f == stack) return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
      --f;
    }
  }
}

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
std::vector<WalkedCell> Octree::cells_on_ray(const Ray& ray) const {
  std::vector<WalkedCell> cells;
  Ray r = ray;
  Hit h;
  walk<false, false>(r, h, nullptr, [&](const Box3& box, bool tested) { cells.push_back({box, tested}); });
  return cells;
}

// The four entry points, which call the kernel of the structure's instruction set.
RAYLAB_INSTANTIATE_ENTRY_POINTS(Octree);

AccelInfo Octree::info() const {
  AccelInfo info;
  info.name = "octree";
  info.build_seconds = m_build_seconds;
  info.memory_bytes = m_tree.nodes.capacity() * sizeof(OctreeNode) +
                      m_tree.boxes.capacity() * sizeof(OctreeChildBoxes) +
                      (m_tree.refs.capacity() + m_tree.ids.capacity()) * sizeof(std::uint32_t) +
                      m_mailboxes->bytes_per_thread() + m_cylinder_frames.bytes();
  info.node_count = m_tree.nodes.size();
  info.leaf_count = m_tree.leaf_count;
  info.primitive_count = m_tree.ids.size();
  info.max_depth = m_tree.max_depth;
  return info;
}

#endif  // RAYLAB_KERNEL_VARIANT

// The kernel, compiled here for this translation unit's instruction set.
RAYLAB_INSTANTIATE_TRAVERSE(Octree);

}  // namespace raylab
