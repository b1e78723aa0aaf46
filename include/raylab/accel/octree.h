#pragma once
/// \file
/// Octree over a cubic root cell, walked in ray order with the parametric top-down traversal of
/// Revelles, Urena & Lastra (2000). The builder (octree_build.cpp) is separate from the
/// traversal (octree.cpp).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "raylab/accel/traversal_accelerator.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// Build parameters of the octree, with the defaults used by `--accel octree`. K = 8: a mesh
/// vertex is shared by about six triangles, and with K below that the cells around every vertex
/// are split down to depth L (the Stanford bunny on a ground quad: 1.24 M nodes and 16 MB at
/// K = 4, 0.17 M nodes and 3.4 MB at K = 8, at the same speed; K = 16 tests twice as many
/// primitives per ray). L = 20: deep enough for a small dense object in a large scene (the teapot
/// in a stadium, 1/1000 of the scene, tests 4.4 primitives per ray at L = 20, 8.0 at L = 16),
/// while elsewhere the split rule stops first (spd:balls ends at depth 10). Measurements:
/// docs/accelerators.md.
struct OctreeConfig {
  int max_items = 8;    ///< K: a cell holding more primitives is subdivided (`--octree-max-items`)
  int max_depth = 20;   ///< L: cells at this depth are never subdivided; clamped to [0, 24] (`--octree-max-depth`)
  bool mailbox = true;  ///< test a primitive spanning several cells once per ray
};

/// Deepest level the octree can reach: cell corners are points of a lattice with 2^24 steps per
/// axis across the root cell, so cells at depth 24 are one step wide.
inline constexpr int kOctreeDepthLimit = 24;

/// Lattice steps per axis across the root cell.
inline constexpr std::uint32_t kOctreeLatticeSteps = 1u << kOctreeDepthLimit;

/// A split is kept only when the children together hold fewer than this many times the parent's
/// references. A child cube has a quarter of its parent's surface area, so a ray through the
/// parent enters a given child with probability about 1/4, and the split is expected to leave a
/// ray (children's references) / 4 tests instead of the parent's n: with fewer than 3n references
/// in all, at most 3/4 of them, a saving that pays for the extra cells the ray visits. Without
/// the rule, primitives that cannot be separated (coincident planes, many triangles through one
/// point, cells smaller than the triangles in them) would be split down to depth L.
inline constexpr int kOctreeSplitGainRatio = 3;

/// One node, 8 bytes. The eight children of an interior node are stored consecutively, child
/// `c` at `first + c`, where bit 0 of `c` selects the upper half in x, bit 1 in y, bit 2 in z.
struct OctreeNode {
  /// `count` of an interior node.
  static constexpr std::uint32_t kInterior = 0xffffffffu;
  std::uint32_t first;  ///< interior: index of child 0; leaf: index of its first reference
  std::uint32_t count;  ///< leaf: number of references (0 for an empty cell); kInterior otherwise

  /// True for a leaf.
  bool is_leaf() const { return count != kInterior; }
};
static_assert(sizeof(OctreeNode) == 8, "OctreeNode must stay 8 bytes");

/// The octree as plain data, produced by `build_octree` and walked by the `Octree` accelerator.
struct OctreeTree {
  std::vector<OctreeNode> nodes;    ///< root at index 0; empty when there are no primitives
  std::vector<std::uint32_t> refs;  ///< leaf references, leaf by leaf: positions in `ids`
  std::vector<std::uint32_t> ids;   ///< the primitives (or groups) indexed, in the order given
  Box3 bounds;                      ///< exact bounds of the primitives
  Vec3 root_lo;                     ///< low corner of the root cell (a cube enclosing `bounds`)
  float root_size = 0.f;            ///< edge length of the root cell
  /// Distance by which a cell is enlarged when primitives are inserted into it, so that rounding
  /// in traversal never loses a hit next to a cell boundary.
  float margin = 0.f;
  int max_depth = 0;           ///< depth of the deepest leaf (root = 0)
  std::size_t leaf_count = 0;  ///< number of leaves, empty ones included

  /// Coordinate of lattice plane `step` (0 .. kOctreeLatticeSteps) along `axis`: every cell
  /// boundary the builder uses comes from here, so cells that share a boundary agree on it bit for
  /// bit. Traversal computes its crossings from the same lattice, up to the rounding `margin` covers.
  float plane(int axis, std::uint32_t step) const {
    // float(step) is exact (step <= 2^24) and so is the scale by 2^-24: one rounding in the
    // product, one in the sum, the same wherever this is inlined (the build has no FMA contraction).
    return root_lo[axis] + static_cast<float>(step) * (root_size * 0x1p-24f);
  }

  /// The box of the cell at depth `depth` whose low corner is lattice point `lo`.
  Box3 cell_box(const std::uint32_t lo[3], int depth) const {
    const std::uint32_t size = kOctreeLatticeSteps >> depth;
    return {{plane(0, lo[0]), plane(1, lo[1]), plane(2, lo[2])},
            {plane(0, lo[0] + size), plane(1, lo[1] + size), plane(2, lo[2] + size)}};
  }
};

/// Builds an octree over every primitive of `geometry`.
OctreeTree build_octree(const Geometry& geometry, const OctreeConfig& config = {});

/// Builds an octree over the primitives (or groups) `ids` of `geometry` only. A cell holding more
/// than K primitives, above depth L, is split into eight octants at its centre unless the split
/// would not pay (kOctreeSplitGainRatio); a primitive goes into every octant that it overlaps
/// exactly (overlaps_box) once the octant is enlarged by `margin`. Subtrees build in parallel.
OctreeTree build_octree(const Geometry& geometry, std::span<const std::uint32_t> ids, const OctreeConfig& config = {});

/// Per-thread mailboxes (src/accel/mailbox.h), private to the octree.
class Mailboxes;

/// The octree accelerator. Each ray visits the leaves it crosses in order along the ray
/// (Revelles et al. 2000) and stops at the first leaf whose exit lies beyond the closest hit.
class Octree final : public TraversalAccelerator<Octree> {
 public:
  /// Builds the octree over every primitive of `geometry`, which must outlive this object.
  explicit Octree(const Geometry& geometry, const OctreeConfig& config = {});
  /// Builds the octree over the primitives (or groups) `ids` of `geometry` only.
  Octree(const Geometry& geometry, std::span<const std::uint32_t> ids, const OctreeConfig& config = {});
  ~Octree() override;

  Box3 bounds() const override { return m_tree.bounds; }
  /// Name "octree"; memory counts nodes, references, ids and one thread's mailboxes.
  AccelInfo info() const override;

  /// The tree, for tests and tools.
  const OctreeTree& tree() const { return m_tree; }
  /// The configuration it was built with (K and L as clamped).
  const OctreeConfig& config() const { return m_config; }

 private:
  friend class TraversalAccelerator<Octree>;
  // The kernel of every query (TraversalAccelerator).
  template <bool kAnyHit, bool kCount>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;

  const Geometry& m_geometry;
  OctreeConfig m_config;
  OctreeTree m_tree;
  std::unique_ptr<Mailboxes> m_mailboxes;  ///< one slot per entry of m_tree.ids
  double m_build_seconds = 0.0;
};

extern template class TraversalAccelerator<Octree>;

}  // namespace raylab
