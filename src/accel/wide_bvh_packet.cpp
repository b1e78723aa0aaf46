// Packet traversal of the wide BVH: up to 16 rays of one direction octant walk the tree together.
// A node is first tested against the packet's interval bounds (one conservative test for all
// rays: origins and reciprocal directions as intervals), then against each active ray; children
// are visited nearest first, each with the mask of rays that entered it. Leaves test each active
// ray with the single-ray leaf kernel, and when few rays remain in a subtree they finish it one
// by one with the single-ray walk. Every ray's result is the closest hit with the lower-id tie
// rule, whatever the visiting order, so packets equal single rays bit for bit.

#include <algorithm>
#include <bit>
#include <cmath>

#include "raylab/accel/wide_bvh.h"
#include "raylab/geometry/triangle_rays.h"
#include "wide_bvh_walk.h"

namespace raylab {
namespace {

/// Rays per packet: 16 is a 4x4 pixel tile.
constexpr int kPacketSize = 16;

/// Rays tested together by one box-test instruction: 8, with AVX-512 too. Groups of 16 lanes
/// were measured slower on this project's machine (the `native` preset, raylab bench primary
/// packets of 16 on the bunny scene: 20.8 Mrays/s with 16 lanes, 25.3 with two groups of 8).
constexpr int kRayLanes = simd::kNativeBoxWidth < 8 ? simd::kNativeBoxWidth : 8;

/// Subtrees with at most this many rays left are finished with single-ray walks: below it the
/// shared node fetches no longer pay for the per-ray bookkeeping.
constexpr int kSingleRayThreshold = 2;

/// Conservative interval bounds of a packet's slab distances (see `test`). Valid only when every
/// ray's origin is finite and every reciprocal direction finite and of the octant's sign.
template <int W>
struct PacketInterval {
  using F = simd::WideFloat<W>;
  F near_o[3], far_o[3];   // origin extreme used with the near plane / far plane, per axis
  F inv_lo[3], inv_hi[3];  // reciprocal direction range per axis
  bool valid = false;

