#pragma once
// The leaf test and the box test of the wide BVH (internal to src/accel), shared by the
// single-ray and the packet traversals so that both compute exactly the same numbers. The
// octree tests its nodes' child boxes with the same box test.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "leaf_test.h"
#include "raylab/accel/wide_bvh.h"
#include "raylab/core/float_neighbour.h"
#include "raylab/geometry/cylinder_lanes.h"
#include "raylab/geometry/sphere_lanes.h"
#include "raylab/simd/isa_namespace.h"
#include "raylab/simd/wide_float.h"
#include "traversal_common.h"

namespace raylab {
RAYLAB_ISA_BEGIN

/// The number of triangle blocks of a leaf whose node slot holds `count_flags`: the leaf's
/// triangles are the blocks [first, first + this), unused lanes (kNoPrimitive) excepted. When
/// it is 0, `first` is no block index (the leaf's ids are elsewhere).
template <int W>
inline std::uint32_t leaf_block_count(std::uint32_t count_flags) {
  return WideBvhLeaves::block_count(count_flags);
}

/// Whether the leaf holds primitives other than triangles (tested by intersect_wide_leaf_others).
template <int W>
inline bool leaf_has_others(std::uint32_t count_flags) {
  return (count_flags & WideBvhNode<W>::kLeafHasOthers) != 0;
}

/// Tests the spheres `ids` (a run of a leaf's list in `leaves.others`) four lanes at a time from
/// the leaves' sphere lanes, with intersect_wide_leaf_others' contract. Each group of lanes is
/// tested up to the largest limit the tie rule may apply, then the rule is applied lane by lane
/// in list order, which gives what testing the spheres one by one gives (intersect_sphere_lanes).
template <bool kAnyHit>
[[gnu::always_inline]] inline bool intersect_leaf_spheres(const WideBvhLeaves& leaves,
                                                          std::span<const std::uint32_t> ids, const Ray& ray,
                                                          float tmin, float& tmax, Hit& best) {
  const auto at = static_cast<std::size_t>(ids.data() - leaves.others.data());
  const auto n = static_cast<std::uint32_t>(ids.size());
  bool found = false;
  for (std::uint32_t k = 0; k < n; k += 4) {
    const int lanes = n - k >= 4 ? 0xF : (1 << (n - k)) - 1;
    alignas(16) float t[4];
    int mask = intersect_sphere_lanes(leaves.sphere_lanes_at(at + k), lanes, ray, tmin,
                                      kAnyHit ? tmax : next_float_up(tmax), t);
    if constexpr (kAnyHit) {
      if (mask != 0) return true;
      continue;
    }
    while (mask != 0) {
      const int i = std::countr_zero(static_cast<unsigned>(mask));
      mask &= mask - 1;
      const std::uint32_t id = ids[k + i];
      if (t[i] < best.tie_limit(id, tmax)) {
        tmax = t[i];
        best = Hit{t[i], id, 0.f, 0.f};
        found = true;
      }
    }
  }
  return found;
}

/// The numbers of spheres and then cylinders heading a leaf's list `ids`, counted from the ids:
/// for the leaves whose leaf_kinds entry is saturated (255 or more of a kind). `cylinders` is
/// where the cylinders end.
[[gnu::cold, gnu::noinline]] inline void count_leaf_kinds(const WideBvhLeaves& leaves, const Geometry& geometry,
                                                          std::span<const std::uint32_t> ids, std::size_t& spheres,
                                                          std::size_t& cylinders) {
  const auto sphere_count = static_cast<std::uint32_t>(geometry.spheres.size());
  spheres = 0;
  while (spheres < ids.size() && ids[spheres] - leaves.triangle_count < sphere_count) ++spheres;
  cylinders = spheres;  // the cylinders are the ids with a frame, as the collapse lists them
  while (cylinders < ids.size() && leaves.cylinder_frame_of(ids[cylinders]) != nullptr) ++cylinders;
}

/// A leaf's list of primitives other than triangles: its ids, their position in
/// `leaves.others` (where the sphere and cylinder lanes of the same ids lie), and where its
/// spheres and then its cylinders end (the collapse lists them first, in that order, and counts
/// them in WideBvhLeaves::leaf_kinds).
struct LeafOthers {
  std::span<const std::uint32_t> ids;  ///< the list
  std::size_t position = 0;            ///< ids[0]'s position in leaves.others
  std::size_t sphere_end = 0;          ///< ids [0, sphere_end) are spheres
  std::size_t cylinder_end = 0;        ///< ids [sphere_end, cylinder_end) are cylinders
};

/// The list of the leaf whose node slot holds `first` and `count_flags` (with others in it).
[[gnu::always_inline]] inline LeafOthers leaf_others(const WideBvhLeaves& leaves, const Geometry& geometry,
                                                     std::uint32_t first, std::uint32_t count_flags) {
  LeafOthers others;
  others.ids = leaves.others_of(first, count_flags);
  others.position = static_cast<std::size_t>(others.ids.data() - leaves.others.data());
  const WideBvhLeaves::LeafKinds kinds = leaves.leaf_kinds[others.position];
  others.sphere_end = kinds.spheres;
  others.cylinder_end = others.sphere_end + kinds.cylinders;
  if (kinds.spheres == WideBvhLeaves::kKindCountSaturated || kinds.cylinders == WideBvhLeaves::kKindCountSaturated)
      [[unlikely]] {
    count_leaf_kinds(leaves, geometry, others.ids, others.sphere_end, others.cylinder_end);
  }
  return others;
}

/// Tests the primitives `ids` of a leaf's list one by one, each cylinder from its frame and
/// every other kind through the Geometry, with intersect_wide_leaf_others' contract.
template <bool kAnyHit>
[[gnu::always_inline]] inline bool intersect_leaf_one_by_one(const WideBvhLeaves& leaves, const Geometry& geometry,
                                                             std::span<const std::uint32_t> ids,
                                                             const WatertightRay& tri_ray, const Ray& ray, float tmin,
                                                             float& tmax, Hit& best) {
  bool found = false;
  for (const std::uint32_t id : ids) {
    const CylinderFrame* frame = leaves.cylinder_frame_of(id);
    const bool hit = frame != nullptr
                         ? intersect_cylinder_frame<kAnyHit>(*frame, id, ray, tmin, tmax, best)
                         : intersect_through_geometry<kAnyHit>(geometry, id, tri_ray, ray, tmin, tmax, best);
    if (hit) {
      found = true;
      if constexpr (kAnyHit) return true;
    }
  }
  return found;
}

/// Tests the primitives of a leaf listed by id, not in its triangle blocks (`first` and
/// `count_flags` as stored in its node slot), against `ray` restricted to [tmin, tmax); on a hit
/// shrinks `tmax` and updates `best` (closest hit, lower id on ties). With kAnyHit, returns at
/// the first hit. Counts the primitives tested in `counters` when kCount. A leaf lists its
/// spheres first, then its cylinders (the collapse puts them there, and counts them in
/// WideBvhLeaves::leaf_kinds): at least WideBvhLeaves::kSphereLanesFrom spheres
/// are tested four at a time (intersect_leaf_spheres), fewer one by one; then at least
/// WideBvhLeaves::kCylinderLanesFrom cylinders four at a time through the float rejection
/// (cylinders_surely_missed) and one by one through the exact test, fewer one by one from their
/// frames; then every other kind through the Geometry. The list holds no triangles, so it does not
/// go through the common leaf test (intersect_references): inlining that test's triangle and sphere paths into the walk
/// changed its register allocation and cost single-ray occlusion queries 11% more instructions
/// (callgrind, bunny shadow rays), although they never run here. For the same reason this
/// function is kept out of line: inlined, it cost those queries 4% more instructions (31.7 M
/// against 30.5 M out of line, `valgrind --tool=callgrind raylab bench
/// bench/scenes/bunny-on-ground-triangles.json --rays shadow --against none --repeats 1
/// --width 256 --height 192`), on a scene without a sphere; marked cold as well, 7% more.
template <bool kAnyHit, bool kCount, int W>
[[gnu::noinline]] bool intersect_wide_leaf_others(const WideBvhLeaves& leaves, const Geometry& geometry,
                                                  std::uint32_t first, std::uint32_t count_flags,
                                                  const WatertightRay& tri_ray, const Ray& ray, float tmin, float& tmax,
                                                  Hit& best, TraversalCounters& counters) {
  if (!leaf_has_others<W>(count_flags)) return false;
  const LeafOthers others = leaf_others(leaves, geometry, first, count_flags);
  const std::span<const std::uint32_t> ids = others.ids;
  const std::size_t position = others.position, spheres = others.sphere_end;
  std::size_t cylinders = others.cylinder_end;
  if constexpr (kCount) counters.prim_tests += ids.size();
  bool found = false;
  if (spheres >= WideBvhLeaves::kSphereLanesFrom) {
    found = intersect_leaf_spheres<kAnyHit>(leaves, ids.first(spheres), ray, tmin, tmax, best);
    if constexpr (kAnyHit) {
      if (found) return true;
    }
  } else {
    // Too few to pay for the lanes' set-up: the scalar test, from the same copies.
    for (std::size_t k = 0; k < spheres; ++k) {
      if (intersect_sphere_here<kAnyHit>(leaves.sphere_lanes_at(position + k).sphere(0), ids[k], ray, tmin, tmax,
                                         best)) {
        found = true;
        if constexpr (kAnyHit) return true;
      }
    }
  }
  // Then the cylinders, when there are enough of them: four at a time through the float
  // rejection, the rest of each four through the exact test, which together is
  // intersect_cylinder's answer. Fewer are tested one by one below with the other kinds.
  if (cylinders - spheres < WideBvhLeaves::kCylinderLanesFrom) {
    cylinders = spheres;
  } else {
    for (std::size_t k = spheres; k < cylinders; k += 4) {
      const int lanes = (1 << std::min<std::size_t>(4, cylinders - k)) - 1;
      unsigned maybe =
          static_cast<unsigned>(lanes & ~cylinders_surely_missed(leaves.cylinder_lanes.at(position + k), lanes, ray));
      for (; maybe != 0; maybe &= maybe - 1) {
        const std::uint32_t id = ids[k + static_cast<std::size_t>(std::countr_zero(maybe))];
        if (intersect_cylinder_frame_exact<kAnyHit>(*leaves.cylinder_frame_of(id), id, ray, tmin, tmax, best)) {
          found = true;
          if constexpr (kAnyHit) return true;
        }
      }
    }
  }
  if (intersect_leaf_one_by_one<kAnyHit>(leaves, geometry, ids.subspan(cylinders), tri_ray, ray, tmin, tmax, best)) {
    found = true;
  }
  return found;
}

/// Tests the triangles of a leaf (`first` and `count_flags` as stored in its node slot) against
/// `ray` restricted to [tmin, tmax); on a hit shrinks `tmax` and updates `best`. Lanes are taken
/// in order with the exact `t < tie_limit` rule, so the result is the same as testing the
/// triangles one by one (the closest hit, lower id on ties). With kAnyHit, returns at the first
/// hit. Counts the triangles tested in `counters` when kCount.
template <bool kAnyHit, bool kCount, int W>
inline bool intersect_wide_leaf_triangles(const WideBvhLeaves& leaves, std::uint32_t first, std::uint32_t count_flags,
                                          const WatertightRay& tri_ray, float tmin, float& tmax, Hit& best,
                                          TraversalCounters& counters) {
  const std::uint32_t triangle_count = leaves.triangle_count;
  bool found = false;
  for (std::uint32_t b = first; b < first + leaf_block_count<W>(count_flags); ++b) {
    const TriangleBlock4& block = leaves.blocks[b];
    if constexpr (kCount) {
      for (int i = 0; i < 4; ++i) counters.prim_tests += block.id[i] < triangle_count ? 1 : 0;
    }
    alignas(16) float t[4], u[4], v[4];
    int mask = intersect_triangle_block(block, tri_ray, tmin, tmax, t, u, v);
    while (mask != 0) {
      const int i = std::countr_zero(static_cast<unsigned>(mask));
      mask &= mask - 1;
      const std::uint32_t id = block.id[i];
      if (id >= triangle_count) continue;  // a lane of another kind: its vertices are not real
      if (t[i] < best.tie_limit(id, tmax)) {
        tmax = t[i];
        best = {t[i], id, u[i], v[i]};
        found = true;
        if constexpr (kAnyHit) return true;
      }
    }
  }
  return found;
}

/// Tests every primitive of a leaf against `ray` restricted to [tmin, tmax): the triangles, then
/// the other kinds. The closest hit (lower id on ties) whatever the order; with kAnyHit, returns
/// at the first hit. Counts the primitives tested in `counters` when kCount.
template <bool kAnyHit, bool kCount, int W>
inline bool intersect_wide_leaf(const WideBvhLeaves& leaves, const Geometry& geometry, std::uint32_t first,
                                std::uint32_t count_flags, const WatertightRay& tri_ray, const Ray& ray, float tmin,
                                float& tmax, Hit& best, TraversalCounters& counters) {
  bool found = intersect_wide_leaf_triangles<kAnyHit, kCount, W>(leaves, first, count_flags, tri_ray, tmin, tmax, best,
                                                                 counters);
  if constexpr (kAnyHit) {
    if (found) return true;
  }
  found |= intersect_wide_leaf_others<kAnyHit, kCount, W>(leaves, geometry, first, count_flags, tri_ray, ray, tmin,
                                                          tmax, best, counters);
  return found;
}

/// The per-ray constants of the W-wide box test. The near plane of each axis (`hi` where the
/// direction's sign bit is set, as direction_octant counts it, else `lo`) is chosen once per ray
/// as a byte offset into the node, not by instantiating the walk per octant: diffuse rays come in
/// every octant, and dispatching on it is an indirect jump that mispredicts for most of them.
template <int W>
struct WideBoxRay {
  using F = simd::WideFloat<W>;
  F ox, oy, oz, ix, iy, iz;
  std::uint32_t near_x = 0, near_y = 0, near_z = 0;  ///< byte offsets of the near planes
  std::uint32_t far_x = 0, far_y = 0, far_z = 0;     ///< byte offsets of the far planes
  /// Whether test() must mask out the empty slots itself (see the constructor).
  bool filter_empty_slots = false;

