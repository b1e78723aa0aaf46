#pragma once
/// \file
/// Uniform grid walked with Cleary & Wyvill's incremental traversal (`--accel grid`).
///
/// The scene box is cut into nx * ny * nz equal cells. Each cell lists the primitives that
/// really overlap it (exact shape-box tests, geometry/overlap.h), stored compactly: one offset
/// per cell into one reference array. A ray is clipped to the box and walks the cells it pierces
/// in order, one integer step at a time along the axis whose next cell boundary is nearest; it
/// stops at the first cell that holds a hit no farther than the cell's exit. A primitive spanning
/// several cells is tested once per ray (mailboxing with per-thread ray stamps). Each empty cell
/// also knows how far the nearest non-empty one is, and the walk crosses such empty stretches in
/// jumps (Cohen & Sheffer's proximity clouds) instead of cell by cell.
///
/// Resolution (grid_resolution): the heterogeneous form of Woo's rule, D cells per primitive,
/// cells as close to cubes as the box allows. The default D = 32 was chosen by measurement, on
/// primary rays against the BVH ("bvh"): on spd:balls, where many small spheres crowd a small
/// part of a box stretched by the floor, primitive tests dominate and throughput rises with D up
/// to 64 (about 0.09x the BVH at D = 2, 0.31x at 16, 0.35x at 32, 0.41x at 64); on the Stanford
/// bunny over a ground quad it is flat from D = 16 to 64 (about 0.37x). D = 32 is near the best
/// for both at half the memory of 64: about 5 bytes per cell, i.e. 160 bytes per primitive.

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

/// Build parameters of the uniform grid, with the defaults used by `--accel grid`.
struct GridConfig {
  float density = 32.f;  ///< cells per primitive, D (`--grid-density`); must be > 0
  bool mailbox = true;   ///< test a primitive spanning several cells once per ray
  /// Cross empty space in jumps: a ray in an empty cell whose nearest non-empty cell is d cells
  /// away crosses the empty cube of cells within d - 1 at once instead of cell by cell (off: the
  /// plain walk, for comparison).
  bool skip_empty = true;
};

/// Most cells a grid may have: 2^26, i.e. 256 MiB of cell offsets. A resolution asking for more
/// is scaled down uniformly (see grid_resolution).
inline constexpr std::uint64_t kGridMaxCells = std::uint64_t{1} << 26;

/// Cells per axis for `count` primitives in `box` at density `density` (cells per primitive):
///   n_a = max(1, round(e_a * s)),  s = (density * count / prod e_b)^(1 / k)
/// where the product and k run over the axes that get more than one cell. For a box with three
/// substantial extents that is Woo's rule, n_a = round(e_a * cbrt(D * N / V)). An axis whose
/// extent is zero, or so small that e_a * s < 1 (a flat or thin box), gets one cell and the rule
/// is solved again over the remaining axes, so that D * N cells are still spread over the box
/// instead of being lost to the thin axis. When the product would pass kGridMaxCells, every
/// multi-cell axis is scaled down by the same factor. An empty box or count 0 gives {1, 1, 1}.
std::array<int, 3> grid_resolution(const Box3& box, std::size_t count, float density);

/// The uniform grid accelerator ("grid").
///
/// Memory: (cells + 1) * 4 bytes of offsets and 1 byte per cell of empty-space distance, 4 bytes
/// per reference, 4 bytes per primitive (the id list that references point into), copies of the
/// triangles and spheres in the grid's own (spatial) order, and (n_a + 1) * 4 bytes of plane
/// positions per axis; reported by info(). Mailboxing adds 4 bytes per primitive per thread that
/// traces rays (mailbox_bytes_per_thread()), allocated on each thread's first ray.
///
/// Counted queries report as nodes_visited the cells walked plus the empty-space jumps, and as
/// prim_tests the primitive tests actually run (after the mailboxes).
class UniformGrid final : public TraversalAccelerator<UniformGrid>, public CellWalk {
 public:
  /// Builds the grid over every primitive of `geometry`, which must outlive this object.
  explicit UniformGrid(const Geometry& geometry, const GridConfig& config = {});
  /// Builds the grid over the primitives (or groups) `ids` of `geometry` only.
  UniformGrid(const Geometry& geometry, std::span<const std::uint32_t> ids, const GridConfig& config = {});
  /// Builds the grid with a given number of cells per axis (each >= 1; an axis along which the
  /// box is flat gets 1) instead of the density rule; for tests and experiments.
  UniformGrid(const Geometry& geometry, std::span<const std::uint32_t> ids, std::array<int, 3> resolution,
              const GridConfig& config = {});
  ~UniformGrid() override;

