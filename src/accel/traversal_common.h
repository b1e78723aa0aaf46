#pragma once
// Pieces shared by the BVH traversals (internal to src/accel): the leaf loop, the dispatch on
// the ray's direction octant, and handing the result back.

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "raylab/core/stats.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// What a leaf test needs: references in leaf order, the triangles copied in the same order,
/// and the geometry for the other shapes.
struct LeafPrimitives {
  const std::uint32_t* prim_ids;
  const Triangle* triangles;     ///< parallel to prim_ids; valid where prim_ids[i] < triangle_count
  std::uint32_t triangle_count;  ///< primitive ids below this are triangles
  const Geometry* geometry;
};

/// Tests primitive (or group) `id`, not a triangle, through the Geometry against `ray` restricted
/// to [tmin, tmax). Closest hit: on a hit shrinks `tmax` and updates `best`. With kAnyHit only
/// answers whether anything is hit (a group, a whole sub-structure, may stop at its first hit).
template <bool kAnyHit>
inline bool intersect_other(const Geometry& geometry, std::uint32_t id, const WatertightRay& tri_ray, const Ray& ray,
                            float tmin, float& tmax, Hit& best) {
  Ray probe = ray;
  probe.tmin = tmin;
  probe.tmax = tmax;
  if constexpr (kAnyHit) return geometry.occluded(id, tri_ray, probe);
  const bool hit = geometry.intersect(id, tri_ray, probe, best);
  tmax = probe.tmax;
  return hit;
}

/// Tests references [first, first + count) against `ray` restricted to [tmin, tmax); on a hit
/// shrinks `tmax` and updates `best`. With kAnyHit, returns at the first hit. Returns whether
/// anything was hit; counts tests in `prim_tests` when kCount.
template <bool kAnyHit, bool kCount>
inline bool intersect_leaf(const LeafPrimitives& leaf, std::uint32_t first, std::uint32_t count,
                           const WatertightRay& tri_ray, const Ray& ray, float tmin, float& tmax, Hit& best,
                           std::uint64_t& prim_tests) {
  bool found = false;
  const std::uint32_t end = first + count;
  for (std::uint32_t i = first; i < end; ++i) {
    const std::uint32_t id = leaf.prim_ids[i];
    if constexpr (kCount) ++prim_tests;
    bool hit_here;
    if (id < leaf.triangle_count) {
      float t, u, v;
      hit_here = intersect_triangle(leaf.triangles[i], tri_ray, tmin, best.tie_limit(id, tmax), t, u, v);
      if (hit_here) {
        tmax = t;
        best = {t, id, u, v};
      }
    } else {
      hit_here = intersect_other<kAnyHit>(*leaf.geometry, id, tri_ray, ray, tmin, tmax, best);
    }
    if (hit_here) {
      found = true;
      if constexpr (kAnyHit) return true;
    }
  }
  return found;
}

/// Copies the triangles that `prim_ids` refers to into leaf order (other slots stay zero).
inline std::vector<Triangle> triangles_in_leaf_order(const Geometry& geometry,
                                                     const std::vector<std::uint32_t>& prim_ids) {
  std::vector<Triangle> out(prim_ids.size());
  const auto triangle_count = static_cast<std::uint32_t>(geometry.triangles.size());
  for (std::size_t i = 0; i < prim_ids.size(); ++i) {
    if (prim_ids[i] < triangle_count) out[i] = geometry.triangles[prim_ids[i]];
  }
  return out;
}

/// Factor by which slab tests widen a box's exit distance: 1 + 2 gamma(3) (Ize 2013, as in
/// pbrt). It makes the float slab test conservative, so a primitive lying in a box face is never
/// culled by rounding.
inline constexpr float kSlabWiden = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

/// The ray's direction octant: bit a is set when direction component a is negative (-0
/// included: its reciprocal is -inf). It decides which of a box's two planes is met first.
inline int direction_octant(Vec3 d) {
  return (std::signbit(d.x) ? 1 : 0) | (std::signbit(d.y) ? 2 : 0) | (std::signbit(d.z) ? 4 : 0);
}

/// Calls `f(std::integral_constant<int, octant>{})`, so a kernel can be instantiated once per
/// octant with its near and far planes known at compile time.
template <class F>
inline decltype(auto) dispatch_octant(int octant, F&& f) {
  switch (octant) {
    case 0:
      return f(std::integral_constant<int, 0>{});
    case 1:
      return f(std::integral_constant<int, 1>{});
    case 2:
      return f(std::integral_constant<int, 2>{});
    case 3:
      return f(std::integral_constant<int, 3>{});
    case 4:
      return f(std::integral_constant<int, 4>{});
    case 5:
      return f(std::integral_constant<int, 5>{});
    case 6:
      return f(std::integral_constant<int, 6>{});
    default:
      return f(std::integral_constant<int, 7>{});
  }
}

/// Subtrees waiting to be visited, each with the distance at which the ray enters it.
template <int kCapacity>
class TraversalStack {
 public:
  /// Saves subtree `node`, entered at distance `t_enter`. The caller bounds the depth.
  void push(std::uint32_t node, float t_enter) { m_entries[m_size++] = {node, t_enter}; }

  /// Pops the most recently pushed subtree that can still hold a hit closer than `tmax`
  /// (any subtree for any-hit queries, which need no order); false when none is left.
  template <bool kAnyHit>
  bool pop(float tmax, std::uint32_t& node) {
    while (m_size > 0) {
      const Entry& e = m_entries[--m_size];
      if (kAnyHit || e.t_enter <= tmax * kSlabWiden) {  // widened as the box test is
        node = e.node;
        return true;
      }
    }
    return false;
  }

 private:
  struct Entry {
    std::uint32_t node;
    float t_enter;
  };
  Entry m_entries[kCapacity];
  int m_size = 0;
};

/// Hands a traversal's result back: adds its counts to `stats` (when counting) and, on a hit,
/// writes the hit and shrinks the ray. Returns `found`.
template <bool kCount>
inline bool finish_traversal(bool found, float tmax, const Hit& best, std::uint64_t nodes_visited,
                             std::uint64_t prim_tests, Ray& ray, Hit& hit, TraversalStats* stats) {
  if constexpr (kCount) {
    stats->nodes_visited += nodes_visited;
    stats->prim_tests += prim_tests;
    stats->hits += found ? 1 : 0;
  }
  if (found) {
    ray.tmax = tmax;
    hit = best;
  }
  return found;
}

}  // namespace raylab
