#pragma once
// The one leaf test of the structures that test primitives one by one (internal to src/accel):
// the binary BVH's leaves, the uniform grid's cells and the octree's leaves. It holds the rule every structure must
// share — on an exact tie in t the lower primitive id wins (Hit::tie_limit) — so that all of them return the same hit.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "raylab/accel/cylinder_frames.h"
#include "raylab/geometry/cylinder.h"
#include "raylab/geometry/geometry.h"
#include "raylab/simd/isa_namespace.h"
#include "traversal_common.h"

namespace raylab {
RAYLAB_ISA_BEGIN

/// Primitives a structure keeps in its own order ("slots"): the global id at each slot, and
/// copies of the triangles at the same slots (for locality: the leaf's data lies together).
/// Every other kind is tested through the Geometry. The binary BVH.
struct SlotTriangles {
  static constexpr bool kInlineSpheres = false;  ///< spheres go through the Geometry

  const std::uint32_t* ids;         ///< the global id of each slot
  const Triangle* triangles;        ///< parallel to ids; valid where the id is a triangle's
  std::uint32_t triangle_count;     ///< global ids below this are triangles
  const Geometry* geometry;         ///< for every other kind (and groups)
  const CylinderFrames* cylinders;  ///< the frames of the structure's cylinders

  /// The triangle at `slot` (global id `id`).
  const Triangle& triangle(std::uint32_t slot, std::uint32_t /*id*/) const { return triangles[slot]; }
};

/// Like SlotTriangles, with copies of the spheres at their slots as well. The uniform grid.
struct SlotPrimitives {
  static constexpr bool kInlineSpheres = true;  ///< spheres are tested here

  const std::uint32_t* ids;         ///< the global id of each slot
  const Triangle* triangles;        ///< parallel to ids; valid where the id is a triangle's
  const Sphere* spheres;            ///< parallel to ids; valid where the id is an inline sphere's
  std::uint32_t triangle_count;     ///< global ids below this are triangles
  std::uint32_t sphere_end;         ///< ids in [triangle_count, sphere_end) are tested as inline spheres
  const Geometry* geometry;         ///< for every other kind (and groups)
  const CylinderFrames* cylinders;  ///< the frames of the structure's cylinders

  /// The triangle at `slot` (global id `id`).
  const Triangle& triangle(std::uint32_t slot, std::uint32_t /*id*/) const { return triangles[slot]; }
  /// The sphere at `slot` (global id `id`).
  const Sphere& sphere(std::uint32_t slot, std::uint32_t /*id*/) const { return spheres[slot]; }

  /// The slots `ids` of `geometry` with the copies `copied_triangles` and `copied_spheres` that
  /// copy_slot_primitives made for them and the frames `frames` of its cylinders; the id ranges
  /// of the kinds come from `geometry`.
  SlotPrimitives(const std::uint32_t* slot_ids, const std::vector<Triangle>& copied_triangles,
                 const std::vector<Sphere>& copied_spheres, const CylinderFrames& frames, const Geometry& g)
      : ids(slot_ids),
        triangles(copied_triangles.data()),
        spheres(copied_spheres.data()),
        triangle_count(static_cast<std::uint32_t>(g.triangles.size())),
        sphere_end(triangle_count + static_cast<std::uint32_t>(g.spheres.size())),
        geometry(&g),
        cylinders(&frames) {}
};

/// Fills `triangles` and `spheres` with copies of the primitives `ids` names, slot by slot, for
/// SlotPrimitives (the grids): slot i holds the copy of primitive ids[i] when it is a triangle
/// (or a sphere); other slots stay zero, and an array stays empty when no slot needs it. With
/// `ids` in spatial order, a cell's references point to neighbouring copies instead of all over
/// the scene.
inline void copy_slot_primitives(const Geometry& geometry, const std::vector<std::uint32_t>& ids,
                                 std::vector<Triangle>& triangles, std::vector<Sphere>& spheres) {
  const auto triangle_count = static_cast<std::uint32_t>(geometry.triangles.size());
  const auto sphere_end = triangle_count + static_cast<std::uint32_t>(geometry.spheres.size());
  const bool any_triangle = std::any_of(ids.begin(), ids.end(), [&](std::uint32_t id) { return id < triangle_count; });
  const bool any_sphere =
      std::any_of(ids.begin(), ids.end(), [&](std::uint32_t id) { return id >= triangle_count && id < sphere_end; });
  triangles.assign(any_triangle ? ids.size() : 0, Triangle{});
  spheres.assign(any_sphere ? ids.size() : 0, Sphere{});
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const std::uint32_t id = ids[i];
    if (id < triangle_count)
      triangles[i] = geometry.triangles[id];
    else if (id < sphere_end)
      spheres[i] = geometry.spheres[id - triangle_count];
  }
}

