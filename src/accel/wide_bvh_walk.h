#pragma once
// The single-ray walk of the wide BVH (internal to src/accel): used by `WideBvh::intersect` from
// the root, and by the packet traversal to finish the few rays left in a subtree.

#include <bit>
#include <cstdint>

#include "bvh_depth.h"
#include "raylab/simd/isa_namespace.h"
#include "wide_bvh_leaf.h"

namespace raylab {
RAYLAB_ISA_BEGIN

using bvh_depth::kWideStackSize;  // sized by the builder's depth bound

/// Walks the subtree (or leaf) `start` for one ray, nearest child first, from
/// distance `ray.tmin` up to `tmax`; on hits shrinks `tmax` and updates `best`. With kAnyHit
/// stops at the first hit and visits children in slot order. Returns whether anything was hit;
/// adds the work to `counters` when kCount.
template <bool kAnyHit, bool kCount, int W>
bool walk_wide_bvh(const WideBvhTree<W>& tree, const Geometry& geometry, WideStackEntry start,
                   const WideBoxRay<W>& box_ray, const WatertightRay& tri_ray, const Ray& ray, float& tmax, Hit& best,
                   TraversalCounters& counters) {
  const WideBvhNode<W>* const nodes = tree.nodes.data();
  const float tmin = ray.tmin;
  bool found = false;
  WideStackEntry stack[kWideStackSize<W>];
  int size = 0;
  WideStackEntry current = start;
  for (;;) {
    if (current.count != 0) {
      if (intersect_wide_leaf<kAnyHit, kCount, W>(tree.leaves, geometry, current.child, current.count, tri_ray, ray,
                                                  tmin, tmax, best, counters)) {
        found = true;
        if constexpr (kAnyHit) return true;
      }
    } else {
      const WideBvhNode<W>& node = nodes[current.child];
      if constexpr (kCount) ++counters.nodes_visited;
      alignas(64) float t_enter[W];
      unsigned mask = box_ray.test(node, tmin, tmax, t_enter);
      if (mask != 0) {
        // One child entered (the common case): go on with it, nothing to order.
        int i = std::countr_zero(mask);
        mask &= mask - 1;
        current = {node.child[i], node.count[i], t_enter[i]};
        if (mask == 0) continue;
        // More: push them all, then sort the pushed run farthest first (closest hits only;
        // any occluder will do for any-hit queries), and continue with the nearest.
        const int base = size;
        stack[size++] = current;
        do {
          i = std::countr_zero(mask);
          mask &= mask - 1;
          stack[size++] = {node.child[i], node.count[i], t_enter[i]};
        } while (mask != 0);
        if constexpr (!kAnyHit) {
          for (int a = base + 1; a < size; ++a) {
            const WideStackEntry e = stack[a];
            int b = a;
            for (; b > base && stack[b - 1].t < e.t; --b) stack[b] = stack[b - 1];
            stack[b] = e;
          }
        }
        current = stack[--size];
        continue;
      }
    }
    // Continue with the next subtree that can still hold a closer hit.
    for (;;) {
      if (size == 0) return found;
      current = stack[--size];
      if (kAnyHit || current.t <= widen_exit(tmax)) break;  // widened as the box test is
    }
  }
}

RAYLAB_ISA_END
}  // namespace raylab
