// Expanding the irregular grid's cells. A ray leaving a cell need not stop at the cell's own
// boundary: it may go on as long as whatever it crosses holds no primitive the cell does not
// already list, since those were tested over the ray's whole range. So every cell's exit box
// grows face by face over its neighbours: a face moves out when every cell touching the layer
// of lattice voxels just beyond it lists only references of this cell (an empty cell always
// qualifies), and then as far as the nearest far face of those cells, which they fill
// completely. The reference lists do not change. Every cell grows independently, measured
// against the cells' own boxes (not their expanded ones), so cells expand in parallel.

#include <algorithm>
#include <cstdint>
#include <vector>

#include <tbb/parallel_for.h>

#include "irregular_grid_build.h"

namespace raylab {
namespace {

// Tries to move face `side` (0: low, 1: high) of box [lo, hi) along `axis` outwards; true when
// it moved.
bool grow_face(const IrregularBuildCells& cells, const IrregularGridData& data, std::span<const std::uint32_t> mine,
               int lo[3], int hi[3], int axis, int side) {
  if (side == 1 ? hi[axis] >= data.lattice[axis] : lo[axis] <= 0) return false;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  int reach = side == 1 ? data.lattice[axis] : 0;
  int p[3];
  p[axis] = side == 1 ? hi[axis] : lo[axis] - 1;
  std::uint32_t last_checked = 0xffffffffu;
  // Row by row across the face; the cells met along a row all reach at least to the nearest of
  // their upper v faces, so the rows up to there meet the same cells and are skipped.
  for (p[v] = lo[v]; p[v] < hi[v];) {
    int row_end = hi[v];
    for (p[u] = lo[u]; p[u] < hi[u];) {
      const std::uint32_t c = data.cell_at(p[0], p[1], p[2]);
      const auto& b = cells.boxes[c];
      if (c != last_checked) {
        const auto theirs = cells.refs_of(c);
        if (!theirs.empty() && !std::includes(mine.begin(), mine.end(), theirs.begin(), theirs.end())) return false;
        last_checked = c;
      }
      reach = side == 1 ? std::min(reach, int(b[axis + 3])) : std::max(reach, int(b[axis]));
      row_end = std::min(row_end, int(b[v + 3]));
      p[u] = b[u + 3];
    }
    p[v] = row_end;
  }
  (side == 1 ? hi[axis] : lo[axis]) = reach;
  return true;
}

}  // namespace

std::vector<IrregularCell> expand_cells(const IrregularBuildCells& cells, const IrregularGridData& data,
                                        const IrregularGridConfig& config) {
  const std::size_t n = cells.size();
  std::vector<IrregularCell> out(n + 1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 64), [&](const auto& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      const auto& b = cells.boxes[c];
      int lo[3] = {b[0], b[1], b[2]}, hi[3] = {b[3], b[4], b[5]};
      const auto mine = cells.refs_of(c);
      for (int round = 0; round < config.expand_rounds; ++round) {
        bool grew = false;
        for (int axis = 0; axis < 3; ++axis) {
          for (int side = 0; side < 2; ++side) grew = grow_face(cells, data, mine, lo, hi, axis, side) || grew;
        }
        if (!grew) break;
      }
      IrregularCell& cell = out[c];
      for (int a = 0; a < 3; ++a) {
        cell.lo[a] = static_cast<std::uint16_t>(lo[a]);
        cell.hi[a] = static_cast<std::uint16_t>(hi[a]);
      }
      cell.first = cells.begin[c];
    }
  });
  out[n] = IrregularCell{{0, 0, 0}, {0, 0, 0}, cells.begin[n]};
  return out;
}

}  // namespace raylab