  /// Bit mask of the children that some ray of the packet may enter within [tmin, tmax]:
  /// a superset of every ray's own test, because each bound is computed with the same
  /// (monotone) float operations at the extreme ray values.
  template <int kOctant>
  unsigned test(const WideBvhNode<W>& node, float tmin, float tmax, float* t_enter) const {
    constexpr int kNear[3] = {(kOctant & 1) ? 1 : 0, (kOctant & 2) ? 1 : 0, (kOctant & 4) ? 1 : 0};
    F t_near = F::broadcast(tmin);
    F t_far = F::broadcast(INFINITY);
    for (int a = 0; a < 3; ++a) {
      const F d_near = F::load(kNear[a] ? node.hi[a] : node.lo[a]) - near_o[a];
      const F d_far = F::load(kNear[a] ? node.lo[a] : node.hi[a]) - far_o[a];
      t_near = max(min(d_near * inv_lo[a], d_near * inv_hi[a]), t_near);
      t_far = min(max(d_far * inv_lo[a], d_far * inv_hi[a]), t_far);
    }
    t_far = min(t_far, F::broadcast(tmax)) * F::broadcast(kSlabWiden);
    t_near.store(t_enter);
    return static_cast<unsigned>(less_equal_mask(t_near, t_far));
  }
};

/// The interval bounds of the packet's rays, given as origins and reciprocal directions per axis
/// (all kPacketSize lanes filled: unused lanes repeat a used one); not valid when some origin
/// or reciprocal is not finite or is zero, or `tmin_lo` is NaN.
template <int W, int kOctant>
PacketInterval<W> packet_interval(const float (&origin)[3][kPacketSize], const float (&inv)[3][kPacketSize],
                                  float tmin_lo) {
  using F = simd::WideFloat<W>;
  using L = simd::WideFloat<kRayLanes>;
  PacketInterval<W> interval;
  const L zero = L::broadcast(0.f);
  constexpr unsigned kAll = (1u << kRayLanes) - 1u;
  bool ok = tmin_lo == tmin_lo;
  float bound[4][3];  // origin min, origin max, reciprocal min, reciprocal max per axis
  for (int a = 0; a < 3; ++a) {
    L o_lo = L::load(origin[a]), o_hi = o_lo, i_lo = L::load(inv[a]), i_hi = i_lo;
    for (int g = 0; g < kPacketSize / kRayLanes; ++g) {
      const L o = L::load(origin[a] + g * kRayLanes), r = L::load(inv[a] + g * kRayLanes);
      // x - x is 0 exactly when x is finite (NaN for infinities and NaN).
      const L o_nan = o - o, r_nan = r - r;
      ok = ok && (less_equal_mask(o_nan, zero) & less_equal_mask(r_nan, zero)) == kAll &&
           (less_equal_mask(r, zero) & less_equal_mask(zero, r)) == 0;
      o_lo = min(o, o_lo);
      o_hi = max(o, o_hi);
      i_lo = min(r, i_lo);
      i_hi = max(r, i_hi);
    }
    alignas(64) float lanes[4][kRayLanes];
    o_lo.store(lanes[0]);
    o_hi.store(lanes[1]);
    i_lo.store(lanes[2]);
    i_hi.store(lanes[3]);
    for (int k = 0; k < 4; ++k) {
      bound[k][a] = lanes[k][0];
      for (int i = 1; i < kRayLanes; ++i) {
        bound[k][a] = (k % 2 == 0) ? std::min(bound[k][a], lanes[k][i]) : std::max(bound[k][a], lanes[k][i]);
      }
    }
  }
  interval.valid = ok;
  for (int a = 0; a < 3 && ok; ++a) {
    const bool negative = (kOctant >> a) & 1;
    // Near plane minus origin is smallest at the origin farthest along the direction.
    interval.near_o[a] = F::broadcast(negative ? bound[0][a] : bound[1][a]);
    interval.far_o[a] = F::broadcast(negative ? bound[1][a] : bound[0][a]);
    interval.inv_lo[a] = F::broadcast(bound[2][a]);
    interval.inv_hi[a] = F::broadcast(bound[3][a]);
  }
  return interval;
}

/// Calls `fn(begin, end)` for each run of up to kPacketSize consecutive rays of one direction
/// octant, in order: the packets a group of rays is traced as.
template <class Fn>
void for_each_octant_run(std::span<const Ray> rays, const Fn& fn) {
  std::size_t begin = 0;
  while (begin < rays.size()) {
    const int octant = direction_octant(rays[begin].direction);
    std::size_t end = begin + 1;
    while (end < rays.size() && end - begin < kPacketSize && direction_octant(rays[end].direction) == octant) ++end;
    fn(begin, end);
    begin = end;
  }
}

/// Rays of one group that the leaves test ray-parallel rather than one by one: below this the
/// ray-parallel test (one pass per triangle for the whole group) costs more than ray by ray
/// (one pass per block of four triangles for each ray).
constexpr int kRayParallelLeaf = 4;

/// Packets whose directions lie within this cosine of the first ray's walk interior nodes on
/// the packet's interval test alone: their interval is nearly as tight as each ray's own test.
constexpr float kCoherentCosine = 0.98f;

/// Whether the directions of `rays[0..n)` all lie within kCoherentCosine of the first.
bool directions_coherent(const Ray* rays, int n) {
  const Vec3 d0 = rays[0].direction;
  const float d0_sq = dot(d0, d0);
  for (int i = 1; i < n; ++i) {
    const Vec3 d = rays[i].direction;
    const float c = dot(d, d0);
    if (!(c > 0.f && c * c >= kCoherentCosine * kCoherentCosine * dot(d, d) * d0_sq)) return false;
  }
  return true;
}

/// A subtree waiting to be visited by the rays in `rays` (bit i: lane i), entered by the
/// nearest of them at `t`.
struct PacketStackEntry {
  WideStackEntry node;
  std::uint32_t rays;
};

/// One packet's walk through a wide BVH: the rays' state lane by lane, and the steps of the walk
/// (which rays enter a child, testing a leaf, finishing a subtree one ray at a time, pushing the
/// children). For rays of direction octant kOctant; kAnyHit asks for any hit.
template <int W, bool kAnyHit, int kOctant>
class PacketWalk {
 public:
  /// The state of `rays[0..n)` (n <= kPacketSize) with their closest hits so far in `hits`
  /// (ignored for any-hit queries).
  PacketWalk(const WideBvhTree<W>& tree, const Geometry& geometry, const Ray* rays, const Hit* hits, int n)
      : m_tree(tree), m_geometry(geometry), m_rays(rays), m_n(n) {
    load_lanes(hits);
    m_interval = packet_interval<W, kOctant>(m_origin, m_inv, m_tmin_lo);
    m_coherent = !kAnyHit && m_interval.valid && directions_coherent(rays, n);
    // Rays that share the watertight test's axis permutation can be tested ray-parallel.
    for (int i = 1; i < n; ++i) {
      m_same_axes = m_same_axes && m_tri_rays[i].kx == m_tri_rays[0].kx && m_tri_rays[i].ky == m_tri_rays[0].ky &&
                    m_tri_rays[i].kz == m_tri_rays[0].kz;
    }
    if (m_same_axes) {
      for (int g = 0; g < kGroups; ++g) m_group_rays[g] = watertight_rays<kRayLanes>(m_tri_rays + g * kRayLanes);
    }
  }

