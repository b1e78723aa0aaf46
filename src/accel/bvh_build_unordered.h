#pragma once
/// \file
/// Internal to src/accel: the binary tree exactly as the builder leaves it, before `build_bvh`
/// lays it out depth first. The wide BVH collapses it directly: the collapse gives the wide tree
/// its own depth-first order anyway, so the binary relayout would be a sequential pass for
/// nothing (a tenth of the two-thread build of a 2M-triangle mesh).

#include <cstdint>
#include <memory>
#include <span>

#include "bvh_build_ref.h"
#include "raylab/accel/bvh.h"
#include "raylab/core/uninitialized_vector.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// The builder's output. Node slots [0, node_count) are all used, in the order the build tasks
/// took them: root at 0, the two children of an interior node side by side at `first` and
/// `first + 1`. A leaf's references are refs[first, first + count), in leaf order.
struct UnorderedBvh {
  UninitializedVector<BvhNode> nodes;  ///< slots for two nodes per reference; [0, node_count) used
  std::uint32_t node_count = 0;
  UninitializedVector<bvh_build::BuildRef> refs;  ///< room for every reference, spatial splits' too
};

/// Builds the tree over the primitives `ids` (at least one) of `geometry`; `build_bvh` is this
/// followed by the depth-first relayout, so both describe the same tree.
UnorderedBvh build_bvh_unordered(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config);

}  // namespace raylab