  /// The constants of `ray`.
  explicit WideBoxRay(const Ray& ray)
      : ox(F::broadcast(ray.origin.x)),
        oy(F::broadcast(ray.origin.y)),
        oz(F::broadcast(ray.origin.z)),
        // Exact reciprocals (infinite for zero components); NaN slabs that result for a ray in
        // a face plane are dropped by min/max taking the running value as second operand.
        ix(F::broadcast(1.f / ray.direction.x)),
        iy(F::broadcast(1.f / ray.direction.y)),
        iz(F::broadcast(1.f / ray.direction.z)) {
    plane_offsets(std::signbit(ray.direction.x), 0, near_x, far_x);
    plane_offsets(std::signbit(ray.direction.y), 1, near_y, far_y);
    plane_offsets(std::signbit(ray.direction.z), 2, near_z, far_z);
    // An empty slot (+inf to -inf) gives every ray an entry of +inf and an exit of -inf on each
    // axis, so the slab test refuses it by itself, unless a distance is NaN, which min/max would
    // drop: (inf - origin) * inverse is NaN only for a zero or NaN inverse (a direction component
    // that is infinite or NaN; 1 / FLT_MAX is a denormal, not 0) or an origin that is not
    // finite. Only such rays pay for masking the slots (2 loads, a compare and an AND per node:
    // 2-7% of a single ray's time with 16-wide nodes, docs/performance.md).
    for (int axis = 0; axis < 3; ++axis) {
      if (!std::isfinite(ray.direction[axis]) || !std::isfinite(ray.origin[axis])) filter_empty_slots = true;
    }
  }

