// Every hit along a ray through the wide BVH: the walk of `all_hits`, kept apart from the
// closest-hit and any-hit kernels (wide_bvh_walk.h), which it must not slow down.

#include <bit>

#include "bvh_depth.h"
#include "hit_list.h"
#include "raylab/accel/wide_bvh.h"
#include "wide_bvh_leaf.h"

namespace raylab {

namespace {

// Appends the hits in [ray.tmin, ray.tmax) of the leaf whose node slot holds `first` and
// `count_flags`: the triangles of its blocks, then its other primitives through the Geometry.
template <int W>
void collect_leaf_hits(const WideBvhLeaves& leaves, const Geometry& geometry, std::uint32_t first,
                       std::uint32_t count_flags, const WatertightRay& tri_ray, const Ray& ray,
                       std::vector<Hit>& hits) {
  for (std::uint32_t b = first; b < first + leaf_block_count<W>(count_flags); ++b) {
    const TriangleBlock4& block = leaves.blocks[b];
    alignas(16) float t[4], u[4], v[4];
    int mask = intersect_triangle_block(block, tri_ray, ray.tmin, ray.tmax, t, u, v);
    while (mask != 0) {
      const int i = std::countr_zero(static_cast<unsigned>(mask));
      mask &= mask - 1;
      // Unused lanes and lanes of other kinds carry no real triangle; the block test accepts
      // t == tmax, the range does not.
      if (block.id[i] >= leaves.triangle_count || !(t[i] < ray.tmax)) continue;
      hits.push_back({t[i], block.id[i], u[i], v[i]});
    }
  }
  if (!leaf_has_others<W>(count_flags)) return;
  for (const std::uint32_t id : leaves.others_of(first, count_flags)) {
    Ray probe = ray;
    Hit hit;
    if (geometry.intersect(id, tri_ray, probe, hit)) hits.push_back(hit);
  }
}

}  // namespace

template <int W>
void WideBvh<W>::all_hits(const Ray& ray, std::vector<Hit>& hits) const {
  if (m_tree.leaves.empty() || !traceable_direction(ray.direction)) return;  // nothing, or no ray
  const std::size_t first = hits.size();
  const WideBoxRay<W> box_ray(ray);
  const WatertightRay tri_ray(ray);
  WideStackEntry stack[bvh_depth::kWideStackSize<W>];
  int size = 0;
  stack[size++] = {0, 0, ray.tmin};
  while (size > 0) {
    const WideStackEntry current = stack[--size];
    if (current.count != 0) {
      collect_leaf_hits<W>(m_tree.leaves, m_geometry, current.child, current.count, tri_ray, ray, hits);
      continue;
    }
    const WideBvhNode<W>& node = m_tree.nodes[current.child];
    alignas(64) float t_enter[W];
    // The range never shrinks: every box the ray meets within it is opened.
    for (unsigned mask = box_ray.test(node, ray.tmin, ray.tmax, t_enter); mask != 0; mask &= mask - 1) {
      const int i = std::countr_zero(mask);
      stack[size++] = {node.child[i], node.count[i], t_enter[i]};
    }
  }
  order_all_hits(hits, first);
}

template void WideBvh<4>::all_hits(const Ray&, std::vector<Hit>&) const;
template void WideBvh<8>::all_hits(const Ray&, std::vector<Hit>&) const;
template void WideBvh<16>::all_hits(const Ray&, std::vector<Hit>&) const;

}  // namespace raylab