  /// Walks the tree, nearest subtree first, each with the mask of rays that entered it.
  void run() {
    PacketStackEntry stack[kWideStackSize<W>];
    int size = 0;
    PacketStackEntry current{{0, 0, m_tmin_lo}, m_alive};
    for (;;) {
      std::uint32_t active = current.rays & m_alive;
      if constexpr (!kAnyHit) active &= rays_before_closest_hit(current.node.t);
      if (active != 0 && std::popcount(active) <= kSingleRayThreshold) {
        walk_singly(current.node, active);
      } else if (active != 0 && current.node.count != 0) {
        test_leaf(current.node.child, current.node.count, active);
      } else if (active != 0) {
        push_children(m_tree.nodes[current.node.child], active, stack, size);
      }
      if (size == 0) break;
      current = stack[--size];
    }
  }

  /// Hands the results back: closest hits into `rays[i].tmax` and `hits[i]`, or whether each
  /// ray is occluded into `occluded_out[i]`.
  void write_results(Ray* rays, Hit* hits, std::uint8_t* occluded_out) const {
    for (int i = 0; i < m_n; ++i) {
      if constexpr (kAnyHit) {
        occluded_out[i] = (m_found >> i) & 1u;
      } else if ((m_found >> i) & 1u) {
        rays[i].tmax = m_tmax[i];
        hits[i] = m_best[i];
      }
    }
  }

 private:
  using L = simd::WideFloat<kRayLanes>;
  static constexpr int kGroups = kPacketSize / kRayLanes;
  static constexpr std::uint32_t kGroupMask = (1u << kRayLanes) - 1u;
  static constexpr int kNear[3] = {(kOctant & 1) ? 1 : 0, (kOctant & 2) ? 1 : 0, (kOctant & 4) ? 1 : 0};

