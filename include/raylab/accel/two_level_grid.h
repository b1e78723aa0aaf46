#pragma once
/// \file
/// Two-level grid (`--accel grid2`): Jevans & Wyvill's nested grids, built as Kalojanov,
/// Billeter & Slusallek (2011) build them.
///
/// A coarse top grid covers the scene box; every top cell that primitives overlap holds its own
/// uniform grid (a leaf grid), whose resolution follows the cell's own primitive count. Dense
/// regions (a tree's crown) thus get fine cells and empty space stays coarse. A primitive that
/// spans most of a top cell along two axes (a ground plane, a wall) would stretch the leaf grid
/// over the whole cell and leave a small dense object inside it (a teapot in a stadium) in a
/// cell or two; such "big" primitives go to a short list of the top cell, tested when a ray
/// enters it, and the leaf grid covers only the box of the cell's other primitives (clipped to
/// the cell). Resolutions follow Ize, Shirley & Parker (2007): O(N) cells in
/// all, the top level at about N^0.6 cells (top_density * N^0.6, by the uniform grid's rule of
/// near-cubic cells) and one nesting level whose leaf grids get leaf_density cells per
/// primitive each.
///
/// Build: (top cell, primitive) pairs for every top cell a primitive really overlaps (exact
/// shape-box test with the uniform grid's margins), sorted, which gives each top cell's range;
/// then (leaf cell, primitive) pairs keyed by the leaf grid's offset plus the leaf cell, sorted
/// the same way: one reference array and one offset per leaf cell.
///
/// Traversal: Cleary & Wyvill's walk on the top grid (shared with the uniform grid); in a top
/// cell with primitives, the same walk on its leaf grid over the ray's stretch inside the cell,
/// then back to the top walk. Mailboxes test a primitive once per ray; the walk stops at the
/// first cell holding a hit no farther than the cell's exit; empty space is crossed in jumps
/// at both levels (Cohen & Sheffer's proximity clouds, as in the uniform grid).
///
/// Memory: per top cell 1 byte of empty-space distance and a 64-byte record (offset, leaf
/// resolution, box and cell size); per leaf cell (and list) 1 byte of empty-space distance;
/// (leaf cells + top lists + 1) * 4 bytes of offsets; 4 bytes per reference; 4
/// bytes per primitive of ids, copies of the triangles and spheres in the grid's spatial order,
/// and the top grid's planes; reported by info(). Mailboxing adds 4 bytes per primitive per
/// tracing thread.

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

class Mailboxes;
struct GridWalk;

/// Build parameters of the two-level grid, with the defaults used by `--accel grid2`.
struct TwoLevelGridConfig {
  /// Top cells per N^0.6 (`--grid2-top-density`): the top grid has about top_density * N^0.6
  /// cells for N primitives; must be > 0.
  float top_density = 1.f;
  /// Cells per primitive of each leaf grid (`--grid2-leaf-density`): a top cell overlapped by
  /// n primitives gets about leaf_density * n cells; must be > 0.
  float leaf_density = 2.f;
  bool mailbox = true;  ///< test a primitive spanning several cells once per ray
  /// Cross empty space in jumps at both levels: over the empty top cells around an empty top
  /// cell, and over the empty leaf cells around an empty leaf cell (off: cell by cell).
  bool skip_empty = true;
};

/// The two-level grid accelerator ("grid2").
///
/// Counted queries report as nodes_visited the top cells and leaf cells walked plus the jumps
/// over empty top cells, and as prim_tests the primitive tests actually run.
class TwoLevelGrid final : public TraversalAccelerator<TwoLevelGrid>, public CellWalk {
 public:
  /// Builds the grid over every primitive of `geometry`, which must outlive this object.
  explicit TwoLevelGrid(const Geometry& geometry, const TwoLevelGridConfig& config = {});
  /// Builds the grid over the primitives (or groups) `ids` of `geometry` only.
  TwoLevelGrid(const Geometry& geometry, std::span<const std::uint32_t> ids, const TwoLevelGridConfig& config = {});
  ~TwoLevelGrid() override;

  Box3 bounds() const override { return m_bounds; }
  /// Name "grid2"; node_count = top cells + leaf cells, leaf_count = non-empty leaf cells,
  /// memory_bytes as above (without the per-thread mailboxes); max_depth 1 (0 for an empty grid).
  AccelInfo info() const override;
  /// The cells a closest-hit query walks, from the query's own kernel, in order: each top cell
  /// (has_primitives where its list of big primitives is not empty), then the leaf cells of its
  /// leaf grid that the ray crosses (has_primitives where they hold references). One entry per
  /// cell counted in nodes_visited.
  std::vector<WalkedCell> cells_on_ray(const Ray& ray) const override;

