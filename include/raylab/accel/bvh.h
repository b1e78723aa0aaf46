#pragma once
/// \file
/// Binary bounding volume hierarchy: flattened 32-byte nodes, SAH-built, distance-ordered traversal.

#include <cstddef>
#include <cstdint>
#include <new>
#include <span>
#include <vector>

#include "raylab/accel/cylinder_frames.h"
#include "raylab/accel/traversal_accelerator.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// Build parameters of the BVH, with the defaults used by `--accel bvh`.
struct BvhConfig {
  int bin_count = 16;              ///< SAH bins per axis (binned build, Wald 2007)
  int max_leaf_size = 8;           ///< a node with more primitives is always split if it can be
  float traversal_cost = 1.0f;     ///< SAH cost of visiting a node, relative to one primitive test
  float intersection_cost = 1.0f;  ///< SAH cost of one primitive test
  int parallel_threshold = 4096;   ///< subtrees with at least this many primitives build in parallel
  /// A leaf pays `intersection_cost` per started block of this many primitives (wide BVHs test
  /// leaf triangles 4 or 8 at a time), in the build and in `sah_cost` alike.
  int leaf_block_size = 1;
  /// Spatial splits (Stich et al. 2009, SBVH): triangles may be clipped into several leaves,
  /// so `prim_ids` may list a primitive more than once. Other shapes are only ever object-split.
  bool spatial_splits = false;
  /// A spatial split is tried only where the children of the best object split overlap by more
  /// than this fraction of the root's surface area.
  float spatial_split_alpha = 1e-5f;
  /// Spatial splits may add at most this fraction of the primitive count as extra references.
  float spatial_split_budget = 0.3f;
};

/// One node, 32 bytes so two siblings share a 64-byte cache line:
///   bytes  0-11  box minimum (3 x float)
///   bytes 12-15  interior: index of the left child (the right child follows it);
///                leaf: index of the first primitive reference
///   bytes 16-27  box maximum (3 x float)
///   bytes 28-31  number of primitives; 0 marks an interior node
struct BvhNode {
  float lo[3];
  std::uint32_t first;
  float hi[3];
  std::uint32_t count;

  /// True for a leaf.
  bool is_leaf() const { return count != 0; }
};
static_assert(sizeof(BvhNode) == 32, "BvhNode must stay 32 bytes");

/// The tree as plain data, produced by `build_bvh` and walked by the `Bvh` accelerator.
struct BvhTree {
  std::vector<BvhNode> nodes;           ///< root at index 0
  std::vector<std::uint32_t> prim_ids;  ///< primitive references, leaf by leaf
  int max_depth = 0;                    ///< depth of the deepest leaf (root = 0)
  std::size_t leaf_count = 0;           ///< number of leaves
};

/// Builds a BVH over every primitive of `geometry` with the binned SAH, in parallel on oneTBB.
BvhTree build_bvh(const Geometry& geometry, const BvhConfig& config = {});

/// Builds a BVH over the primitives (or groups) `ids` of `geometry` only.
BvhTree build_bvh(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config = {});

/// SAH cost of a tree (traversal cost per interior node and intersection cost per primitive,
/// charged per started block of `leaf_block_size` in a leaf, weighted by surface area relative to
/// the root): used to compare builds.
double sah_cost(const BvhTree& tree, const BvhConfig& config = {});

/// Per-ray constants of the box test (origin, reciprocal direction); defined in bvh.cpp.
struct BvhBoxRay;

/// The BVH accelerator. Triangles referenced by leaves are copied in leaf order, so a leaf's
/// triangles are contiguous in memory; other shapes are tested through the Geometry.
class Bvh final : public TraversalAccelerator<Bvh> {
 public:
  /// Builds the tree; keeps a reference to `geometry`, which must outlive this object.
  explicit Bvh(const Geometry& geometry, const BvhConfig& config = {});
  /// Builds the tree over the primitives (or groups) `ids` of `geometry` only.
  Bvh(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config = {});

  Box3 bounds() const override;
  AccelInfo info() const override;

  /// The tree, for tests and tools.
  const BvhTree& tree() const { return m_tree; }

 private:
  friend class TraversalAccelerator<Bvh>;
  // The kernel of every query (TraversalAccelerator): dispatches on the direction's octant.
  template <bool kAnyHit, bool kCount, class K>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
  template <bool kAnyHit, bool kCount, int kOctant, class K>
  bool traverse_octant(Ray& ray, const BvhBoxRay& box_ray, Hit& hit, TraversalStats* stats) const;

  const Geometry& m_geometry;
  BvhTree m_tree;
  std::vector<Triangle> m_leaf_triangles;  ///< parallel to prim_ids; unused slots for non-triangles
  CylinderFrames m_cylinder_frames;        ///< the frames of the cylinders among the primitives
  std::uint32_t m_triangle_count = 0;      ///< prim ids below this are triangles
  double m_build_seconds = 0.0;
};

extern template class TraversalAccelerator<Bvh>;

}  // namespace raylab
