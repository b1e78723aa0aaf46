#pragma once
/// \file
/// Irregular grid (`--accel irregular`), after Pérard-Gayot, Kalojanov & Slusallek, "GPU ray
/// tracing using irregular grids" (Eurographics 2017).
///
/// The build (irregular_grid_build*.cpp) works on a virtual lattice over the scene box: a coarse
/// top grid (density rule, grid_resolution) whose cells are each cut into 2^s cells per axis,
/// s chosen from the cell's own primitive count, and dense cells cut again while it pays, so
/// every cell is a box of integer coordinates of the finest lattice. Neighbouring cells then
/// merge where a cost model says the merged cell is cheaper to cross, and every cell's exit box
/// is expanded over the neighbours whose primitives it already lists. The traversal
/// (irregular_grid.cpp) looks a point up (one load, then two per level of subdivision), tests
/// the cell's primitives and jumps to the point where the ray leaves the expanded box: few, long
/// steps.

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

/// Build parameters of the irregular grid, with the defaults used by `--accel irregular`
/// (measured: docs/accelerators.md, "Irregular grid").
struct IrregularGridConfig {
  float top_density = 0.125f;  ///< λ1: top cells per primitive (`--irregular-top-density`)
  float sub_density = 2.f;     ///< λ2: cells per reference when a cell is subdivided (`--irregular-sub-density`)
  int max_shift = 3;           ///< most levels one subdivision step takes, 2^s cells per axis; [1, 6]
  int max_depth = 16;          ///< most levels below a top cell in all; [0, 16], also capped by the 16-bit lattice
  float step_cost = 1.f;       ///< C_step of the merge cost model (per cell crossed)
  float prim_cost = 1.f;       ///< C_prim of the merge cost model (per primitive tested)
  int merge_rounds = 4;        ///< most rounds of x, y, z merge passes (0: no merging)
  int expand_rounds = 3;       ///< rounds over the six faces when expanding exits (0: none)
  bool mailbox = true;         ///< test a primitive spanning several cells once per ray
};

/// One cell of the finished grid, 16 bytes: the box the ray leaves it through (its expanded box,
/// in lattice coordinates, lo inclusive, hi exclusive) and its first reference; its last one is
/// the next cell's first.
struct IrregularCell {
  std::uint16_t lo[3];  ///< expanded box, low lattice corner
  std::uint16_t hi[3];  ///< expanded box, high lattice corner (exclusive)
  std::uint32_t first;  ///< index of its first reference
};
static_assert(sizeof(IrregularCell) == 16, "IrregularCell must stay 16 bytes");

/// Most lattice steps per axis: cell coordinates are 16-bit.
inline constexpr int kIrregularMaxLattice = 65535;

/// The irregular grid as plain data, produced by build_irregular_grid and walked by IrregularGrid.
///
/// The lookup map is a shallow tree over the lattice: one entry per top cell, and per subdivided
/// cell a block of 2^s x 2^s x 2^s entries (x fastest). An entry with kLeaf set holds a cell
/// index; any other entry is the index of a node, which says where its block starts and its s.
struct IrregularGridData {
  /// Marks a map entry that is a cell index.
  static constexpr std::uint32_t kLeaf = 0x80000000u;
  /// A subdivided cell of the lookup map.
  struct Node {
    std::uint32_t begin;  ///< first entry of its block in `map`
    std::uint32_t shift;  ///< s: its block has 2^s entries per axis
  };

  /// The primitives (or groups) in spatial order (Morton order of their box centres, ties by
  /// id); references point here, and the accelerator's copies of the triangles and spheres
  /// follow the same order, so the primitives of one cell lie together in memory.
  std::vector<std::uint32_t> ids;
  std::vector<IrregularCell> cells;  ///< the cells, plus one sentinel holding the reference count
  std::vector<std::uint32_t> refs;   ///< positions in `ids`, cell by cell, ascending in each cell
  std::vector<std::uint32_t> top;    ///< one map entry per top cell, x fastest
  std::vector<Node> nodes;           ///< the subdivided cells of the map
  std::vector<std::uint32_t> map;    ///< the blocks of map entries
  /// Each cell's own box (lattice lo x, y, z, hi x, y, z; before expansion): the cells tile the
  /// lattice. Kept by the builder for tests and tools; the accelerator drops it.
  std::vector<std::array<std::uint16_t, 6>> boxes;
  Box3 bounds;                          ///< exact bounds of the primitives
  Vec3 origin{0.f, 0.f, 0.f};           ///< lattice plane 0 per axis (bounds.lo)
  Vec3 step{0.f, 0.f, 0.f};             ///< lattice step per axis (rounded up: plane(lattice) >= bounds.hi)
  Vec3 inv_step{0.f, 0.f, 0.f};         ///< lattice steps per unit length (0 on a flat axis)
  std::array<int, 3> top_res{1, 1, 1};  ///< top cells per axis
  std::array<int, 3> lattice{1, 1, 1};  ///< lattice steps per axis: top_res << depth
  int depth = 0;                        ///< lattice levels below a top cell
  std::size_t nonempty_cells = 0;       ///< cells holding references

