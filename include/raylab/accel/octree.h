#pragma once
/// \file
/// Octree over a cubic root cell, walked in ray order with the parametric top-down traversal of
/// Revelles, Urena & Lastra (2000). Each interior node also keeps the boxes of what its eight
/// children hold, so a ray skips a child whose content it misses (an empty child, or the part of
/// a cell that a primitive leaves empty) without entering it. The builder (octree_build.cpp) is
/// separate from the traversal (octree.cpp).

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "raylab/accel/cell_walk.h"
#include "raylab/accel/cylinder_frames.h"
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

/// The cost of entering one more node (a frame and an 8-wide box test), in primitive tests: the
/// split rule's price of a level. A cell of n references is split when the children are expected
/// to cost a ray less: kOctreeTraversalCost + sum over children of n_c * area(content_c) /
/// area(content) < n, the surface-area heuristic with the content boxes (a ray that enters the
/// parent's content box enters a child's with probability about the ratio of their areas).
/// Primitives that cannot be separated (many triangles through one point, coincident planes)
/// leave every child's content about as large as the parent's share and stop the splitting.
inline constexpr double kOctreeTraversalCost = 1.0;

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

/// The content boxes of an interior node's eight children, as a structure of arrays that one
/// 8-wide slab test reads (the wide BVH's, WideBoxRay): child c's box is lo[axis][c] to
/// hi[axis][c]. A child's content box is the union, over the primitives in its subtree, of each
/// primitive's bounds clipped to the child's cell enlarged by the margin: a ray that reaches a
/// hit in the child's cell passes through it. An empty child has the empty box (+inf to -inf).
/// 192 bytes, three cache lines.
struct alignas(64) OctreeChildBoxes {
  float lo[3][8];  ///< low corners, by axis then child
  float hi[3][8];  ///< high corners, by axis then child
};

/// The octree as plain data, produced by `build_octree` and walked by the `Octree` accelerator.
struct OctreeTree {
  std::vector<OctreeNode> nodes;  ///< root at index 0; empty when there are no primitives
  /// One entry per interior node: the boxes of its children, the node whose child 0 is at
  /// index `first` owning entry (first - 1) / 8 (children come in groups of eight after the root).
  std::vector<OctreeChildBoxes> boxes;
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

  /// The content boxes of the children of interior node `node`.
  const OctreeChildBoxes& child_boxes(const OctreeNode& node) const { return boxes[(node.first - 1) >> 3]; }

  /// The box of the cell at depth `depth` whose low corner is lattice point `lo`.
  Box3 cell_box(const std::uint32_t lo[3], int depth) const {
    const std::uint32_t size = kOctreeLatticeSteps >> depth;
    return {{plane(0, lo[0]), plane(1, lo[1]), plane(2, lo[2])},
            {plane(0, lo[0] + size), plane(1, lo[1] + size), plane(2, lo[2] + size)}};
  }
};

/// The split rule: whether a cell of `n` references whose content box is `content` is split, given
/// the references `counts` and content boxes `contents` its eight children would get (see
/// kOctreeTraversalCost). A split that leaves every reference in one child is made only for 16
/// references or more: a small object in a large empty cell, not primitives meeting in a point.
/// One that leaves every reference in two or more children is never made: it separates nothing
/// (primitives sharing a line or a point).
bool octree_split_pays(std::size_t n, const Box3& content, const std::array<std::size_t, 8>& counts,
                       const std::array<Box3, 8>& contents);

/// Builds an octree over every primitive of `geometry`.
OctreeTree build_octree(const Geometry& geometry, const OctreeConfig& config = {});

/// Builds an octree over the primitives (or groups) `ids` of `geometry` only. A cell holding more
/// than K primitives, above depth L, is split into eight octants at its centre unless the split
/// would not pay (kOctreeTraversalCost); a primitive goes into every octant that it overlaps
/// exactly (overlaps_box) once the octant is enlarged by `margin`. Subtrees build in parallel.
OctreeTree build_octree(const Geometry& geometry, std::span<const std::uint32_t> ids, const OctreeConfig& config = {});

/// Per-thread mailboxes (src/accel/mailbox.h), private to the octree.
class Mailboxes;

/// The octree accelerator. Each ray visits the leaves it crosses in order along the ray
/// (Revelles et al. 2000), skipping the children whose content boxes it misses, and stops at
/// the first leaf whose exit lies beyond the closest hit.
class Octree final : public TraversalAccelerator<Octree>, public CellWalk {
 public:
  /// Builds the octree over every primitive of `geometry`, which must outlive this object.
  explicit Octree(const Geometry& geometry, const OctreeConfig& config = {});
  /// Builds the octree over the primitives (or groups) `ids` of `geometry` only.
  Octree(const Geometry& geometry, std::span<const std::uint32_t> ids, const OctreeConfig& config = {});
  ~Octree() override;

  Box3 bounds() const override { return m_tree.bounds; }
  /// Name "octree"; memory counts nodes, child boxes, references, ids and one thread's mailboxes.
  AccelInfo info() const override;

  /// The cells a closest-hit query for `ray` steps into, in order, from the query's own walk:
  /// each leaf whose primitives it tests (has_primitives), and each leaf or whole subtree it
  /// passes over because the ray misses its content box (empty cells included). Once no child
  /// of a node that the ray enters lies ahead, the walk leaves the node at once: the cells
  /// after that one are not stepped into, so they are not listed.
  std::vector<WalkedCell> cells_on_ray(const Ray& ray) const override;

  /// The tree, for tests and tools.
  const OctreeTree& tree() const { return m_tree; }
  /// The configuration it was built with (K and L as clamped).
  const OctreeConfig& config() const { return m_config; }

 private:
  friend class TraversalAccelerator<Octree>;
  // The kernel of every query (TraversalAccelerator).
  template <bool kAnyHit, bool kCount, class K>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
  // The walk behind traverse and cells_on_ray: `on_cell(box, tested)` hears of every cell the ray
  // steps through (a no-op for queries).
  template <bool kAnyHit, bool kCount, class OnCell>
  bool walk(Ray& ray, Hit& hit, TraversalStats* stats, OnCell&& on_cell) const;

  const Geometry& m_geometry;
  OctreeConfig m_config;
  OctreeTree m_tree;
  CylinderFrames m_cylinder_frames;        ///< the frames of the cylinders among the primitives
  std::unique_ptr<Mailboxes> m_mailboxes;  ///< one slot per entry of m_tree.ids
  double m_build_seconds = 0.0;
};

extern template class TraversalAccelerator<Octree>;

}  // namespace raylab