/// Primitives read from the Geometry by global id, with no copies: the octree. `ids` still maps a structure's slot to
/// the global id.
struct GeometryPrimitives {
  static constexpr bool kInlineSpheres = true;  ///< spheres are tested here

  const std::uint32_t* ids;         ///< the global id of each slot
  const Triangle* triangles;        ///< the Geometry's triangles, by global id
  const Sphere* spheres;            ///< the Geometry's spheres, by global id - triangle_count
  std::uint32_t triangle_count;     ///< global ids below this are triangles
  std::uint32_t sphere_end;         ///< ids in [triangle_count, sphere_end) are spheres
  const Geometry* geometry;         ///< for every other kind (and groups)
  const CylinderFrames* cylinders;  ///< the frames of the structure's cylinders

  /// The primitives of `g`, numbered by `slot_ids`, and the frames `frames` of its cylinders.
  GeometryPrimitives(const std::uint32_t* slot_ids, const CylinderFrames& frames, const Geometry& g)
      : ids(slot_ids),
        triangles(g.triangles.data()),
        spheres(g.spheres.data()),
        triangle_count(static_cast<std::uint32_t>(g.triangles.size())),
        sphere_end(triangle_count + static_cast<std::uint32_t>(g.spheres.size())),
        geometry(&g),
        cylinders(&frames) {}

  /// The triangle with global id `id`.
  const Triangle& triangle(std::uint32_t /*slot*/, std::uint32_t id) const { return triangles[id]; }
  /// The sphere with global id `id`.
  const Sphere& sphere(std::uint32_t /*slot*/, std::uint32_t id) const { return spheres[id - triangle_count]; }
};

/// Slot of reference r when a structure's references are its slots (the BVH's leaves).
struct SlotIsReference {
  /// `r` itself.
  std::uint32_t operator()(std::uint32_t r) const { return r; }
};

/// Slot of reference r when a structure lists slots per cell or leaf (grid, octree).
struct SlotFromList {
  const std::uint32_t* slots;  ///< the structure's reference list
  /// `slots[r]`.
  std::uint32_t operator()(std::uint32_t r) const { return slots[r]; }
};

/// Tests every slot, for structures that reference each primitive once (no mailboxes).
struct TestEverySlot {
  /// Always true.
  static constexpr bool first_visit(std::uint32_t) { return true; }
};

/// Tests primitive (or group) `id` through the Geometry against `ray` restricted to
/// [tmin, tmax). Closest hit: on a hit shrinks `tmax` and updates `best`. With kAnyHit only
/// answers whether anything is hit (a group, a whole sub-structure, may stop at its first hit).
template <bool kAnyHit>
inline bool intersect_through_geometry(const Geometry& geometry, std::uint32_t id, const WatertightRay& tri_ray,
                                       const Ray& ray, float tmin, float& tmax, Hit& best) {
  Ray probe = ray;
  probe.tmin = tmin;
  probe.tmax = tmax;
  if constexpr (kAnyHit) return geometry.occluded(id, tri_ray, probe);
  const bool hit = geometry.intersect(id, tri_ray, probe, best);
  tmax = probe.tmax;
  return hit;
}

/// Runs `test(limit, t, u, v)`, the test of primitive `id` against the ray up to `limit`, with
/// the tie rule (Hit::tie_limit) of the closest hit so far, `best`; on a hit of a closest-hit
/// query, shrinks `tmax` and makes the hit `best`. Geometry::intersect's rule, for the shapes a
/// structure tests itself.
template <bool kAnyHit, class Test>
inline bool test_with_tie_rule(std::uint32_t id, float& tmax, Hit& best, const Test& test) {
  float t = 0.f, u = 0.f, v = 0.f;
  // An any-hit query has no hit yet, so no tie limit.
  if (!test(kAnyHit ? tmax : best.tie_limit(id, tmax), t, u, v)) return false;
  if constexpr (!kAnyHit) {
    tmax = t;
    best = Hit{t, id, u, v};
  }
  return true;
}

/// Tests cylinder `id` from its precomputed `frame` against `ray` restricted to [tmin, tmax),
/// with intersect_through_geometry's contract and bit for bit its answer.
template <bool kAnyHit>
inline bool intersect_cylinder_frame(const CylinderFrame& frame, std::uint32_t id, const Ray& ray, float tmin,
                                     float& tmax, Hit& best) {
  return test_with_tie_rule<kAnyHit>(id, tmax, best, [&](float limit, float& t, float&, float& v) {
    return intersect_cylinder(frame, ray, tmin, limit, t, v);
  });
}