  /// Bit mask of the children of `node` that the ray enters within [tmin, tmax] (the exit
  /// widened by widen_exit), and their entry distances in `t_enter`. `Node` is a WideBvhNode<W>
  /// or another node whose boxes lie as its do (the octree's OctreeChildBoxes for W = 8).
  template <class Node>
  unsigned test(const Node& node, float tmin, float tmax, float* t_enter) const {
    static_assert(same_box_layout<Node>(), "the boxes must lie as in WideBvhNode<W>");
    const F tx0 = (plane(node, near_x) - ox) * ix;
    const F tx1 = (plane(node, far_x) - ox) * ix;
    const F ty0 = (plane(node, near_y) - oy) * iy;
    const F ty1 = (plane(node, far_y) - oy) * iy;
    const F tz0 = (plane(node, near_z) - oz) * iz;
    const F tz1 = (plane(node, far_z) - oz) * iz;
    const F t_near = max(tz0, max(ty0, max(tx0, F::broadcast(tmin))));
    // Widened after the closest-hit limit too: a primitive in a box face can be hit at a
    // distance that rounds just below the box's computed entry and the current closest hit.
    const F t_far = widen_exit(min(min(tz1, min(ty1, min(tx1, F::broadcast(INFINITY)))), F::broadcast(tmax)));
    t_near.store(t_enter);
    const auto entered = static_cast<unsigned>(less_equal_mask(t_near, t_far));
    return filter_empty_slots ? entered & occupied_slots(node) : entered;
  }

