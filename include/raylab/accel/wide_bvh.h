#pragma once
/// \file
/// The wide BVH ("bvh"): the binned SAH tree collapsed to W-wide nodes (W = 4, 8 or 16) whose
/// children's boxes one SIMD instruction per plane tests together, with leaves of triangles stored
/// four to a block and tested with SIMD. Single-ray traversal is ordered by the ray's octant and
/// by distance; packets of rays share the walk (wide_bvh_packet.cpp).

#include <cstdint>
#include <span>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/bvh.h"
#include "raylab/geometry/geometry.h"
#include "raylab/geometry/triangle_block.h"
#include "raylab/simd/wide_float.h"

namespace raylab {

/// One W-wide node, boxes as structure of arrays (W = 8: 256 bytes, four cache lines):
///   lo[axis][slot], hi[axis][slot]  the children's boxes
///   child[slot]   an interior child's node index, or a leaf's first TriangleBlock4
///   count[slot]   0 for an interior child or an empty slot; for a leaf, its number of blocks,
///                 with kLeafHasOthers set when some lanes hold non-triangle primitives
/// An empty slot has an empty box (lo = +inf, hi = -inf), which no ray enters.
template <int W>
struct alignas(64) WideBvhNode {
  /// Flag in `count`: the leaf holds primitives other than triangles (tested one by one).
  static constexpr std::uint32_t kLeafHasOthers = 0x80000000u;

  float lo[3][W];
  float hi[3][W];
  std::uint32_t child[W];
  std::uint32_t count[W];
};

/// The leaves' content of a wide BVH: blocks of four triangles (or other primitives, whose lanes
/// hold no vertices), leaf after leaf.
struct WideBvhLeaves {
  std::vector<TriangleBlock4> blocks;
  std::uint32_t triangle_count = 0;  ///< primitive ids below this are triangles

  /// Whether no leaf holds anything (no ray can hit).
  bool empty() const { return blocks.empty(); }
};

/// A wide tree as plain data.
template <int W>
struct WideBvhTree {
  std::vector<WideBvhNode<W>> nodes;  ///< root at index 0
  WideBvhLeaves leaves;
  std::size_t leaf_count = 0;
  int max_depth = 0;
};

/// Collapses a binary tree into W-wide nodes: each wide node takes a binary interior node's two
/// children and keeps opening the child of largest surface area until it has W. Each binary
/// leaf becomes a wide leaf whose primitives are packed four to a block, in leaf order.
template <int W>
WideBvhTree<W> collapse_to_wide(const BvhTree& tree, const Geometry& geometry);

/// The wide BVH accelerator. `intersect(span)` / `occluded(span)` trace groups of rays as
/// packets (up to 16 rays share the walk, with interval culling, falling back to single rays when
/// few remain); results equal the single-ray results bit for bit.
template <int W>
class WideBvh final : public Accelerator {
 public:
  /// Builds the tree; keeps a reference to `geometry`, which must outlive this object.
  explicit WideBvh(const Geometry& geometry, const BvhConfig& config = {});
  /// Builds the tree over the primitives (or groups) `ids` of `geometry` only.
  WideBvh(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config = {});

  Box3 bounds() const override { return m_bounds; }
  bool intersect(Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override;
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const override;
  bool occluded_counted(const Ray& ray, TraversalStats& stats) const override;
  void intersect(std::span<Ray> rays, std::span<Hit> hits) const override;
  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> occluded) const override;
  AccelInfo info() const override;

  /// The tree, for tests and tools.
  const WideBvhTree<W>& tree() const { return m_tree; }

  /// The configuration the binary tree is built with: `config` with leaves priced per block of
  /// four primitives (at least), the leaf format's unit of work.
  static BvhConfig build_config(const BvhConfig& config);

 private:
  template <bool kAnyHit, bool kCount>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
  template <bool kAnyHit, bool kCount, int kOctant>
  bool traverse_octant(Ray& ray, Hit& hit, TraversalStats* stats) const;
  template <bool kAnyHit>
  void trace_packet(Ray* rays, Hit* hits, std::uint8_t* occluded, int n) const;
  template <bool kAnyHit, int kOctant>
  void trace_packet_octant(Ray* rays, Hit* hits, std::uint8_t* occluded, int n) const;

  const Geometry& m_geometry;
  WideBvhTree<W> m_tree;
  Box3 m_bounds;
  double m_build_seconds = 0.0;
};

extern template class WideBvh<4>;
extern template class WideBvh<8>;
extern template class WideBvh<16>;

}  // namespace raylab