  // Fills the lanes from the rays: structure of arrays for the box tests across rays (unused
  // lanes copy ray 0 and stay inactive), per ray for the single-ray leaf tests.
  void load_lanes(const Hit* hits) {
    for (int i = 0; i < kPacketSize; ++i) {
      const Ray& r = m_rays[i < m_n ? i : 0];
      for (int a = 0; a < 3; ++a) {
        m_origin[a][i] = r.origin[a];
        m_inv[a][i] = 1.f / r.direction[a];  // exactly as the single-ray box test computes it
      }
      m_tmin[i] = r.tmin;
      m_tmax[i] = r.tmax;
      m_tri_rays[i] = i < m_n ? WatertightRay(r) : m_tri_rays[0];
      if (i >= m_n) continue;
      m_best[i] = kAnyHit ? Hit{} : hits[i];
      m_tmin_lo = std::min(m_tmin_lo, r.tmin);
      // A ray with an empty or NaN interval takes no part (the single-ray walk would find nothing).
      if (r.tmin <= r.tmax) m_alive |= 1u << i;
    }
  }

  // Ray i found a hit: an any-hit ray is done.
  void record_hit(int i) {
    m_found |= 1u << i;
    if constexpr (kAnyHit) m_alive &= ~(1u << i);
  }

  // The rays whose closest hit so far is not nearer than a subtree entered at `t_enter`: the
  // others leave it.
  std::uint32_t rays_before_closest_hit(float t_enter) const {
    std::uint32_t still = 0;
    for (int g = 0; g < kGroups; ++g) {
      still |= static_cast<std::uint32_t>(
                   less_equal_mask(L::broadcast(t_enter), L::load(m_tmax + g * kRayLanes) * L::broadcast(kSlabWiden)))
               << (g * kRayLanes);
    }
    return still;
  }

  // Bit mask of the lanes of group g that enter child c of `node` within their own
  // [tmin, tmax]: the single-ray box test, lane by lane, with the same operations. Stores their
  // entry distances in `t_enter` unless it is null.
  std::uint32_t lanes_entering(const WideBvhNode<W>& node, int c, int g, float* t_enter) const {
    const int o = g * kRayLanes;
    L t_near = L::load(m_tmin + o);
    L t_far = L::broadcast(INFINITY);
    for (int a = 0; a < 3; ++a) {
      const L o_a = L::load(m_origin[a] + o), i_a = L::load(m_inv[a] + o);
      const L t0 = (L::broadcast(kNear[a] ? node.hi[a][c] : node.lo[a][c]) - o_a) * i_a;
      const L t1 = (L::broadcast(kNear[a] ? node.lo[a][c] : node.hi[a][c]) - o_a) * i_a;
      t_near = max(t0, t_near);
      t_far = min(t1, t_far);
    }
    t_far = min(t_far, L::load(m_tmax + o)) * L::broadcast(kSlabWiden);
    if (t_enter != nullptr) t_near.store(t_enter);
    return static_cast<std::uint32_t>(less_equal_mask(t_near, t_far)) << o;
  }

  // Finishes subtree `node` for each ray of `active` with the single-ray walk.
  void walk_singly(const WideStackEntry& node, std::uint32_t active) {
    for (std::uint32_t m = active; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      const Ray& r = m_rays[i];
      if (walk_wide_bvh<kAnyHit, false, W>(m_tree, m_geometry, node, WideBoxRay<W>(r), m_tri_rays[i], r, m_tmax[i],
                                           m_best[i], m_unused_counters)) {
        record_hit(i);
      }
    }
  }

  // The leaf (first, count_flags) for the rays in `active`: ray-parallel for the groups with
  // enough rays sharing the axis permutation, ray by ray for the others.
  void test_leaf(std::uint32_t first, std::uint32_t count_flags, std::uint32_t active) {
    std::uint32_t parallel = 0;
    if (m_same_axes) {
      for (int g = 0; g < kGroups; ++g) {
        const std::uint32_t m = (active >> (g * kRayLanes)) & kGroupMask;
        if (std::popcount(m) >= kRayParallelLeaf) parallel |= m << (g * kRayLanes);
      }
    }
    if (parallel != 0) test_leaf_triangles_ray_parallel(first, count_flags, parallel);
    for (std::uint32_t m = active & ~parallel; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (intersect_wide_leaf_triangles<kAnyHit, false, W>(m_tree.leaves, first, count_flags, m_tri_rays[i], m_tmin[i],
                                                           m_tmax[i], m_best[i], m_unused_counters)) {
        record_hit(i);
      }
    }
    if (!leaf_has_others<W>(count_flags)) return;
    for (std::uint32_t m = active & m_alive; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (intersect_wide_leaf_others<kAnyHit, false, W>(m_tree.leaves, m_geometry, first, count_flags, m_tri_rays[i],
                                                        m_rays[i], m_tmin[i], m_tmax[i], m_best[i],
                                                        m_unused_counters)) {
        record_hit(i);
      }
    }
  }

