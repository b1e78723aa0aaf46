// The 4-wide BVH accelerator: build, collapse, and traversal with one SIMD box test per node.

#include "raylab/accel/bvh4.h"

#include <bit>
#include <chrono>
#include <cmath>

#include "raylab/simd/float4.h"
#include "traversal_common.h"

namespace raylab {
namespace {

// Each step pushes at most three entries and the tree is at most ~96 levels deep (the builder's
// median fallback bounds it), so 512 entries cannot overflow.
constexpr int kStackSize = 512;

int depth_of(const std::vector<Bvh4Node>& nodes, std::uint32_t index) {
  int deepest = 0;
  const Bvh4Node& n = nodes[index];
  for (int i = 0; i < 4; ++i) {
    if (n.count[i] == 0 && n.lo[0][i] <= n.hi[0][i]) {  // an interior slot (empty slots have empty boxes)
      deepest = std::max(deepest, 1 + depth_of(nodes, n.child[i]));
    }
  }
  return deepest;
}

}  // namespace

Bvh4::Bvh4(const Geometry& geometry, const BvhConfig& config) : Bvh4(geometry, geometry.primitive_ids(), config) {}

Bvh4::Bvh4(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config)
    : m_geometry(geometry) {
  const auto start = std::chrono::steady_clock::now();
  BvhTree tree = build_bvh(geometry, ids, config);
  m_nodes = collapse_to_bvh4(tree);
  m_prim_ids = std::move(tree.prim_ids);
  m_leaf_triangles = triangles_in_leaf_order(geometry, m_prim_ids);
  m_triangle_count = static_cast<std::uint32_t>(geometry.triangles.size());
  m_leaf_count = tree.leaf_count;
  const BvhNode& root = tree.nodes[0];
  m_bounds = {{root.lo[0], root.lo[1], root.lo[2]}, {root.hi[0], root.hi[1], root.hi[2]}};
  m_build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m_max_depth = m_prim_ids.empty() ? 0 : depth_of(m_nodes, 0);
}

template <bool kAnyHit, bool kCount>
bool Bvh4::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  if (m_prim_ids.empty()) return false;
  return dispatch_octant(direction_octant(ray.direction), [&](auto octant) {
    return traverse_octant<kAnyHit, kCount, decltype(octant)::value>(ray, hit, stats);
  });
}

