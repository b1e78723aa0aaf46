#pragma once
// The leaf loop shared by the BVH traversals (internal to src/accel).

#include <cstdint>

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
      hit_here = intersect_triangle(leaf.triangles[i], tri_ray, tmin, tmax, t, u, v);
      if (hit_here) {
        tmax = t;
        best = {t, id, u, v};
      }
    } else {
      Ray probe = ray;
      probe.tmin = tmin;
      probe.tmax = tmax;
      hit_here = leaf.geometry->intersect(id, tri_ray, probe, best);
      tmax = probe.tmax;
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

}  // namespace raylab