/// intersect_cylinder_frame without the float rejection, for a cylinder that a caller's own
/// rejection (cylinders_surely_missed) did not turn away: together the same answer.
template <bool kAnyHit>
inline bool intersect_cylinder_frame_exact(const CylinderFrame& frame, std::uint32_t id, const Ray& ray, float tmin,
                                           float& tmax, Hit& best) {
  return test_with_tie_rule<kAnyHit>(id, tmax, best, [&](float limit, float& t, float&, float& v) {
    return intersect_cylinder_exact(frame, ray, tmin, limit, t, v);
  });
}

/// Tests sphere `id` (`sphere`) against `ray` restricted to [tmin, tmax), with
/// intersect_through_geometry's contract and bit for bit its answer.
template <bool kAnyHit>
inline bool intersect_sphere_here(const Sphere& sphere, std::uint32_t id, const Ray& ray, float tmin, float& tmax,
                                  Hit& best) {
  return test_with_tie_rule<kAnyHit>(id, tmax, best, [&](float limit, float& t, float&, float&) {
    return intersect_sphere(sphere, ray, tmin, limit, t);
  });
}

/// Tests primitive (or group) `id` of `prims`, neither a triangle nor an inline sphere: a
/// cylinder from the structure's frame of it, anything else through the Geometry (with
/// intersect_through_geometry's contract and, for the cylinder, bit for bit its answer).
template <bool kAnyHit, class Primitives>
inline bool intersect_other_kind(const Primitives& prims, std::uint32_t id, const WatertightRay& tri_ray,
                                 const Ray& ray, float tmin, float& tmax, Hit& best) {
  if (const CylinderFrame* frame = prims.cylinders->find(id)) {
    return intersect_cylinder_frame<kAnyHit>(*frame, id, ray, tmin, tmax, best);
  }
  return intersect_through_geometry<kAnyHit>(*prims.geometry, id, tri_ray, ray, tmin, tmax, best);
}

/// Tests the references [begin, end) against `ray` restricted to [tmin, tmax): reference r is
/// slot `slot_of(r)` of `prims`, skipped unless `mailbox.first_visit(slot)` (a slot that an
/// earlier cell of the same ray already tested). Triangles, inline spheres and cylinders are
/// tested here, other kinds and groups through the Geometry; each test starts from the closest hit so far
/// with the tie rule. Closest hit: on a hit shrinks `tmax` and updates `best`. With kAnyHit,
/// returns at the first hit and leaves `tmax` and `best` alone. Returns whether anything was
/// hit; counts the tests run in `counters.prim_tests` when kCount.
template <bool kAnyHit, bool kCount, class Primitives, class SlotOf, class Mailbox>
inline bool intersect_references(const Primitives& prims, std::uint32_t begin, std::uint32_t end, SlotOf slot_of,
                                 Mailbox& mailbox, const WatertightRay& tri_ray, const Ray& ray, float tmin,
                                 float& tmax, Hit& best, TraversalCounters& counters) {
  bool found = false;
  for (std::uint32_t r = begin; r < end; ++r) {
    const std::uint32_t slot = slot_of(r);
    if (!mailbox.first_visit(slot)) continue;
    const std::uint32_t id = prims.ids[slot];
    if constexpr (kCount) ++counters.prim_tests;
    bool hit_here;
    if (id < prims.triangle_count) {
      hit_here = test_with_tie_rule<kAnyHit>(id, tmax, best, [&](float limit, float& t, float& u, float& v) {
        return intersect_triangle(prims.triangle(slot, id), tri_ray, tmin, limit, t, u, v);
      });
    } else if constexpr (Primitives::kInlineSpheres) {
      if (id < prims.sphere_end) {
        hit_here = intersect_sphere_here<kAnyHit>(prims.sphere(slot, id), id, ray, tmin, tmax, best);
      } else {
        hit_here = intersect_other_kind<kAnyHit>(prims, id, tri_ray, ray, tmin, tmax, best);
      }
    } else {
      hit_here = intersect_other_kind<kAnyHit>(prims, id, tri_ray, ray, tmin, tmax, best);
    }
    if (hit_here) {
      found = true;
      if constexpr (kAnyHit) return true;
    }
  }
  return found;
}

RAYLAB_ISA_END
}  // namespace raylab
