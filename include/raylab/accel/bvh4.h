#pragma once
/// \file
/// The 4-wide BVH: the binary SAH tree collapsed so each node holds four children, whose boxes
/// one SIMD operation per plane tests together. Fewer, wider steps per ray than the binary tree.

#include <cstdint>
#include <span>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/bvh.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// One 4-wide node, 128 bytes (two cache lines), boxes as structure of arrays:
///   bytes   0-47   lo_x[4], lo_y[4], lo_z[4]
///   bytes  48-95   hi_x[4], hi_y[4], hi_z[4]
///   bytes  96-111  child[4]: an interior child's node index, or a leaf's first primitive reference
///   bytes 112-127  count[4]: a leaf's primitive count; 0 for an interior child or an empty slot
/// An empty slot has an empty box (lo = +inf, hi = -inf), which no ray enters.
struct alignas(64) Bvh4Node {
  float lo[3][4];
  float hi[3][4];
  std::uint32_t child[4];
  std::uint32_t count[4];
};
static_assert(sizeof(Bvh4Node) == 128, "Bvh4Node must stay 128 bytes");

/// Collapses a binary tree into 4-wide nodes: each wide node takes a binary interior node's two
/// children and keeps opening the child of largest surface area until it has four. Leaves and
/// primitive references are kept as they are. The root of the result is at index 0.
std::vector<Bvh4Node> collapse_to_bvh4(const BvhTree& tree);

/// The default BVH accelerator ("bvh"): binned SAH build (build_bvh), collapsed to 4-wide nodes,
/// traversal specialised on the ray's direction octant, children visited nearest first, `occluded`
/// stops at the first hit. The binary nodes are freed after the collapse.
class Bvh4 final : public Accelerator {
 public:
  /// Builds the tree; keeps a reference to `geometry`, which must outlive this object.
  explicit Bvh4(const Geometry& geometry, const BvhConfig& config = {});
  /// Builds the tree over the primitives (or groups) `ids` of `geometry` only.
  Bvh4(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config = {});

  Box3 bounds() const override { return m_bounds; }
  bool intersect(Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override;
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const override;
  bool occluded_counted(const Ray& ray, TraversalStats& stats) const override;
  using Accelerator::intersect;
  using Accelerator::occluded;
  AccelInfo info() const override;

  /// The wide nodes, for tests and tools.
  const std::vector<Bvh4Node>& nodes() const { return m_nodes; }

 private:
  template <bool kAnyHit, bool kCount>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
  template <bool kAnyHit, bool kCount, int kOctant>
  bool traverse_octant(Ray& ray, Hit& hit, TraversalStats* stats) const;

  const Geometry& m_geometry;
  std::vector<Bvh4Node> m_nodes;
  std::vector<std::uint32_t> m_prim_ids;   ///< primitive references, leaf by leaf
  std::vector<Triangle> m_leaf_triangles;  ///< parallel to m_prim_ids; unused slots for non-triangles
  std::uint32_t m_triangle_count = 0;      ///< prim ids below this are triangles
  Box3 m_bounds;
  int m_max_depth = 0;
  std::size_t m_leaf_count = 0;
  double m_build_seconds = 0.0;
};

}  // namespace raylab
