// Packet traversal of the wide BVH: up to 16 rays of one direction octant walk the tree together.
// A node is first tested against the packet's interval bounds (one conservative test for all
// rays: origins and reciprocal directions as intervals), then against each active ray; children
// are visited nearest first, each with the mask of rays that entered it. Leaves test each
// triangle, sphere and cylinder against a group of rays at once where enough rays reach them,
// else each active ray with the single-ray leaf kernel (other kinds always ray by ray), and when
// few rays remain in a subtree they finish it one by one with the single-ray walk. Every ray's
// result is the closest hit with the lower-id tie rule, whatever the visiting order, so packets
// equal single rays bit for bit.

#include <algorithm>
#include <bit>
#include <cmath>

#include "kernel_dispatch.h"
#include "raylab/accel/wide_bvh.h"
#include "raylab/core/float_neighbour.h"
#include "raylab/geometry/cylinder_rays.h"
#include "raylab/geometry/ray_lanes.h"
#include "raylab/geometry/sphere_rays.h"
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
    t_far = widen_exit(min(t_far, F::broadcast(tmax)));
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
    // One loop per bound, no choice inside: this runs for every packet.
    bound[0][a] = lanes[0][0];
    bound[1][a] = lanes[1][0];
    bound[2][a] = lanes[2][0];
    bound[3][a] = lanes[3][0];
    for (int i = 1; i < kRayLanes; ++i) {
      bound[0][a] = std::min(bound[0][a], lanes[0][i]);
      bound[1][a] = std::max(bound[1][a], lanes[1][i]);
      bound[2][a] = std::min(bound[2][a], lanes[2][i]);
      bound[3][a] = std::max(bound[3][a], lanes[3][i]);
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

/// Rays of one group from which a leaf's spheres and cylinders are tested ray-parallel (each
/// shape against the group's rays at once); a lone ray takes the single-ray leaf test, which
/// puts up to four spheres or cylinders against it. One and two measured the same under
/// callgrind on the SPD scenes; two was the faster by wall clock (docs/performance.md).
constexpr int kRayParallelOthers = 2;

/// Packets whose directions lie within this cosine of the first ray's walk interior nodes on
/// the packet's interval test alone: their interval is nearly as tight as each ray's own test.
constexpr float kCoherentCosine = 0.98f;

/// Whether the directions of all kPacketSize lanes (`direction[axis][lane]`; unused lanes repeat
/// lane 0) lie within kCoherentCosine of lane 0's, tested lane-parallel.
bool directions_coherent(const float (&direction)[3][kPacketSize]) {
  using L = simd::WideFloat<kRayLanes>;
  constexpr unsigned kAll = (1u << kRayLanes) - 1u;
  const float x0 = direction[0][0], y0 = direction[1][0], z0 = direction[2][0];
  const L d0x = L::broadcast(x0), d0y = L::broadcast(y0), d0z = L::broadcast(z0);
  const L bound = L::broadcast(kCoherentCosine * kCoherentCosine * (x0 * x0 + y0 * y0 + z0 * z0));
  const L zero = L::broadcast(0.f);
  for (int g = 0; g < kPacketSize / kRayLanes; ++g) {
    const int o = g * kRayLanes;
    const L dx = L::load(direction[0] + o), dy = L::load(direction[1] + o), dz = L::load(direction[2] + o);
    const L c = dx * d0x + dy * d0y + dz * d0z;
    const L length_sq = dx * dx + dy * dy + dz * dz;
    if ((less_mask(zero, c) & less_equal_mask(bound * length_sq, c * c)) != kAll) return false;
  }
  return true;
}

/// A subtree waiting to be visited by the rays in `rays` (bit i: lane i), entered by the
/// nearest of them at `t`.
struct PacketStackEntry {
  WideStackEntry node;
  std::uint32_t rays;
};

}  // namespace