  // The leaf's triangles for the rays in `parallel`, each triangle against a whole group of
  // rays at once.
  void test_leaf_triangles_ray_parallel(std::uint32_t first, std::uint32_t count_flags, std::uint32_t parallel) {
    const std::uint32_t triangle_count = m_tree.leaves.triangle_count;
    for (std::uint32_t b = first; b < first + leaf_block_count<W>(count_flags); ++b) {
      const TriangleBlock4& block = m_tree.leaves.blocks[b];
      for (int lane = 0; lane < 4; ++lane) {
        const std::uint32_t id = block.id[lane];
        if (id >= triangle_count) continue;  // unused
        for (int g = 0; g < kGroups; ++g) {
          const int o = g * kRayLanes;
          if (((parallel & m_alive) >> o & kGroupMask) == 0) continue;
          alignas(64) float t[kRayLanes], u[kRayLanes], v[kRayLanes];
          std::uint32_t hit = intersect_triangle_rays<kRayLanes>(block, lane, m_group_rays[g], L::load(m_tmin + o),
                                                                 L::load(m_tmax + o), t, u, v);
          // Each candidate kept under the exact closest-hit rule (lower id on ties), as the
          // single-ray leaf test keeps it; an any-hit ray stops at its first.
          for (hit &= (parallel & m_alive) >> o; hit != 0; hit &= hit - 1) {
            const int i = o + std::countr_zero(hit);
            const int j = i - o;
            if (!(t[j] < m_best[i].tie_limit(id, m_tmax[i]))) continue;
            m_tmax[i] = t[j];
            m_best[i] = {t[j], id, u[j], v[j]};
            record_hit(i);
          }
        }
      }
    }
  }

  // Pushes the children of `node` that some ray of `active` enters, each with the mask of those
  // rays; for closest hits the farthest goes first, so the nearest is visited next.
  void push_children(const WideBvhNode<W>& node, std::uint32_t active, PacketStackEntry* stack, int& size) const {
    alignas(64) float order_t[W];
    unsigned candidates = WideBoxRay<W>::occupied_slots(node);
    if (m_interval.valid) {
      float packet_tmax = 0.f;
      for (std::uint32_t m = active; m != 0; m &= m - 1)
        packet_tmax = std::max(packet_tmax, m_tmax[std::countr_zero(m)]);
      candidates &= m_interval.template test<kOctant>(node, m_tmin_lo, packet_tmax, order_t);
    }
    const int base = size;
    for (; candidates != 0; candidates &= candidates - 1) {
      const int c = std::countr_zero(candidates);
      std::uint32_t entering = 0;
      if (m_coherent && node.count[c] == 0) {
        // A coherent packet enters interior children together on the interval test alone;
        // rays are culled one by one only before a leaf, where testing costs most.
        entering = active;
      } else if (m_interval.valid) {
        for (int g = 0; g < kGroups; ++g) entering |= lanes_entering(node, c, g, nullptr);
        entering &= active;
      } else {
        // No interval bound to order by: the nearest entry of the lanes that enter.
        alignas(64) float t_enter[kPacketSize];
        for (int g = 0; g < kGroups; ++g) entering |= lanes_entering(node, c, g, t_enter + g * kRayLanes);
        entering &= active;
        order_t[c] = INFINITY;
        for (std::uint32_t m = entering; m != 0; m &= m - 1)
          order_t[c] = std::min(order_t[c], t_enter[std::countr_zero(m)]);
      }
      if (entering == 0) continue;
      const PacketStackEntry e{{node.child[c], node.count[c], order_t[c]}, entering};
      int b = size++;
      for (; b > base && !kAnyHit && stack[b - 1].node.t < e.node.t; --b) stack[b] = stack[b - 1];
      stack[b] = e;
    }
  }

