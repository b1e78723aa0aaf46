// The wide BVH accelerator: build, and the single-ray traversal ordered by distance.

#include "raylab/accel/wide_bvh.h"
#include "raylab/core/stopwatch.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>

#include "traversal_entry_points.h"
#include "wide_bvh_collapse.h"
#include "wide_bvh_walk.h"

namespace raylab {
#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
template <int W>
WideBvh<W>::WideBvh(const Geometry& geometry, const BvhConfig& config)
    : WideBvh(geometry, geometry.primitive_ids(), config) {}

template <int W>
WideBvh<W>::WideBvh(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config)
    : m_geometry(geometry) {
  const auto start = std::chrono::steady_clock::now();
  if (ids.empty()) {
    m_tree = collapse_to_wide<W>(build_bvh(geometry, ids, build_config(config)), geometry);
  } else {
    // The builder's tree as it comes, without build_bvh's depth-first relayout: the collapse
    // lays the wide tree out itself.
    const UnorderedBvh tree = build_bvh_unordered(geometry, ids, build_config(config));
    m_tree = collapse_to_wide<W>(tree, geometry, ids);
    const BvhNode& root = tree.nodes[0];
    m_bounds = {{root.lo[0], root.lo[1], root.lo[2]}, {root.hi[0], root.hi[1], root.hi[2]}};
  }
  m_build_seconds = seconds_since(start);
}

template <int W>
BvhConfig WideBvh<W>::build_config(const BvhConfig& config) {
  // Leaves are blocks of four triangles tested at once, so the tree is priced that way: a leaf
  // of one to four primitives costs one block test.
  BvhConfig block_config = config;
  block_config.leaf_block_size = std::max(config.leaf_block_size, 4);
  return block_config;
}

#endif  // RAYLAB_KERNEL_VARIANT

template <int W>
template <bool kAnyHit, bool kCount, class K>
bool WideBvh<W>::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  if (m_tree.leaves.empty()) return false;
  const WideBoxRay<W> box_ray(ray);
  const WatertightRay tri_ray(ray);
  float tmax = ray.tmax;
  Hit best = hit;
  TraversalCounters counters;
  const bool found = walk_wide_bvh<kAnyHit, kCount, W>(m_tree, m_geometry, WideStackEntry{0, 0, ray.tmin}, box_ray,
                                                       tri_ray, ray, tmax, best, counters);
  return finish_traversal<kCount>(found, tmax, best, counters, ray, hit, stats);
}

#ifndef RAYLAB_KERNEL_VARIANT  // once, with the library's own flags (kernel_dispatch.h)
template <int W>
AccelInfo WideBvh<W>::info() const {
  AccelInfo info;
  info.name = W == native_box_width(this->kernel_isa()) ? "bvh" : "bvh" + std::to_string(W);
  info.build_seconds = m_build_seconds;
  const WideBvhLeaves& leaves = m_tree.leaves;
  info.memory_bytes =
      m_tree.nodes.size() * sizeof(WideBvhNode<W>) + leaves.blocks.size() * sizeof(TriangleBlock4) +
      leaves.others.size() * sizeof(std::uint32_t) + leaves.cylinder_frames.bytes() +
      (leaves.sphere_x.size() + leaves.sphere_y.size() + leaves.sphere_z.size() + leaves.sphere_radius.size()) *
          sizeof(float) +
      leaves.cylinder_lanes.bytes() + leaves.leaf_kinds.size() * sizeof(WideBvhLeaves::LeafKinds);
  info.node_count = m_tree.nodes.size();
  info.leaf_count = m_tree.leaf_count;
  // References: the used lanes of the blocks and the ids listed by the leaves (not the headers).
  std::size_t references = 0;
  for (const TriangleBlock4& b : leaves.blocks) {
    for (std::uint32_t id : b.id) references += id != TriangleBlock4::kNoPrimitive ? 1 : 0;
  }
  for (const WideBvhNode<W>& node : m_tree.nodes) {
    for (int i = 0; i < W; ++i) references += leaves.others_of(node.child[i], node.count[i]).size();
  }
  info.primitive_count = references;
  info.max_depth = m_tree.max_depth;
  return info;
}

// The single-ray entry points, which call the kernel of the structure's instruction set.
RAYLAB_INSTANTIATE_ENTRY_POINTS(WideBvh<4>);
RAYLAB_INSTANTIATE_ENTRY_POINTS(WideBvh<8>);
RAYLAB_INSTANTIATE_ENTRY_POINTS(WideBvh<16>);
template class WideBvh<4>;
template class WideBvh<8>;
template class WideBvh<16>;

#endif  // RAYLAB_KERNEL_VARIANT

// The single-ray kernel, compiled here for this translation unit's instruction set.
RAYLAB_INSTANTIATE_TRAVERSE(WideBvh<4>);
RAYLAB_INSTANTIATE_TRAVERSE(WideBvh<8>);
RAYLAB_INSTANTIATE_TRAVERSE(WideBvh<16>);

}  // namespace raylab
