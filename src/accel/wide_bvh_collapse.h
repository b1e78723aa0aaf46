#pragma once
/// \file
/// Internal to src/accel: collapsing the builder's unordered binary tree straight into a wide
/// tree (the public `collapse_to_wide` takes `build_bvh`'s laid-out tree; both give the same
/// wide tree for the same build).

#include <cstdint>
#include <span>

#include "bvh_build_unordered.h"
#include "raylab/accel/wide_bvh.h"

namespace raylab {

/// As collapse_to_wide(build_bvh(...), geometry) for the build that produced `tree` over the
/// primitives `ids` (which give the range of cylinder ids whose frames the leaves keep).
template <int W>
WideBvhTree<W> collapse_to_wide(const UnorderedBvh& tree, const Geometry& geometry, std::span<const std::uint32_t> ids);

}  // namespace raylab