  Box3 bounds() const override { return m_bounds; }
  /// Name "grid"; node_count = cells, leaf_count = non-empty cells, memory_bytes as above
  /// (without the per-thread mailboxes).
  AccelInfo info() const override;

  /// Cells per axis.
  std::array<int, 3> resolution() const { return m_resolution; }
  /// Total number of primitive references over all cells.
  std::size_t reference_count() const { return m_refs.size(); }
  /// The global ids of the primitives in cell (x, y, z), ascending.
  std::vector<std::uint32_t> cell_primitives(int x, int y, int z) const;
  /// Bytes of mailbox stamps each tracing thread allocates (0 when mailboxing is off).
  std::size_t mailbox_bytes_per_thread() const;
  /// The cells a closest-hit query walks, from the query's own kernel: one entry per cell
  /// counted in nodes_visited (a jump's entry is the cell it starts from).
  std::vector<WalkedCell> cells_on_ray(const Ray& ray) const override;

 private:
  /// Cap on the empty-space distances, in cells: a jump crosses at most kMaxSkip - 1 cells per
  /// axis. A higher cap costs build time (the distance passes scan up to it per cell).
  static constexpr int kMaxSkip = 16;
  void build(std::array<int, 3> resolution);
  // Fills m_skip from the offsets.
  void fill_skip_distances();
  // Orders m_ids by the cell of each primitive's centre.
  void order_by_cell(std::array<int, 3> resolution);
  friend class TraversalAccelerator<UniformGrid>;
  // The kernel of every query (TraversalAccelerator): clip, enter, walk.
  template <bool kAnyHit, bool kCount, class K>
  bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
  // The kernel, telling `on_cell(walk, empty-space distance)` about every cell it counts
  // (cells_on_ray).
  template <bool kAnyHit, bool kCount, class OnCell>
  bool run(Ray& ray, Hit& hit, TraversalStats* stats, OnCell&& on_cell) const;
  // Clips the ray to the grid's box and sets up its walk from the entry cell; false when the
  // ray misses the grid.
  // (A template only so that each instruction set's kernel source compiles its own copy.)
  template <class K>
  bool clip_and_enter(const Ray& ray, GridWalk& walk) const;
  // Walks the cells from `walk` on; `mailbox` is the ray's stamp or a stand-in that tests all.
  template <bool kAnyHit, bool kCount, class Mailbox, class OnCell>
  bool walk_cells(Ray& ray, Hit& hit, TraversalStats* stats, GridWalk& walk, Mailbox mailbox, OnCell& on_cell) const;

  const Geometry& m_geometry;
  GridConfig m_config;
  std::vector<std::uint32_t> m_ids;   ///< indexed primitives in spatial order; references point here
  std::vector<Triangle> m_triangles;  ///< parallel to m_ids where they are triangles (else unused)
  std::vector<Sphere> m_spheres;      ///< parallel to m_ids where they are spheres (else unused)
  CylinderFrames m_cylinder_frames;   ///< the frames of the cylinders among the primitives
  Box3 m_bounds;
  std::array<int, 3> m_resolution{1, 1, 1};
  Vec3 m_cell{0.f, 0.f, 0.f};                  ///< cell edge lengths
  Vec3 m_inv_cell{0.f, 0.f, 0.f};              ///< cells per unit length (0 on a flat axis)
  std::array<std::vector<float>, 3> m_planes;  ///< n_a + 1 cell boundaries per axis, lo to hi
  std::vector<std::uint32_t> m_offsets;        ///< cell c holds m_refs[m_offsets[c] .. m_offsets[c + 1])
  std::vector<std::uint8_t> m_skip;            ///< per cell: 0 = holds references, else distance to one (capped)
  std::vector<std::uint32_t> m_refs;           ///< positions in m_ids, cell by cell (x fastest)
  std::size_t m_nonempty_cells = 0;
  double m_build_seconds = 0.0;
  std::unique_ptr<Mailboxes> m_mailboxes;  ///< null when mailboxing is off
};

extern template class TraversalAccelerator<UniformGrid>;

}  // namespace raylab
