// BVH traversal: closest hit with front-to-back child order, any hit with early exit.

#include <chrono>
#include <cmath>

#include "raylab/accel/bvh.h"
#include "raylab/core/stopwatch.h"

#include "bvh_depth.h"
#include "leaf_test.h"
#include "traversal_common.h"
#include "traversal_entry_points.h"

namespace raylab {

// Per-ray constants for box tests: origin and reciprocal direction. The slab distances are
// (plane - origin) * inv_dir with exact IEEE infinities for zero direction components. (The
// one-FMA form plane * inv_dir - origin * inv_dir was tried and rejected: for a ray lying in a
// face plane it becomes inf - inf, and with a tiny stand-in direction the rounding residual of
// origin * inv_dir culls such rays wrongly; tests/accel/bvh_vs_brute_test.cpp catches it.)
struct BvhBoxRay {
  float ox, oy, oz;
  float ix, iy, iz;

  explicit BvhBoxRay(const Ray& ray)
      : ox(ray.origin.x),
        oy(ray.origin.y),
        oz(ray.origin.z),
        ix(1.f / ray.direction.x),
        iy(1.f / ray.direction.y),
        iz(1.f / ray.direction.z) {}
};

namespace {

// Entry distance into `node` if the ray's [tmin, tmax] overlaps it, for rays in octant kOctant
// (near and far planes chosen at compile time). NaN slabs (origin on the plane of a face,
// direction parallel to it) are ignored by the comparison order, so boxes are closed sets. The
// exit distance is widened once, after the minimum (scaling by a positive factor is monotonic).
template <int kOctant>
inline bool hit_node(const BvhNode& node, const BvhBoxRay& r, float tmin, float tmax, float& t_enter) {
  constexpr bool kNegX = (kOctant & 1) != 0, kNegY = (kOctant & 2) != 0, kNegZ = (kOctant & 4) != 0;
  const float tx0 = ((kNegX ? node.hi[0] : node.lo[0]) - r.ox) * r.ix;
  const float tx1 = ((kNegX ? node.lo[0] : node.hi[0]) - r.ox) * r.ix;
  const float ty0 = ((kNegY ? node.hi[1] : node.lo[1]) - r.oy) * r.iy;
  const float ty1 = ((kNegY ? node.lo[1] : node.hi[1]) - r.oy) * r.iy;
  const float tz0 = ((kNegZ ? node.hi[2] : node.lo[2]) - r.oz) * r.iz;
  const float tz1 = ((kNegZ ? node.lo[2] : node.hi[2]) - r.oz) * r.iz;
  float t_near = tmin;
  t_near = tx0 > t_near ? tx0 : t_near;
  t_near = ty0 > t_near ? ty0 : t_near;
  t_near = tz0 > t_near ? tz0 : t_near;
  float t_far = INFINITY;
  t_far = tx1 < t_far ? tx1 : t_far;
  t_far = ty1 < t_far ? ty1 : t_far;
  t_far = tz1 < t_far ? tz1 : t_far;
  // Both limits are widened: a primitive lying in a box face can be hit at a distance that
  // rounds just below the box's computed entry, and just below the current closest hit.
  t_far = widen_exit(t_far < tmax ? t_far : tmax);
  t_enter = t_near;
  return t_near <= t_far;
}

constexpr int kStackSize = 128;
static_assert(kStackSize >= bvh_depth::kBinaryStackSize, "the builder's depth bound must fit the stack");

}  // namespace

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
Bvh::Bvh(const Geometry& geometry, const BvhConfig& config) : Bvh(geometry, geometry.primitive_ids(), config) {}

Bvh::Bvh(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config) : m_geometry(geometry) {
  const auto start = std::chrono::steady_clock::now();
  m_tree = build_bvh(geometry, ids, config);
  m_triangle_count = static_cast<std::uint32_t>(geometry.triangles.size());
  m_leaf_triangles = triangles_in_leaf_order(geometry, m_tree.prim_ids);
  m_cylinder_frames = CylinderFrames::of(geometry, m_tree.prim_ids);
  m_build_seconds = seconds_since(start);
}

Box3 Bvh::bounds() const {
  const BvhNode& root = m_tree.nodes[0];
  return {{root.lo[0], root.lo[1], root.lo[2]}, {root.hi[0], root.hi[1], root.hi[2]}};
}

#endif  // RAYLAB_KERNEL_VARIANT

template <bool kAnyHit, bool kCount, class K>
bool Bvh::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  if (m_tree.prim_ids.empty()) return false;
  const BvhBoxRay box_ray(ray);
  return dispatch_octant(direction_octant(ray.direction), [&](auto octant) {
    return traverse_octant<kAnyHit, kCount, decltype(octant)::value, K>(ray, box_ray, hit, stats);
  });
}

