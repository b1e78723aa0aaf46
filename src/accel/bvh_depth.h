#pragma once
// The depth bound that the BVH builder guarantees and the traversal stacks rely on (internal to
// src/accel): one constant, so that neither can change without the other.

namespace raylab::bvh_depth {

/// Beyond this depth the builder splits at the object median, which halves the reference count
/// each level: a bound on depth that holds on pathological inputs (sizes spread over many orders
/// of magnitude) where the SAH would peel one primitive off per level.
inline constexpr int kMedianFallbackDepth = 64;

/// No binary BVH node is deeper than this: the median levels halve a 32-bit reference count.
inline constexpr int kMaxDepth = kMedianFallbackDepth + 32;

/// Entries a binary traversal stack needs: at most one far child pushed per level, plus the root.
inline constexpr int kBinaryStackSize = kMaxDepth + 1;

/// Entries a W-wide traversal stack needs: each step pushes at most W - 1 children, and a wide
/// node spans at least one binary level, so a walk is at most kMaxDepth steps deep.
template <int W>
inline constexpr int kWideStackSize = kMaxDepth*(W - 1) + 1;

}  // namespace raylab::bvh_depth
