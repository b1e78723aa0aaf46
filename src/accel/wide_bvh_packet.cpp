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
#include "wide_bvh_walk.h"

namespace raylab {
namespace {

/// Rays per packet: 16 is a 4x4 pixel tile.
constexpr int kPacketSize = 16;

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
  unsigned test(const WideBvhNode<W>& node, float tmin, float tmax) const {
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
    return static_cast<unsigned>(less_equal_mask(t_near, t_far));
  }
};

/// A subtree waiting to be visited by the rays in `rays` (bit i: lane i), entered by the
/// nearest of them at `t`.
struct PacketStackEntry {
  WideStackEntry node;
  std::uint32_t rays;
};

}  // namespace

template <int W>
template <bool kAnyHit, int kOctant>
void WideBvh<W>::trace_packet_octant(Ray* rays, Hit* hits, std::uint8_t* occluded_out, int n) const {
  // Per-lane state: the box and triangle constants, the running closest distance and hit.
  WideBoxRay<W> box_rays[kPacketSize];
  WatertightRay tri_rays[kPacketSize];
  float tmax[kPacketSize];
  Hit best[kPacketSize];
  float tmin_lo = INFINITY;
  std::uint32_t found = 0, alive = 0;
  for (int i = 0; i < n; ++i) {
    box_rays[i] = WideBoxRay<W>(rays[i]);
    tri_rays[i] = WatertightRay(rays[i]);
    tmax[i] = rays[i].tmax;
    best[i] = kAnyHit ? Hit{} : hits[i];
    tmin_lo = std::min(tmin_lo, rays[i].tmin);
    // A ray with an empty or NaN interval takes no part (the single-ray walk would find nothing).
    if (rays[i].tmin <= rays[i].tmax) alive |= 1u << i;
  }

  // The packet's interval bounds, when every ray allows them.
  PacketInterval<W> interval;
  {
    bool ok = !(tmin_lo != tmin_lo);
    float o_lo[3] = {INFINITY, INFINITY, INFINITY}, o_hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    float i_lo[3] = {INFINITY, INFINITY, INFINITY}, i_hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < n && ok; ++i) {
      for (int a = 0; a < 3; ++a) {
        const float o = rays[i].origin[a], inv = 1.f / rays[i].direction[a];
        ok = ok && std::isfinite(o) && std::isfinite(inv) && inv != 0.f;
        o_lo[a] = std::min(o_lo[a], o);
        o_hi[a] = std::max(o_hi[a], o);
        i_lo[a] = std::min(i_lo[a], inv);
        i_hi[a] = std::max(i_hi[a], inv);
      }
    }
    interval.valid = ok;
    using F = simd::WideFloat<W>;
    for (int a = 0; a < 3 && ok; ++a) {
      const bool negative = (kOctant >> a) & 1;
      // Near plane minus origin is smallest at the origin farthest along the direction.
      interval.near_o[a] = F::broadcast(negative ? o_lo[a] : o_hi[a]);
      interval.far_o[a] = F::broadcast(negative ? o_hi[a] : o_lo[a]);
      interval.inv_lo[a] = F::broadcast(i_lo[a]);
      interval.inv_hi[a] = F::broadcast(i_hi[a]);
    }
  }

  std::uint64_t nodes_visited = 0, prim_tests = 0;  // not reported: packets are never counted
  PacketStackEntry stack[kWideStackSize<W>];
  int size = 0;
  PacketStackEntry current{{0, 0, tmin_lo}, alive};
  for (;;) {
    std::uint32_t active = current.rays & alive;
    // Rays whose closest hit is already nearer than the subtree's entry leave it.
    if constexpr (!kAnyHit) {
      for (std::uint32_t m = active; m != 0; m &= m - 1) {
        const int i = std::countr_zero(m);
        if (!(current.node.t <= tmax[i] * kSlabWiden)) active &= ~(1u << i);
      }
    }
    if (active != 0 && std::popcount(active) <= kSingleRayThreshold) {
      for (std::uint32_t m = active; m != 0; m &= m - 1) {
        const int i = std::countr_zero(m);
        if (walk_wide_bvh<kAnyHit, false, kOctant, W>(m_tree, m_geometry, current.node, box_rays[i], tri_rays[i],
                                                      rays[i], tmax[i], best[i], nodes_visited, prim_tests)) {
          found |= 1u << i;
          if constexpr (kAnyHit) alive &= ~(1u << i);
        }
      }
    } else if (active != 0 && current.node.count != 0) {
      for (std::uint32_t m = active; m != 0; m &= m - 1) {
        const int i = std::countr_zero(m);
        if (intersect_wide_leaf<kAnyHit, false, W>(m_tree.leaves, m_geometry, current.node.child, current.node.count,
                                                   tri_rays[i], rays[i], rays[i].tmin, tmax[i], best[i], prim_tests)) {
          found |= 1u << i;
          if constexpr (kAnyHit) alive &= ~(1u << i);
        }
      }
    } else if (active != 0) {
      const WideBvhNode<W>& node = m_tree.nodes[current.node.child];
      float packet_tmax = 0.f;
      for (std::uint32_t m = active; m != 0; m &= m - 1) packet_tmax = std::max(packet_tmax, tmax[std::countr_zero(m)]);
      const unsigned candidates =
          interval.valid ? interval.template test<kOctant>(node, tmin_lo, packet_tmax) : (1u << W) - 1u;
      if (candidates != 0) {
        std::uint32_t child_rays[W] = {};
        float child_t[W];
        std::fill(child_t, child_t + W, INFINITY);
        for (std::uint32_t m = active; m != 0; m &= m - 1) {
          const int i = std::countr_zero(m);
          alignas(64) float t_enter[W];
          unsigned hit_children = box_rays[i].template test<kOctant>(node, rays[i].tmin, tmax[i], t_enter) & candidates;
          for (; hit_children != 0; hit_children &= hit_children - 1) {
            const int c = std::countr_zero(hit_children);
            child_rays[c] |= 1u << i;
            child_t[c] = std::min(child_t[c], t_enter[c]);
          }
        }
        // Push the entered children farthest first, so the nearest is visited next.
        const int base = size;
        for (int c = 0; c < W; ++c) {
          if (child_rays[c] == 0) continue;
          const PacketStackEntry e{{node.child[c], node.count[c], child_t[c]}, child_rays[c]};
          int b = size++;
          for (; b > base && !kAnyHit && stack[b - 1].node.t < e.node.t; --b) stack[b] = stack[b - 1];
          stack[b] = e;
        }
      }
    }
    if (size == 0) break;
    current = stack[--size];
  }

  for (int i = 0; i < n; ++i) {
    if constexpr (kAnyHit) {
      occluded_out[i] = (found >> i) & 1u;
    } else if ((found >> i) & 1u) {
      rays[i].tmax = tmax[i];
      hits[i] = best[i];
    }
  }
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
  if (m_tree.leaves.blocks.empty()) return;
  // Runs of up to 16 consecutive rays of one octant form a packet; a lone ray goes alone.
  std::size_t i = 0;
  while (i < rays.size()) {
    const int octant = direction_octant(rays[i].direction);
    std::size_t end = i + 1;
    while (end < rays.size() && end - i < kPacketSize && direction_octant(rays[end].direction) == octant) ++end;
    if (end - i == 1) {
      intersect(rays[i], hits[i]);
    } else {
      trace_packet<false>(&rays[i], &hits[i], nullptr, static_cast<int>(end - i));
    }
    i = end;
  }
}