  /// Top cells per axis.
  std::array<int, 3> top_resolution() const { return m_top_resolution; }
  /// The box of top cell (x, y, z).
  Box3 top_cell_box(int x, int y, int z) const;
  /// Leaf cells per axis of top cell (x, y, z): {0, 0, 0} when it has no leaf grid (no
  /// primitive, or only big ones, overlap it).
  std::array<int, 3> leaf_resolution(int x, int y, int z) const;
  /// The box the leaf grid of top cell (x, y, z) covers (empty when it has none).
  Box3 leaf_grid_box(int x, int y, int z) const;
  /// The global ids of the big primitives listed in top cell (x, y, z), ascending.
  std::vector<std::uint32_t> top_cell_primitives(int x, int y, int z) const;
  /// The box of leaf cell (i, j, k) of top cell (x, y, z), as the walk and the build use it.
  Box3 leaf_cell_box(int x, int y, int z, int i, int j, int k) const;
  /// The global ids of the primitives in leaf cell (i, j, k) of top cell (x, y, z), ascending.
  std::vector<std::uint32_t> leaf_cell_primitives(int x, int y, int z, int i, int j, int k) const;
  /// Total number of leaf cells.
  std::size_t leaf_cell_count() const { return m_leaf_cells; }
  /// Total number of primitive references over all leaf cells.
  std::size_t reference_count() const { return m_refs.size(); }

 private:
  /// Cap on the top grid's empty-space distances, in cells (as the uniform grid's).
  static constexpr int kMaxSkip = 16;
  /// One top cell as the walk needs it.
  struct TopCell {
    std::uint32_t list = 0;           ///< m_offsets index of the big primitives; the leaf cells follow
    std::array<int, 3> res{0, 0, 0};  ///< leaf cells per axis; 0 when there is no leaf grid
    Vec3 lo, hi;                      ///< the leaf grid's box
    Vec3 cell;                        ///< leaf cell lengths
    Vec3 inv_cell;                    ///< leaf cells per unit length (0 on a flat axis)
  };
  void build();
  void order_by_top_cell();
  friend class TraversalAccelerator<TwoLevelGrid>;
  // The kernel of every query (TraversalAccelerator).
  template <bool kAnyHit, bool kCount, class K>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
  // The kernel, telling on_cell(top index, leaf cell or null, tested, jump reach in cells) about
  // every cell it counts.
  template <bool kAnyHit, bool kCount, class OnCell>
  bool run(Ray& ray, Hit& hit, TraversalStats* stats, OnCell&& on_cell) const;
  // Clips the ray to the box and sets up the top walk; false when the ray misses the grid.
  // (A template only so that each instruction set's kernel source compiles its own copy.)
  template <class K>
  bool clip_and_enter(const Ray& ray, GridWalk& walk, float& t_in) const;
  template <bool kAnyHit, bool kCount, class Mailbox, class OnCell>
  bool walk(Ray& ray, Hit& hit, TraversalStats* stats, GridWalk& top, float t_in, Mailbox mailbox,
            OnCell& on_cell) const;
  // Lower and upper corner of top cell (x, y, z).
  Vec3 top_lo(int x, int y, int z) const;
  Vec3 top_hi(int x, int y, int z) const;

  const Geometry& m_geometry;
  TwoLevelGridConfig m_config;
  std::vector<std::uint32_t> m_ids;   ///< indexed primitives in spatial order; references point here
  std::vector<Triangle> m_triangles;  ///< parallel to m_ids where they are triangles (else unused)
  std::vector<Sphere> m_spheres;      ///< parallel to m_ids where they are spheres (else unused)
  CylinderFrames m_cylinder_frames;   ///< the frames of the cylinders among the primitives
  Box3 m_bounds;
  std::array<int, 3> m_top_resolution{1, 1, 1};
  Vec3 m_top_cell{0.f, 0.f, 0.f};                  ///< top cell edge lengths
  Vec3 m_top_inv_cell{0.f, 0.f, 0.f};              ///< top cells per unit length (0 on a flat axis)
  std::array<std::vector<float>, 3> m_top_planes;  ///< n_a + 1 top cell boundaries per axis
  std::vector<TopCell> m_top;                      ///< top cells, x fastest
  std::vector<std::uint8_t> m_top_skip;            ///< per top cell: 0 = has a leaf grid, else distance to one
  std::vector<std::uint8_t> m_leaf_skip;  ///< per list or leaf cell: 0 = holds references, else distance to one
  std::vector<std::uint32_t> m_offsets;   ///< list or leaf cell c: m_refs[m_offsets[c] .. m_offsets[c + 1])
  std::vector<std::uint32_t> m_refs;      ///< positions in m_ids, leaf cell by leaf cell
  std::size_t m_leaf_cells = 0;
  std::size_t m_nonempty_leaf_cells = 0;
  double m_build_seconds = 0.0;
  std::unique_ptr<Mailboxes> m_mailboxes;  ///< null when mailboxing is off
};

extern template class TraversalAccelerator<TwoLevelGrid>;

}  // namespace raylab