template <bool kAnyHit, bool kCount, int kOctant, class K>
bool Bvh::traverse_octant(Ray& ray, const BvhBoxRay& box_ray, Hit& hit, TraversalStats* stats) const {
  // Everything the loop touches lives in locals: stores through `ray` and `hit` inside the loop
  // would force the compiler to reload node and array pointers after each one (they may alias).
  const BvhNode* const nodes = m_tree.nodes.data();
  const SlotTriangles leaf{m_tree.prim_ids.data(), m_leaf_triangles.data(), m_triangle_count, &m_geometry,
                           &m_cylinder_frames};
  TestEverySlot every_slot;
  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  Hit best = hit;
  TraversalCounters counters{.nodes_visited = 1};

  float t_root = 0.f;
  bool found = false;
  if (hit_node<kOctant>(nodes[0], box_ray, tmin, tmax, t_root)) {
    // Only rays that enter the tree need the triangle test's constants (most rays of a typical
    // image miss everything, and for them the root test is the whole cost).
    const WatertightRay tri_ray(ray);
    TraversalStack<kStackSize> stack;
    std::uint32_t current = 0;
    for (;;) {
      const BvhNode& node = nodes[current];
      if (node.is_leaf()) {
        if (intersect_references<kAnyHit, kCount>(leaf, node.first, node.first + node.count, SlotIsReference{},
                                                  every_slot, tri_ray, ray, tmin, tmax, best, counters)) {
          found = true;
          if constexpr (kAnyHit) return finish_traversal<kCount>(true, tmax, best, counters, ray, hit, stats);
        }
      } else {
        const std::uint32_t left = node.first;
        float t_left = 0.f, t_right = 0.f;
        if constexpr (kCount) counters.nodes_visited += 2;
        // Both children are tested one after the other in scalar code. A two-box SIMD test
        // (both 32-byte siblings in one 256-bit pair of loads) was measured slower: this loop is
        // bound by the latency from node load to branch, and the lane shuffles lengthen it.
        const bool hit_left = hit_node<kOctant>(nodes[left], box_ray, tmin, tmax, t_left);
        const bool hit_right = hit_node<kOctant>(nodes[left + 1], box_ray, tmin, tmax, t_right);
        if (hit_left && hit_right) {
          // Visit the nearer child first; the farther one waits with its entry distance, so it
          // can be skipped if a closer hit is found meanwhile.
          const bool right_first = t_right < t_left;
          if (right_first) {
            stack.push(left, t_left);
          } else {
            stack.push(left + 1, t_right);
          }
          current = right_first ? left + 1 : left;
          continue;
        }
        if (hit_left | hit_right) {
          current = hit_left ? left : left + 1;
          continue;
        }
      }
      // Continue with the next subtree that can still hold a closer hit.
      if (!stack.template pop<kAnyHit>(tmax, current)) break;
    }
  }
  return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
}

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
// The four entry points, which call the kernel of the structure's instruction set.
RAYLAB_INSTANTIATE_ENTRY_POINTS(Bvh);

AccelInfo Bvh::info() const {
  AccelInfo info;
  info.name = "bvh2";
  info.build_seconds = m_build_seconds;
  info.memory_bytes = m_tree.nodes.size() * sizeof(BvhNode) + m_tree.prim_ids.size() * sizeof(std::uint32_t) +
                      m_leaf_triangles.size() * sizeof(Triangle) + m_cylinder_frames.bytes();
  info.node_count = m_tree.nodes.size();
  info.leaf_count = m_tree.leaf_count;
  info.primitive_count = m_tree.prim_ids.size();
  info.max_depth = m_tree.max_depth;
  return info;
}

#endif  // RAYLAB_KERNEL_VARIANT

// The kernel, compiled here for this translation unit's instruction set.
RAYLAB_INSTANTIATE_TRAVERSE(Bvh);

}  // namespace raylab
