#pragma once
// Pieces shared by the traversals (internal to src/accel): the work counters, the dispatch on
// the ray's direction octant, the stack of subtrees and handing the result back. The leaf test
// is in leaf_test.h.

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "raylab/core/stats.h"
#include "raylab/geometry/geometry.h"
#include "raylab/simd/isa_namespace.h"

namespace raylab {
RAYLAB_ISA_BEGIN

/// The work a counted query does, added up during the walk and handed to TraversalStats at the
/// end (a structure's uncounted kernels never touch it).
struct TraversalCounters {
  std::uint64_t nodes_visited = 0;  ///< nodes, cells or box tests, as each structure defines it
  std::uint64_t prim_tests = 0;     ///< primitive tests run
};

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

/// The mirror of kSlabWiden below 1 (exact in float: 1 - 3 * 2^-23), which widens a negative
/// exit distance by the same relative amount.
inline constexpr float kSlabNarrow = 2.0f - kSlabWiden;

/// A box's exit distance `t_exit` moved outward by the slab test's rounding bound, for either
/// sign: t * kSlabWiden alone would pull a negative exit (a box behind the origin, asked for by
/// tmin < 0) toward the entry and cull a primitive lying in the exit face. For t >= 0 the result
/// is t * kSlabWiden bit for bit, so rays with tmin >= 0 see no change. `T` is float or one of
/// the SIMD float types (anything with `*` and `max`).
template <class T>
inline T widen_exit(const T& t_exit) {
  if constexpr (std::is_same_v<T, float>) {
    const float up = t_exit * kSlabWiden;
    const float down = t_exit * kSlabNarrow;
    return up > down ? up : down;  // NaN stays NaN
  } else {
    return max(t_exit * T::broadcast(kSlabWiden), t_exit * T::broadcast(kSlabNarrow));
  }
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
      if (kAnyHit || e.t_enter <= widen_exit(tmax)) {  // widened as the box test is
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
inline bool finish_traversal(bool found, float tmax, const Hit& best, const TraversalCounters& counters, Ray& ray,
                             Hit& hit, TraversalStats* stats) {
  if constexpr (kCount) {
    stats->nodes_visited += counters.nodes_visited;
    stats->prim_tests += counters.prim_tests;
    stats->hits += found ? 1 : 0;
  }
  if (found) {
    ray.tmax = tmax;
    hit = best;
  }
  return found;
}

RAYLAB_ISA_END
}  // namespace raylab
