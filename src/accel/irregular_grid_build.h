#pragma once
// The irregular grid's build stages (internal to src/accel): the virtual grid
// (irregular_grid_build.cpp), merging (irregular_grid_build_merge.cpp) and expansion
// (irregular_grid_build_expand.cpp) hand each other the cells in this form.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "raylab/accel/irregular_grid.h"

namespace raylab {

/// Cells under construction: each one's own lattice box (lo x, y, z, then hi x, y, z; hi
/// exclusive) and its references, ascending, as offsets into one array.
struct IrregularBuildCells {
  std::vector<std::array<std::uint16_t, 6>> boxes;  ///< per cell
  std::vector<std::uint32_t> begin;                 ///< cells + 1 offsets into refs
  std::vector<std::uint32_t> refs;                  ///< positions in the data's ids, cell by cell

  /// Number of cells.
  std::size_t size() const { return boxes.size(); }
  /// The references of cell c.
  std::span<const std::uint32_t> refs_of(std::size_t c) const {
    return {refs.data() + begin[c], refs.data() + begin[c + 1]};
  }
};

/// Fills the lattice and the lookup map from `data.ids` and `data.bounds`, and returns the
/// virtual grid's cells: top cells cut into 2^s per axis by their counts, recursively, every
/// primitive referenced by every cell its surface overlaps (enlarged by the grid margins).
IrregularBuildCells build_virtual_grid(const Geometry& geometry, IrregularGridData& data,
                                       const IrregularGridConfig& config);

/// Merges neighbouring cells where the cost model says it pays (alternating x, y, z passes, at
/// most config.merge_rounds rounds), renumbering the cells and the lookup map's leaves.
void merge_cells(IrregularBuildCells& cells, IrregularGridData& data, const IrregularGridConfig& config);

/// The finished cells: each one's box expanded over the neighbouring cells whose references it
/// holds (config.expand_rounds rounds over the six faces), plus the sentinel.
std::vector<IrregularCell> expand_cells(const IrregularBuildCells& cells, const IrregularGridData& data,
                                        const IrregularGridConfig& config);

}  // namespace raylab