template <bool kAnyHit, bool kCount, int kOctant>
bool Bvh4::traverse_octant(Ray& ray, Hit& hit, TraversalStats* stats) const {
  using simd::Float4;
  // Near plane per axis: `hi` where the direction is negative. Chosen at compile time.
  constexpr int kNearX = (kOctant & 1) ? 1 : 0, kNearY = (kOctant & 2) ? 1 : 0, kNearZ = (kOctant & 4) ? 1 : 0;
  const Float4 ox = Float4::broadcast(ray.origin.x), oy = Float4::broadcast(ray.origin.y),
               oz = Float4::broadcast(ray.origin.z);
  // Exact reciprocals (infinite for zero components); NaN slabs that result for a ray lying in a
  // face plane are dropped by min/max taking the running value as second operand.
  const Float4 ix = Float4::broadcast(1.f / ray.direction.x), iy = Float4::broadcast(1.f / ray.direction.y),
               iz = Float4::broadcast(1.f / ray.direction.z);
  const Float4 widen = Float4::broadcast(kSlabWiden);
  const Float4 infinity = Float4::broadcast(INFINITY);
  const WatertightRay tri_ray(ray);
  const LeafPrimitives leaf{m_prim_ids.data(), m_leaf_triangles.data(), m_triangle_count, &m_geometry};
  const Bvh4Node* const nodes = m_nodes.data();

  const float tmin = ray.tmin;
  float tmax = ray.tmax;
  Hit best = hit;
  bool found = false;
  std::uint64_t nodes_visited = 0, prim_tests = 0;
  TraversalStack<kStackSize> stack;
  std::uint32_t current = 0;
  for (;;) {
    const Bvh4Node& node = nodes[current];
    if constexpr (kCount) ++nodes_visited;
    const Float4 tx0 = (Float4::load(kNearX ? node.hi[0] : node.lo[0]) - ox) * ix;
    const Float4 tx1 = (Float4::load(kNearX ? node.lo[0] : node.hi[0]) - ox) * ix;
    const Float4 ty0 = (Float4::load(kNearY ? node.hi[1] : node.lo[1]) - oy) * iy;
    const Float4 ty1 = (Float4::load(kNearY ? node.lo[1] : node.hi[1]) - oy) * iy;
    const Float4 tz0 = (Float4::load(kNearZ ? node.hi[2] : node.lo[2]) - oz) * iz;
    const Float4 tz1 = (Float4::load(kNearZ ? node.lo[2] : node.hi[2]) - oz) * iz;
    const Float4 t_near = max(tz0, max(ty0, max(tx0, Float4::broadcast(tmin))));
    // Widened after the closest-hit limit too: a primitive in a box face can be hit at a
    // distance that rounds just below the box's computed entry and the current closest hit.
    const Float4 t_far = min(min(tz1, min(ty1, min(tx1, infinity))), Float4::broadcast(tmax)) * widen;
    int mask = less_equal_mask(t_near, t_far);
    alignas(16) float t_enter[4];
    t_near.store(t_enter);

    // Leaves are tested at once (a hit shrinks tmax, which culls the rest); interior children
    // are collected and visited nearest first.
    std::uint32_t next[4];
    float next_t[4];
    int n = 0;
    while (mask != 0) {
      const int i = std::countr_zero(static_cast<unsigned>(mask));
      mask &= mask - 1;
      if (node.count[i] != 0) {
        if (intersect_leaf<kAnyHit, kCount>(leaf, node.child[i], node.count[i], tri_ray, ray, tmin, tmax, best,
                                            prim_tests)) {
          found = true;
          if constexpr (kAnyHit) {
            return finish_traversal<kCount>(true, tmax, best, nodes_visited, prim_tests, ray, hit, stats);
          }
        }
      } else {
        next[n] = node.child[i];
        next_t[n] = t_enter[i];
        ++n;
      }
    }
    if (n > 0) {
      // Insertion sort, farthest first, so the nearest ends up on top of the stack. Any-hit
      // queries skip it: any occluder will do, so the order buys nothing.
      for (int a = 1; !kAnyHit && a < n; ++a) {
        for (int b = a; b > 0 && next_t[b - 1] < next_t[b]; --b) {
          std::swap(next_t[b - 1], next_t[b]);
          std::swap(next[b - 1], next[b]);
        }
      }
      for (int a = 0; a + 1 < n; ++a) {
        if (kAnyHit || next_t[a] <= tmax) stack.push(next[a], next_t[a]);
      }
      if (kAnyHit || next_t[n - 1] <= tmax) {
        current = next[n - 1];
        continue;
      }
    }
    // Continue with the next subtree that can still hold a closer hit.
    if (!stack.template pop<kAnyHit>(tmax, current)) break;
  }
  return finish_traversal<kCount>(found, tmax, best, nodes_visited, prim_tests, ray, hit, stats);
}

bool Bvh4::intersect(Ray& ray, Hit& hit) const { return traverse<false, false>(ray, hit, nullptr); }

bool Bvh4::occluded(const Ray& ray) const {
  Ray probe = ray;
  Hit scratch;
  return traverse<true, false>(probe, scratch, nullptr);
}

bool Bvh4::intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const {
  return traverse<false, true>(ray, hit, &stats);
}

bool Bvh4::occluded_counted(const Ray& ray, TraversalStats& stats) const {
  Ray probe = ray;
  Hit scratch;
  return traverse<true, true>(probe, scratch, &stats);
}

AccelInfo Bvh4::info() const {
  AccelInfo info;
  info.name = "bvh";
  info.build_seconds = m_build_seconds;
  info.memory_bytes = m_nodes.size() * sizeof(Bvh4Node) + m_prim_ids.size() * sizeof(std::uint32_t) +
                      m_leaf_triangles.size() * sizeof(Triangle);
  info.node_count = m_nodes.size();
  info.leaf_count = m_leaf_count;
  info.primitive_count = m_prim_ids.size();
  info.max_depth = m_max_depth;
  return info;
}

}  // namespace raylab