  const WideBvhTree<W>& m_tree;
  const Geometry& m_geometry;
  const Ray* m_rays;
  int m_n;
  alignas(64) float m_origin[3][kPacketSize];
  alignas(64) float m_inv[3][kPacketSize];
  alignas(64) float m_tmin[kPacketSize];
  alignas(64) float m_tmax[kPacketSize];
  WatertightRay m_tri_rays[kPacketSize];
  Hit m_best[kPacketSize];
  WatertightRays<kRayLanes> m_group_rays[kGroups];
  float m_tmin_lo = INFINITY;
  std::uint32_t m_found = 0;  // rays that found a hit (bit i: ray i)
  std::uint32_t m_alive = 0;  // rays still walking
  PacketInterval<W> m_interval;
  bool m_coherent = false;
  bool m_same_axes = true;
  TraversalCounters m_unused_counters;  // packets are never counted (kCount = false)
};

}  // namespace

template <int W>
template <bool kAnyHit, int kOctant>
void WideBvh<W>::trace_packet_octant(Ray* rays, Hit* hits, std::uint8_t* occluded_out, int n) const {
  PacketWalk<W, kAnyHit, kOctant> walk(m_tree, m_geometry, rays, hits, n);
  walk.run();
  walk.write_results(rays, hits, occluded_out);
}

template <int W>
template <bool kAnyHit>
void WideBvh<W>::trace_packet(Ray* rays, Hit* hits, std::uint8_t* occluded_out, int n) const {
  dispatch_octant(direction_octant(rays[0].direction), [&](auto octant) {
    trace_packet_octant<kAnyHit, decltype(octant)::value>(rays, hits, occluded_out, n);
  });
}

template <int W>
void WideBvh<W>::intersect(std::span<Ray> rays, std::span<Hit> hits) const {
  if (m_tree.leaves.empty()) return;
  for_each_octant_run(rays, [&](std::size_t begin, std::size_t end) {
    if (end - begin == 1) {
      intersect(rays[begin], hits[begin]);
    } else {
      trace_packet<false>(&rays[begin], &hits[begin], nullptr, static_cast<int>(end - begin));
    }
  });
}

template <int W>
void WideBvh<W>::occluded(std::span<const Ray> rays, std::span<std::uint8_t> occluded_out) const {
  if (m_tree.leaves.empty()) {
    std::fill(occluded_out.begin(), occluded_out.begin() + static_cast<std::ptrdiff_t>(rays.size()), std::uint8_t{0});
    return;
  }
  for_each_octant_run(rays, [&](std::size_t begin, std::size_t end) {
    if (end - begin == 1) {
      occluded_out[begin] = occluded(rays[begin]) ? 1 : 0;
    } else {
      // The packet kernel writes no ray state for any-hit queries; it takes a mutable pointer
      // only because closest-hit queries share it.
      trace_packet<true>(const_cast<Ray*>(&rays[begin]), nullptr, &occluded_out[begin], static_cast<int>(end - begin));
    }
  });
}

template void WideBvh<4>::intersect(std::span<Ray>, std::span<Hit>) const;
template void WideBvh<8>::intersect(std::span<Ray>, std::span<Hit>) const;
template void WideBvh<16>::intersect(std::span<Ray>, std::span<Hit>) const;
template void WideBvh<4>::occluded(std::span<const Ray>, std::span<std::uint8_t>) const;
template void WideBvh<8>::occluded(std::span<const Ray>, std::span<std::uint8_t>) const;
template void WideBvh<16>::occluded(std::span<const Ray>, std::span<std::uint8_t>) const;

}  // namespace raylab
