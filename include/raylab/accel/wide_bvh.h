#pragma once
/// \file
/// The wide BVH ("bvh"): the binned SAH tree collapsed to W-wide nodes (W = 4, 8 or 16) whose
/// children's boxes one SIMD instruction per plane tests together, with leaves of triangles stored
/// four to a block and tested with SIMD, other primitives listed by id. Single-ray traversal visits
/// children nearest first; packets of rays share the walk (wide_bvh_packet.cpp).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/bvh.h"
#include "raylab/accel/cylinder_frames.h"
#include "raylab/core/uninitialized_vector.h"
#include "raylab/geometry/cylinder.h"
#include "raylab/geometry/cylinder_lanes.h"
#include "raylab/geometry/geometry.h"
#include "raylab/geometry/sphere_lanes.h"
#include "raylab/geometry/triangle_block.h"
#include "raylab/simd/wide_float.h"

namespace raylab {

/// The leaves' content of a wide BVH. A leaf's triangles are packed four to a TriangleBlock4 in
/// `blocks`; its other primitives (spheres, cylinders, disks, quads, groups) are listed by id in
/// `others`, 4 bytes each, instead of taking a 40-byte lane of a block each. Spheres are also
/// copied beside their ids as structure of arrays and tested four at a time; cylinders have
/// precomputed frames; the other kinds are tested one by one through the Geometry.
///
/// A leaf's node slot (`child`, `count`) says where its content is, in one of three forms:
///   triangles only   child = its first block, count = its number of blocks (kHasOthers clear):
///                    the triangle path needs nothing more, as if there were no other kinds;
///   others only      child = where its ids start in `others`,
///                    count = kHasOthers | number of ids << kBlockBits (no blocks);
///   both             child = its first block,
///                    count = kHasOthers | start << kBlockBits | number of blocks (1 to
///                    kMaxMixedBlocks), where others[start] is the number of ids, which follow it.
/// A leaf with both kinds is rare (triangles and spheres side by side), so it alone pays the
/// 4-byte header; it keeps at most kMaxMixedBlocks blocks and lists any further triangles with
/// its others. The headers of all such leaves come first in `others`, so that their starts stay
/// small whatever the number of leaves holding only others.
struct WideBvhLeaves {
  /// Flag in a leaf's `count`: the leaf holds primitives other than triangles.
  static constexpr std::uint32_t kHasOthers = 0x80000000u;
  /// Bits of `count` holding the number of blocks of a leaf that also holds others.
  static constexpr int kBlockBits = 4;
  /// The most blocks a leaf holding others keeps.
  static constexpr std::uint32_t kMaxMixedBlocks = (1u << kBlockBits) - 1;
  /// The largest value of the field above the block bits (a start or a number of ids).
  static constexpr std::uint32_t kMaxOthersField = (kHasOthers >> kBlockBits) - 1;

  UninitializedVector<TriangleBlock4> blocks;  ///< triangles, leaf after leaf
  std::vector<std::uint32_t> others;           ///< ids of the other kinds (and headers), see above
  std::uint32_t triangle_count = 0;            ///< primitive ids below this are triangles
  /// The frames of the cylinders the tree holds: what their test needs, computed at build.
  CylinderFrames cylinder_frames;

  /// The fewest spheres a leaf must hold for the traversal to test them as lanes of four; it
  /// tests fewer one by one. Callgrind, SPD protocol, 1 thread, against the one-by-one test:
  /// lanes from 1 or 2 spheres cost rings and tree 3-7% more instructions (most of their leaves
  /// hold one sphere); from 3, balls (a third of its leaves hold 4) saves 5%.
  static constexpr std::size_t kSphereLanesFrom = 3;

  /// The spheres among `others`, position by position, as structure of arrays: at position i
  /// the centre and radius of the sphere whose id others[i] is, radius 0 at every other position
  /// (other kinds, headers) and at 3 positions of padding after the end, so that four lanes load
  /// from any position of a leaf's list. Empty when the scene has no sphere or no leaf lists ids.
  std::vector<float> sphere_x, sphere_y, sphere_z, sphere_radius;

  /// The four lanes of spheres from position `at` of `others`.
  SphereLanes sphere_lanes_at(std::size_t at) const {
    return {sphere_x.data() + at, sphere_y.data() + at, sphere_z.data() + at, sphere_radius.data() + at};
  }

  /// The fewest cylinders a leaf must hold for the traversal to turn them away as lanes of four;
  /// it tests fewer one by one. Callgrind, SPD protocol, 1 thread, instructions against the
  /// one-by-one test: lanes from 1 cylinder rings 0.948, tree 1.017; from 2, rings 0.928, tree
  /// 0.995; from 3, rings 0.962, tree 0.999 (most leaves of tree hold one cylinder).
  static constexpr std::size_t kCylinderLanesFrom = 2;

  /// The cylinders among `others`, position by position: what the float rejection needs
  /// (CylinderLaneArrays), so that a leaf's cylinders, listed after its spheres, are turned away
  /// four at a time. Empty when the scene has no cylinder or no leaf lists ids.
  CylinderLaneArrays cylinder_lanes;

  /// How many spheres and cylinders head a leaf's list of ids, stored at the position where the
  /// list starts (other positions unused), each up to kKindCountSaturated: one load instead of
  /// reading the ids to count them, a loop whose exit mispredicted once per leaf (callgrind's
  /// branch simulation put 9% of rings' mispredictions there). Empty when no leaf lists ids.
  struct LeafKinds {
    std::uint8_t spheres = 0;    ///< spheres first
    std::uint8_t cylinders = 0;  ///< then cylinders
  };
  /// A count that reached this value may be larger: the traversal counts on from the ids.
  static constexpr std::uint8_t kKindCountSaturated = 255;
  std::vector<LeafKinds> leaf_kinds;