template <int W>
template <bool kAnyHit, int kOctant, class K>
void WideBvh<W>::trace_packet_octant(Ray* rays, Hit* hits, std::uint8_t* occluded_out, int n) const {
  using L = simd::WideFloat<kRayLanes>;
  constexpr int kGroups = kPacketSize / kRayLanes;
  constexpr std::uint32_t kGroupMask = (1u << kRayLanes) - 1u;
  constexpr int kNear[3] = {(kOctant & 1) ? 1 : 0, (kOctant & 2) ? 1 : 0, (kOctant & 4) ? 1 : 0};
  // Per-lane state, as structure of arrays for the box tests across rays (unused lanes copy
  // ray 0 and stay inactive), and per ray for the single-ray leaf tests.
  alignas(64) float origin[3][kPacketSize], direction[3][kPacketSize], inv[3][kPacketSize], tmin[kPacketSize],
      tmax[kPacketSize];
  WatertightRay tri_rays[kPacketSize];
  Hit best[kPacketSize];
  for (int i = 0; i < kPacketSize; ++i) {
    const Ray& r = rays[i < n ? i : 0];
    for (int a = 0; a < 3; ++a) {
      origin[a][i] = r.origin[a];
      direction[a][i] = r.direction[a];
    }
    tmin[i] = r.tmin;
    tmax[i] = r.tmax;
  }
  // Exactly as the single-ray box test computes them (a correctly rounded division either way).
  for (int a = 0; a < 3; ++a) {
    for (int o = 0; o < kPacketSize; o += kRayLanes) (L::broadcast(1.f) / L::load(direction[a] + o)).store(inv[a] + o);
  }
  float tmin_lo = INFINITY;
  std::uint32_t found = 0, alive = 0;
  for (int i = 0; i < n; ++i) {
    const Ray& r = rays[i];
    best[i] = kAnyHit ? Hit{} : hits[i];
    tmin_lo = std::min(tmin_lo, r.tmin);
    // A ray with an empty or NaN interval, or no traceable direction, takes no part (the
    // single-ray entry points answer it with a miss too).
    if (r.tmin <= r.tmax && traceable_direction(r.direction)) alive |= 1u << i;
  }
  const PacketInterval<W> interval = packet_interval<W, kOctant>(origin, inv, tmin_lo);
  const bool coherent = !kAnyHit && interval.valid && directions_coherent(direction);
  WatertightRays<kRayLanes> group_rays[kGroups];
  RayLanes<kRayLanes> shape_rays[kGroups];  // for the spheres' and cylinders' ray-parallel tests
  for (int g = 0; g < kGroups; ++g) {
    const int o = g * kRayLanes;
    shape_rays[g] = RayLanes<kRayLanes>::load(origin[0] + o, origin[1] + o, origin[2] + o, direction[0] + o,
                                              direction[1] + o, direction[2] + o);
  }
  // The watertight triangle test's per-ray constants for the whole packet, made when it first
  // reaches a leaf with triangles: packets that miss the scene, or meet only spheres and
  // cylinders, never pay for them. A ray tested on its own before that (the single-ray walk,
  // a leaf's other kinds, which the Geometry may test with them) makes its own: tri_ray.
  bool same_axes = false;  // rays that share the watertight test's axis permutation
  bool triangles_ready = false;
  // Out of line: inlined into the leaf test it cost more than it saved (callgrind, SPD tree
  // 1,074.5 M instructions against 1,071.0 M, teapot 846.4 M against 844.6 M).
  auto make_triangle_rays = [&]() __attribute__((noinline)) {
    triangles_ready = true;
    same_axes = true;
    for (int i = 0; i < n; ++i) {
      tri_rays[i] = WatertightRay(rays[i]);
      // kx and ky decide kz (the three are a permutation).
      same_axes = same_axes && tri_rays[i].kx == tri_rays[0].kx && tri_rays[i].ky == tri_rays[0].ky;
    }
    for (int i = n; i < kPacketSize; ++i) tri_rays[i] = tri_rays[0];
    if (same_axes) {
      for (int g = 0; g < kGroups; ++g) group_rays[g] = watertight_rays<kRayLanes>(tri_rays + g * kRayLanes);
    }
  };
  auto prepare_triangles = [&] {
    if (!triangles_ready) make_triangle_rays();
  };
  // Ray i's constants alone, for a ray tested on its own before the packet's are made: the same
  // values (WatertightRay of the same ray) without the other fifteen. Made again at each call:
  // keeping those made in a mask cost more than it saved (callgrind, SPD tree 1,071.8 M
  // instructions against 1,071.0 M, rings 3,299.4 M against 3,297.7 M).
  auto tri_ray = [&](int i) { return triangles_ready ? tri_rays[i] : WatertightRay(rays[i]); };

  // Bit mask of the lanes of group g that enter child c of `node` within their own
  // [tmin, tmax]: the single-ray box test, lane by lane, with the same operations.
  auto lanes_entering = [&](const WideBvhNode<W>& node, int c, int g, float* t_enter) {
    const int o = g * kRayLanes;
    L t_near = L::load(tmin + o);
    L t_far = L::broadcast(INFINITY);
    for (int a = 0; a < 3; ++a) {
      const L o_a = L::load(origin[a] + o), i_a = L::load(inv[a] + o);
      const L t0 = (L::broadcast(kNear[a] ? node.hi[a][c] : node.lo[a][c]) - o_a) * i_a;
      const L t1 = (L::broadcast(kNear[a] ? node.lo[a][c] : node.hi[a][c]) - o_a) * i_a;
      t_near = max(t0, t_near);
      t_far = min(t1, t_far);
    }
    t_far = widen_exit(min(t_far, L::load(tmax + o)));
    if (t_enter != nullptr) t_near.store(t_enter);
    return static_cast<std::uint32_t>(less_equal_mask(t_near, t_far)) << o;
  };

  TraversalCounters unused_counters;  // packets are never counted (kCount = false)

  // Ray i found a hit: an any-hit ray is done.
  auto record_hit = [&](int i) {
    found |= 1u << i;
    if constexpr (kAnyHit) alive &= ~(1u << i);
  };

  // The leaf's primitives other than triangles (first, count_flags) for the rays in `rays_in`
  // (whole groups): each sphere against a group's rays at once, each cylinder's float rejection
  // the same way and the exact test for the rays it leaves, every other kind ray by ray. Each
  // ray keeps its closest hit under the tie rule (lower id on ties), which does not depend on
  // the order of the tests, so the answers are those of the single-ray leaf test.
  auto test_others_ray_parallel = [&](std::uint32_t first, std::uint32_t count_flags, std::uint32_t rays_in) {
    const WideBvhLeaves& leaves = m_tree.leaves;
    const LeafOthers others = leaf_others(leaves, m_geometry, first, count_flags);
    // The limits handed to the sphere test: for closest hits the float above each ray's tmax
    // now, which is at least any tie limit the rule applies later in this leaf.
    alignas(64) float limit[kPacketSize];
    for (std::uint32_t m = rays_in; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      limit[i] = kAnyHit ? tmax[i] : next_float_up(tmax[i]);
    }
    for (std::size_t k = 0; k < others.sphere_end; ++k) {
      const std::uint32_t id = others.ids[k];
      const Sphere sphere = leaves.sphere_lanes_at(others.position + k).sphere(0);
      for (int g = 0; g < kGroups; ++g) {
        const int o = g * kRayLanes;
        const std::uint32_t lanes = ((rays_in & alive) >> o) & kGroupMask;
        if (lanes == 0) continue;
        alignas(64) float t[kRayLanes];
        for (std::uint32_t hit = intersect_sphere_rays<kRayLanes>(sphere, shape_rays[g], lanes, L::load(tmin + o),
                                                                  L::load(limit + o), t);
             hit != 0; hit &= hit - 1) {
          const int j = std::countr_zero(hit);
          const int i = o + j;
          if constexpr (!kAnyHit) {
            if (!(t[j] < best[i].tie_limit(id, tmax[i]))) continue;
            tmax[i] = t[j];
            best[i] = {t[j], id, 0.f, 0.f};
          }
          record_hit(i);
        }
      }
    }
    for (std::size_t k = others.sphere_end; k < others.cylinder_end; ++k) {
      const std::uint32_t id = others.ids[k];
      const CylinderFrame& frame = *leaves.cylinder_frame_of(id);
      for (int g = 0; g < kGroups; ++g) {
        const int o = g * kRayLanes;
        const std::uint32_t lanes = ((rays_in & alive) >> o) & kGroupMask;
        if (lanes == 0) continue;
        for (std::uint32_t maybe = lanes & ~cylinders_surely_missed_by_rays<kRayLanes>(frame, shape_rays[g], lanes);
             maybe != 0; maybe &= maybe - 1) {
          const int i = o + std::countr_zero(maybe);
          if (intersect_cylinder_frame_exact<kAnyHit>(frame, id, rays[i], tmin[i], tmax[i], best[i])) record_hit(i);
        }
      }
    }
    if (others.cylinder_end == others.ids.size()) return;
    const std::span<const std::uint32_t> rest = others.ids.subspan(others.cylinder_end);
    for (std::uint32_t m = rays_in & alive; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (intersect_leaf_one_by_one<kAnyHit>(leaves, m_geometry, rest, tri_ray(i), rays[i], tmin[i], tmax[i],
                                             best[i])) {
        record_hit(i);
      }
    }
  };

  // The leaf's triangles (first, count_flags) for the rays in `active`: ray-parallel for the
  // groups with enough rays sharing the axis permutation, ray by ray for the others.
  auto test_triangles = [&](std::uint32_t first, std::uint32_t count_flags, std::uint32_t active) {
    prepare_triangles();
    std::uint32_t parallel = 0;
    if (same_axes) {
      for (int g = 0; g < kGroups; ++g) {
        const std::uint32_t m = (active >> (g * kRayLanes)) & kGroupMask;
        if (std::popcount(m) >= kRayParallelLeaf) parallel |= m << (g * kRayLanes);
      }
    }
    const std::uint32_t triangle_count = m_tree.leaves.triangle_count;
    for (std::uint32_t b = first; parallel != 0 && b < first + leaf_block_count<W>(count_flags); ++b) {
      const TriangleBlock4& block = m_tree.leaves.blocks[b];
      for (int lane = 0; lane < 4; ++lane) {
        const std::uint32_t id = block.id[lane];
        if (id >= triangle_count) continue;  // unused
        for (int g = 0; g < kGroups; ++g) {
          const int o = g * kRayLanes;
          if (((parallel & alive) >> o & kGroupMask) == 0) continue;
          alignas(64) float t[kRayLanes], u[kRayLanes], v[kRayLanes];
          std::uint32_t hit = intersect_triangle_rays<kRayLanes>(block, lane, group_rays[g], L::load(tmin + o),
                                                                 L::load(tmax + o), t, u, v);
          // Each candidate kept under the exact closest-hit rule (lower id on ties), as the
          // single-ray leaf test keeps it; an any-hit ray stops at its first.
          for (hit &= (parallel & alive) >> o; hit != 0; hit &= hit - 1) {
            const int i = o + std::countr_zero(hit);
            const int j = i - o;
            if (!(t[j] < best[i].tie_limit(id, tmax[i]))) continue;
            tmax[i] = t[j];
            best[i] = {t[j], id, u[j], v[j]};
            record_hit(i);
          }
        }
      }
    }
    for (std::uint32_t m = active & ~parallel; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (intersect_wide_leaf_triangles<kAnyHit, false, W>(m_tree.leaves, first, count_flags, tri_rays[i], tmin[i],
                                                           tmax[i], best[i], unused_counters)) {
        record_hit(i);
      }
    }
  };

  // The leaf (first, count_flags) for the rays in `active`: its triangles, then its other
  // primitives.
  auto test_leaf = [&](std::uint32_t first, std::uint32_t count_flags, std::uint32_t active) {
    if (leaf_block_count<W>(count_flags) != 0) test_triangles(first, count_flags, active);
    if (!leaf_has_others<W>(count_flags)) return;
    std::uint32_t by_ray = active & alive;
    std::uint32_t parallel_others = 0;
    for (int g = 0; g < kGroups; ++g) {
      const std::uint32_t m = (by_ray >> (g * kRayLanes)) & kGroupMask;
      if (std::popcount(m) >= kRayParallelOthers) parallel_others |= m << (g * kRayLanes);
    }
    if (parallel_others != 0) {
      test_others_ray_parallel(first, count_flags, parallel_others);
      by_ray &= ~parallel_others;
    }
    for (std::uint32_t m = by_ray; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (intersect_wide_leaf_others<kAnyHit, false, W>(m_tree.leaves, m_geometry, first, count_flags, tri_ray(i),
                                                        rays[i], tmin[i], tmax[i], best[i], unused_counters)) {
        record_hit(i);
      }
    }
  };

  PacketStackEntry stack[kWideStackSize<W>];
  int size = 0;
  PacketStackEntry current{{0, 0, tmin_lo}, alive};
  for (;;) {
    std::uint32_t active = current.rays & alive;
    // Rays whose closest hit is already nearer than the subtree's entry leave it.
    if constexpr (!kAnyHit) {
      std::uint32_t still = 0;
      for (int g = 0; g < kGroups; ++g) {
        still |= static_cast<std::uint32_t>(
                     less_equal_mask(L::broadcast(current.node.t), widen_exit(L::load(tmax + g * kRayLanes))))
                 << (g * kRayLanes);
      }
      active &= still;
    }
    if (active != 0 && std::popcount(active) <= kSingleRayThreshold) {
      for (std::uint32_t m = active; m != 0; m &= m - 1) {
        const int i = std::countr_zero(m);
        Ray& r = rays[i];
        if (walk_wide_bvh<kAnyHit, false, W>(m_tree, m_geometry, current.node, WideBoxRay<W>(r), tri_ray(i), r, tmax[i],
                                             best[i], unused_counters)) {
          record_hit(i);
        }
      }
    } else if (active != 0 && current.node.count != 0) {
      test_leaf(current.node.child, current.node.count, active);
    } else if (active != 0) {
      const WideBvhNode<W>& node = m_tree.nodes[current.node.child];
      alignas(64) float order_t[W];
      unsigned candidates = WideBoxRay<W>::occupied_slots(node);
      if (interval.valid) {
        float packet_tmax = 0.f;
        for (std::uint32_t m = active; m != 0; m &= m - 1)
          packet_tmax = std::max(packet_tmax, tmax[std::countr_zero(m)]);
        candidates &= interval.template test<kOctant>(node, tmin_lo, packet_tmax, order_t);
      }
      const int base = size;
      for (; candidates != 0; candidates &= candidates - 1) {
        const int c = std::countr_zero(candidates);
        std::uint32_t entering = 0;
        if (coherent && node.count[c] == 0) {
          // A coherent packet enters interior children together on the interval test alone;
          // rays are culled one by one only before a leaf, where testing costs most.
          entering = active;
        } else if (interval.valid) {
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
        // Push farthest first (closest hits), so the nearest is visited next.
        const PacketStackEntry e{{node.child[c], node.count[c], order_t[c]}, entering};
        int b = size++;
        for (; b > base && !kAnyHit && stack[b - 1].node.t < e.node.t; --b) stack[b] = stack[b - 1];
        stack[b] = e;
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
template <bool kAnyHit, class K>
void WideBvh<W>::trace_packet(Ray* rays, Hit* hits, std::uint8_t* occluded_out, int n) const {
  dispatch_octant(direction_octant(rays[0].direction), [&](auto octant) {
    trace_packet_octant<kAnyHit, decltype(octant)::value, K>(rays, hits, occluded_out, n);
  });
}

// The packet kernels of the three widths under the set tag Tag, both queries, each preceded by
// `Keywords` (as RAYLAB_TRAVERSE_FORMS).
#define RAYLAB_PACKET_FORMS(Keywords, Tag)                                                   \
  Keywords void WideBvh<4>::trace_packet<false, Tag>(Ray*, Hit*, std::uint8_t*, int) const;  \
  Keywords void WideBvh<8>::trace_packet<false, Tag>(Ray*, Hit*, std::uint8_t*, int) const;  \
  Keywords void WideBvh<16>::trace_packet<false, Tag>(Ray*, Hit*, std::uint8_t*, int) const; \
  Keywords void WideBvh<4>::trace_packet<true, Tag>(Ray*, Hit*, std::uint8_t*, int) const;   \
  Keywords void WideBvh<8>::trace_packet<true, Tag>(Ray*, Hit*, std::uint8_t*, int) const;   \
  Keywords void WideBvh<16>::trace_packet<true, Tag>(Ray*, Hit*, std::uint8_t*, int) const

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
// The packet kernels of the other sets, compiled in their own kernel sources (see
// RAYLAB_EXTERN_TRAVERSE in kernel_dispatch.h for why they are declared).
#ifdef RAYLAB_KERNELS_AVX2
RAYLAB_PACKET_FORMS(extern template, isa_avx2::KernelIsa);
#endif
#ifdef RAYLAB_KERNELS_AVX512
RAYLAB_PACKET_FORMS(extern template, isa_avx512::KernelIsa);
#endif

template <int W>
void WideBvh<W>::intersect(std::span<Ray> rays, std::span<Hit> hits) const {
  if (m_tree.leaves.empty()) return;
  for_each_octant_run(rays, [&](std::size_t begin, std::size_t end) {
    if (end - begin == 1) {
      intersect(rays[begin], hits[begin]);
    } else {
      with_kernels(this->kernel_isa(), [&]<class K>() {
        trace_packet<false, K>(&rays[begin], &hits[begin], nullptr, static_cast<int>(end - begin));
      });
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
      with_kernels(this->kernel_isa(), [&]<class K>() {
        trace_packet<true, K>(const_cast<Ray*>(&rays[begin]), nullptr, &occluded_out[begin],
                              static_cast<int>(end - begin));
      });
    }
  });
}

template void WideBvh<4>::intersect(std::span<Ray>, std::span<Hit>) const;
template void WideBvh<8>::intersect(std::span<Ray>, std::span<Hit>) const;
template void WideBvh<16>::intersect(std::span<Ray>, std::span<Hit>) const;
template void WideBvh<4>::occluded(std::span<const Ray>, std::span<std::uint8_t>) const;
template void WideBvh<8>::occluded(std::span<const Ray>, std::span<std::uint8_t>) const;
template void WideBvh<16>::occluded(std::span<const Ray>, std::span<std::uint8_t>) const;

#endif  // RAYLAB_KERNEL_VARIANT

// The packet kernels, compiled here for this translation unit's instruction set.
RAYLAB_PACKET_FORMS(template, KernelIsa);

}  // namespace raylab
