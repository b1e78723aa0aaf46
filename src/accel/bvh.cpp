// BVH traversal: closest hit with front-to-back child order, any hit with early exit.

#include <chrono>
#include <cmath>

#include "raylab/accel/bvh.h"

namespace raylab {
namespace {

// Slab factor of Ize (2013) as used by pbrt: widening the exit distance by 1 + 2 * gamma(3)
// makes the float slab test conservative, so a primitive lying on a box face is never culled.
constexpr float kSlabWiden = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

// Per-ray constants for box tests: origin, reciprocal direction and which plane is near per axis.
// The slab distances are (plane - origin) * inv_dir with exact IEEE infinities for zero direction
// components. The shorter plane * inv_dir - origin * inv_dir (one FMA) was tried and rejected:
// for a ray lying in a face plane it turns into inf - inf, and with a tiny stand-in direction the
// rounding residual of origin * inv_dir is huge, so such rays were culled wrongly.
struct BoxRay {
  Vec3 origin;
  Vec3 inv_dir;
  bool negative[3];

  explicit BoxRay(const Ray& ray) : origin(ray.origin), inv_dir(safe_reciprocal(ray.direction)) {
    for (int a = 0; a < 3; ++a) negative[a] = inv_dir[a] < 0.f;
  }
};

// Entry distance into `node` if the ray's [tmin, tmax] overlaps it. NaN slabs (origin on the
// plane of a face, direction parallel to it) are ignored by the comparison order, so boxes are
// closed sets.
inline bool hit_node(const BvhNode& node, const BoxRay& r, float tmin, float tmax, float& t_enter) {
  float t_near = tmin;
  float t_far = tmax;
  for (int a = 0; a < 3; ++a) {
    const float near_plane = r.negative[a] ? node.hi[a] : node.lo[a];
    const float far_plane = r.negative[a] ? node.lo[a] : node.hi[a];
    const float t0 = (near_plane - r.origin[a]) * r.inv_dir[a];
    const float t1 = (far_plane - r.origin[a]) * r.inv_dir[a] * kSlabWiden;
    t_near = t0 > t_near ? t0 : t_near;
    t_far = t1 < t_far ? t1 : t_far;
  }
  t_enter = t_near;
  return t_near <= t_far;
}

struct StackEntry {
  std::uint32_t node;
  float t_enter;
};
constexpr int kStackSize = 128;  // the builder bounds depth well below this (see bvh_build.cpp)

}  // namespace

Bvh::Bvh(const Geometry& geometry, const BvhConfig& config) : m_geometry(geometry) {
  const auto start = std::chrono::steady_clock::now();
  m_tree = build_bvh(geometry, config);
  m_triangle_count = static_cast<std::uint32_t>(geometry.triangles.size());
  m_leaf_triangles.resize(m_tree.prim_ids.size());
  for (std::size_t i = 0; i < m_tree.prim_ids.size(); ++i) {
    const std::uint32_t id = m_tree.prim_ids[i];
    if (id < m_triangle_count) m_leaf_triangles[i] = geometry.triangles[id];
  }
  m_build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Box3 Bvh::bounds() const {
  const BvhNode& root = m_tree.nodes[0];
  return {{root.lo[0], root.lo[1], root.lo[2]}, {root.hi[0], root.hi[1], root.hi[2]}};
}

template <bool kAnyHit, bool kCount>
bool Bvh::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  if (m_tree.prim_ids.empty()) return false;
  const BvhNode* nodes = m_tree.nodes.data();
  const BoxRay box_ray(ray);
  const WatertightRay tri_ray(ray);
  float t_root = 0.f;
  if constexpr (kCount) ++stats->nodes_visited;
  if (!hit_node(nodes[0], box_ray, ray.tmin, ray.tmax, t_root)) return false;

  StackEntry stack[kStackSize];
  int sp = 0;
  std::uint32_t current = 0;
  bool found = false;
  for (;;) {
    const BvhNode& node = nodes[current];
    if (node.is_leaf()) {
      const std::uint32_t end = node.first + node.count;
      for (std::uint32_t i = node.first; i < end; ++i) {
        const std::uint32_t id = m_tree.prim_ids[i];
        if constexpr (kCount) ++stats->prim_tests;
        bool hit_here;
        if (id < m_triangle_count) {
          float t, u, v;
          hit_here = intersect_triangle(m_leaf_triangles[i], tri_ray, ray.tmin, ray.tmax, t, u, v);
          if (hit_here) {
            ray.tmax = t;
            hit.t = t;
            hit.prim_id = id;
            hit.u = u;
            hit.v = v;
          }
        } else {
          hit_here = m_geometry.intersect(id, tri_ray, ray, hit);
        }
        if (hit_here) {
          found = true;
          if constexpr (kAnyHit) {
            if constexpr (kCount) ++stats->hits;
            return true;
          }
        }
      }
    } else {
      const std::uint32_t left = node.first;
      float t_left = 0.f, t_right = 0.f;
      if constexpr (kCount) stats->nodes_visited += 2;
      const bool hit_left = hit_node(nodes[left], box_ray, ray.tmin, ray.tmax, t_left);
      const bool hit_right = hit_node(nodes[left + 1], box_ray, ray.tmin, ray.tmax, t_right);
      if (hit_left && hit_right) {
        // Visit the nearer child first; the farther one waits with its entry distance, so it
        // can be skipped if a closer hit is found meanwhile.
        if (t_right < t_left) {
          stack[sp++] = {left, t_left};
          current = left + 1;
        } else {
          stack[sp++] = {left + 1, t_right};
          current = left;
        }
        continue;
      }
      if (hit_left) {
        current = left;
        continue;
      }
      if (hit_right) {
        current = left + 1;
        continue;
      }
    }
    // Pop the next subtree that can still hold a closer hit.
    for (;;) {
      if (sp == 0) {
        if constexpr (kCount) stats->hits += found ? 1 : 0;
        return found;
      }
      const StackEntry e = stack[--sp];
      if (kAnyHit || e.t_enter <= ray.tmax) {
        current = e.node;
        break;
      }
    }
  }
}

template <bool kCount>
bool Bvh::intersect_impl(Ray& ray, Hit& hit, TraversalStats* stats) const {
  return traverse<false, kCount>(ray, hit, stats);
}

template <bool kCount>
bool Bvh::occluded_impl(const Ray& ray, TraversalStats* stats) const {
  Ray probe = ray;
  Hit scratch;
  return traverse<true, kCount>(probe, scratch, stats);
}

bool Bvh::intersect(Ray& ray, Hit& hit) const { return intersect_impl<false>(ray, hit, nullptr); }
bool Bvh::occluded(const Ray& ray) const { return occluded_impl<false>(ray, nullptr); }
bool Bvh::intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const {
  return intersect_impl<true>(ray, hit, &stats);
}
bool Bvh::occluded_counted(const Ray& ray, TraversalStats& stats) const { return occluded_impl<true>(ray, &stats); }

AccelInfo Bvh::info() const {
  AccelInfo info;
  info.name = "bvh";
  info.build_seconds = m_build_seconds;
  info.memory_bytes = m_tree.nodes.size() * sizeof(BvhNode) + m_tree.prim_ids.size() * sizeof(std::uint32_t) +
                      m_leaf_triangles.size() * sizeof(Triangle);
  info.node_count = m_tree.nodes.size();
  info.leaf_count = m_tree.leaf_count;
  info.primitive_count = m_tree.prim_ids.size();
  info.max_depth = m_tree.max_depth;
  return info;
}

}  // namespace raylab