  /// The frame of primitive `id` when it is a cylinder with one, else null.
  const CylinderFrame* cylinder_frame_of(std::uint32_t id) const { return cylinder_frames.find(id); }

  /// Whether no leaf holds anything (no ray can hit).
  bool empty() const { return blocks.empty() && others.empty(); }

  /// The number of blocks of a leaf whose slot's count is `count`.
  static std::uint32_t block_count(std::uint32_t count) {
    return (count & kHasOthers) != 0 ? count & kMaxMixedBlocks : count;
  }

  /// The ids of the other primitives of a leaf whose slot holds `child` and `count` (none when
  /// the leaf holds triangles only).
  std::span<const std::uint32_t> others_of(std::uint32_t child, std::uint32_t count) const {
    if ((count & kHasOthers) == 0) return {};
    const std::uint32_t field = (count & ~kHasOthers) >> kBlockBits;
    if ((count & kMaxMixedBlocks) == 0) return {others.data() + child, field};
    return {others.data() + field + 1, others[field]};
  }
};

/// One W-wide node, boxes as structure of arrays (W = 8: 256 bytes, four cache lines):
///   lo[axis][slot], hi[axis][slot]  the children's boxes
///   child[slot]   an interior child's node index, or where a leaf's content starts
///   count[slot]   0 for an interior child or an empty slot; for a leaf never 0: its number of
///                 blocks, with kLeafHasOthers set when it holds non-triangle primitives (the
///                 encoding is WideBvhLeaves')
/// An empty slot has an empty box (lo = +inf, hi = -inf), which no ray enters.
template <int W>
struct alignas(64) WideBvhNode {
  /// Flag in `count`: the leaf holds primitives other than triangles (tested one by one).
  static constexpr std::uint32_t kLeafHasOthers = WideBvhLeaves::kHasOthers;

  float lo[3][W];
  float hi[3][W];
  std::uint32_t child[W];
  std::uint32_t count[W];
};

/// A wide tree as plain data.
template <int W>
struct WideBvhTree {
  UninitializedVector<WideBvhNode<W>> nodes;  ///< root at index 0
  WideBvhLeaves leaves;
  std::size_t leaf_count = 0;
  int max_depth = 0;
};

/// Collapses a binary tree into W-wide nodes: each wide node takes a binary interior node's two
/// children and keeps opening the child of largest surface area until it has W. Each binary
/// leaf becomes a wide leaf whose triangles are packed four to a block and whose other
/// primitives are listed by id, the spheres first, then the cylinders (each part in leaf order);
/// the frames of the cylinder ids the tree holds are computed first, and the cylinders' lanes
/// copied from them. Throws
/// std::length_error should a leaf's encoding overflow (more than 2^27 ids listed by the leaves
/// holding both kinds).
template <int W>
WideBvhTree<W> collapse_to_wide(const BvhTree& tree, const Geometry& geometry);

/// The wide BVH accelerator. `intersect(span)` / `occluded(span)` trace groups of rays as
/// packets (up to 16 rays share the walk, with interval culling, falling back to single rays when
/// few remain); results equal the single-ray results bit for bit.
template <int W>
class WideBvh final : public TraversalAccelerator<WideBvh<W>> {
 public:
  /// Builds the tree; keeps a reference to `geometry`, which must outlive this object.
  explicit WideBvh(const Geometry& geometry, const BvhConfig& config = {});
  /// Builds the tree over the primitives (or groups) `ids` of `geometry` only.
  WideBvh(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config = {});

  Box3 bounds() const override { return m_bounds; }
  using TraversalAccelerator<WideBvh<W>>::intersect;
  using TraversalAccelerator<WideBvh<W>>::occluded;
  void intersect(std::span<Ray> rays, std::span<Hit> hits) const override;
  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> occluded) const override;
  /// Exact: walks every box the ray enters within its range and keeps every hit.
  void all_hits(const Ray& ray, std::vector<Hit>& hits) const override;
  AccelInfo info() const override;

  /// The tree, for tests and tools.
  const WideBvhTree<W>& tree() const { return m_tree; }

  /// The configuration the binary tree is built with: `config` with leaves priced per block of
  /// four primitives (at least), the leaf format's unit of work.
  static BvhConfig build_config(const BvhConfig& config);

 private:
  friend class TraversalAccelerator<WideBvh<W>>;
  // The kernel of every single-ray query (TraversalAccelerator).
  template <bool kAnyHit, bool kCount, class K>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
  template <bool kAnyHit, class K>
  void trace_packet(Ray* rays, Hit* hits, std::uint8_t* occluded, int n) const;
  template <bool kAnyHit, int kOctant, class K>
  void trace_packet_octant(Ray* rays, Hit* hits, std::uint8_t* occluded, int n) const;

  const Geometry& m_geometry;
  WideBvhTree<W> m_tree;
  Box3 m_bounds;
  double m_build_seconds = 0.0;
};

extern template class TraversalAccelerator<WideBvh<4>>;
extern template class TraversalAccelerator<WideBvh<8>>;
extern template class TraversalAccelerator<WideBvh<16>>;
extern template class WideBvh<4>;
extern template class WideBvh<8>;
extern template class WideBvh<16>;

}  // namespace raylab