  /// Bit mask of the slots of `node` that hold a child. The slab test alone does not exclude an
  /// empty slot (+inf to -inf) for every ray: with an infinite direction component every slab
  /// distance is NaN, which the test drops; test() masks with this for such rays only.
  template <class Node>
  static unsigned occupied_slots(const Node& node) {
    return static_cast<unsigned>(less_equal_mask(F::load(node.lo[0]), F::load(node.hi[0])));
  }

 private:
  // Whether `Node` keeps lo[3][W] and hi[3][W] at WideBvhNode<W>'s offsets (`plane` reads them so).
  template <class Node>
  static constexpr bool same_box_layout() {
    return offsetof(Node, lo) == offsetof(WideBvhNode<W>, lo) && offsetof(Node, hi) == offsetof(WideBvhNode<W>, hi) &&
           sizeof(Node::lo) == sizeof(WideBvhNode<W>::lo) && sizeof(Node::hi) == sizeof(WideBvhNode<W>::hi);
  }
  // The W floats at byte `offset` of `node`: one plane of the children's boxes.
  template <class Node>
  static F plane(const Node& node, std::uint32_t offset) {
    return F::load(reinterpret_cast<const float*>(reinterpret_cast<const unsigned char*>(&node) + offset));
  }
  // The offsets of axis `axis`'s near and far planes for a direction component of sign `negative`.
  static void plane_offsets(bool negative, int axis, std::uint32_t& near, std::uint32_t& far) {
    const auto lo = static_cast<std::uint32_t>(offsetof(WideBvhNode<W>, lo) + sizeof(float) * W * axis);
    const auto hi = static_cast<std::uint32_t>(offsetof(WideBvhNode<W>, hi) + sizeof(float) * W * axis);
    near = negative ? hi : lo;
    far = negative ? lo : hi;
  }
};

/// A subtree or leaf waiting to be visited: the node's `child` and `count` fields of its slot,
/// and the distance at which the ray enters it.
struct WideStackEntry {
  std::uint32_t child;
  std::uint32_t count;  ///< 0 for an interior node
  float t;
};

RAYLAB_ISA_END
}  // namespace raylab