  /// Number of cells (without the sentinel).
  std::size_t cell_count() const { return cells.empty() ? 0 : cells.size() - 1; }

  /// Lattice plane k along `axis`. The build's cell boxes and the walk's exits both come from
  /// here, so they agree bit for bit (the build has no FMA contraction).
  float plane(int axis, int k) const { return origin[axis] + float(k) * step[axis]; }

  /// The cell holding lattice voxel (x, y, z) (each coordinate below lattice[axis]): one load
  /// for the top cell, two more per level of subdivision.
  std::uint32_t cell_at(std::uint32_t x, std::uint32_t y, std::uint32_t z) const {
    std::uint32_t level = static_cast<std::uint32_t>(depth);
    std::uint32_t entry =
        top[(x >> level) + std::size_t(top_res[0]) * ((y >> level) + std::size_t(top_res[1]) * (z >> level))];
    while (!(entry & kLeaf)) {
      const Node n = nodes[entry];
      level -= n.shift;
      const std::uint32_t mask = (1u << n.shift) - 1u;
      entry = map[n.begin + ((x >> level) & mask) + (((y >> level) & mask) << n.shift) +
                  (((z >> level) & mask) << (2 * n.shift))];
    }
    return entry & ~kLeaf;
  }

  /// The world box of lattice box [lo, hi).
  Box3 lattice_box(const std::uint16_t lo[3], const std::uint16_t hi[3]) const {
    return {{plane(0, lo[0]), plane(1, lo[1]), plane(2, lo[2])}, {plane(0, hi[0]), plane(1, hi[1]), plane(2, hi[2])}};
  }
};

/// Builds the irregular grid over the primitives (or groups) `ids` of `geometry`: virtual grid,
/// merge, expansion (each a pass of its own, in parallel where it pays). Throws UsageError on
/// invalid parameters.
IrregularGridData build_irregular_grid(const Geometry& geometry, std::span<const std::uint32_t> ids,
                                       const IrregularGridConfig& config = {});

class Mailboxes;

/// The irregular grid accelerator ("irregular").
///
/// Memory: 16 bytes per cell, 4 per reference, 4 per primitive (the id list), 4 per entry of the
/// lookup map and 8 per node, and copies of the triangles and spheres in the grid's spatial
/// order (where the scene has any); reported by info().
/// Counted queries report as nodes_visited the cells visited (one lookup each) and as prim_tests
/// the primitive tests run.
class IrregularGrid final : public TraversalAccelerator<IrregularGrid>, public CellWalk {
 public:
  /// Builds the grid over every primitive of `geometry`, which must outlive this object.
  explicit IrregularGrid(const Geometry& geometry, const IrregularGridConfig& config = {});
  /// Builds the grid over the primitives (or groups) `ids` of `geometry` only.
  IrregularGrid(const Geometry& geometry, std::span<const std::uint32_t> ids, const IrregularGridConfig& config = {});
  ~IrregularGrid() override;

  Box3 bounds() const override { return m_data.bounds; }
  /// Name "irregular"; node_count = cells, leaf_count = non-empty cells, memory_bytes as above.
  AccelInfo info() const override;
  /// The expanded boxes of the cells a closest-hit query for `ray` visits, in order.
  std::vector<WalkedCell> cells_on_ray(const Ray& ray) const override;

  /// The grid's data (without the cells' own boxes, which the accelerator does not keep).
  const IrregularGridData& data() const { return m_data; }

 private:
  friend class TraversalAccelerator<IrregularGrid>;
  // The kernel of every query (TraversalAccelerator).
  template <bool kAnyHit, bool kCount, class K>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
  // The walk itself; `visit(cell)` is called for every cell visited (cells_on_ray).
  template <bool kAnyHit, bool kCount, class Mailbox, class Visit>
  bool walk(Ray& ray, Hit& hit, TraversalStats* stats, Mailbox mailbox, Visit&& visit) const;

  const Geometry& m_geometry;
  IrregularGridConfig m_config;
  IrregularGridData m_data;
  std::vector<Triangle> m_triangles;  ///< parallel to m_data.ids where they are triangles (else unused)
  std::vector<Sphere> m_spheres;      ///< parallel to m_data.ids where they are spheres (else unused)
  CylinderFrames m_cylinder_frames;   ///< the frames of the cylinders among the primitives
  double m_build_seconds = 0.0;
  std::unique_ptr<Mailboxes> m_mailboxes;  ///< null when mailboxing is off
};

extern template class TraversalAccelerator<IrregularGrid>;

}  // namespace raylab