template <int W>
void WideBvh<W>::occluded(std::span<const Ray> rays, std::span<std::uint8_t> occluded_out) const {
  std::size_t i = 0;
  while (i < rays.size()) {
    const int octant = direction_octant(rays[i].direction);
    std::size_t end = i + 1;
    while (end < rays.size() && end - i < kPacketSize && direction_octant(rays[end].direction) == octant) ++end;
    if (m_tree.leaves.blocks.empty()) {
      std::fill(occluded_out.begin() + i, occluded_out.begin() + end, std::uint8_t{0});
    } else if (end - i == 1) {
      occluded_out[i] = occluded(rays[i]) ? 1 : 0;
    } else {
      // The packet kernel writes no ray state for any-hit queries; it takes a mutable pointer
      // only because closest-hit queries share it.
      trace_packet<true>(const_cast<Ray*>(&rays[i]), nullptr, &occluded_out[i], static_cast<int>(end - i));
    }
    i = end;
  }
}

template void WideBvh<4>::intersect(std::span<Ray>, std::span<Hit>) const;
template void WideBvh<8>::intersect(std::span<Ray>, std::span<Hit>) const;
template void WideBvh<16>::intersect(std::span<Ray>, std::span<Hit>) const;
template void WideBvh<4>::occluded(std::span<const Ray>, std::span<std::uint8_t>) const;
template void WideBvh<8>::occluded(std::span<const Ray>, std::span<std::uint8_t>) const;
template void WideBvh<16>::occluded(std::span<const Ray>, std::span<std::uint8_t>) const;

}  // namespace raylab
