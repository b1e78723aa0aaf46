#pragma once
/// \file
/// The cells a ray walks through a space-subdivision structure, for drawings and tests.

#include <vector>

#include "raylab/core/box.h"
#include "raylab/core/ray.h"

namespace raylab {

/// One cell the walk visited: its box, and whether the walk tested primitives there.
struct WalkedCell {
  Box3 box;               ///< the cell's box (for an irregular grid: the box the ray crossed to leave it)
  bool has_primitives{};  ///< the walk tested primitives in this cell
};

/// Implemented by the structures made of cells (the grids and the octree) next to Accelerator:
/// the cells a closest-hit query for `ray` visits, in the order it visits them, ending where the
/// query ends (at the cell holding the closest hit, or where the ray leaves the structure). It
/// does the query's own walk, so a drawing shows what the traversal really does. Not for timing.
class CellWalk {
 public:
  virtual ~CellWalk() = default;
  /// The cells a closest-hit query for `ray` visits, in order.
  virtual std::vector<WalkedCell> cells_on_ray(const Ray& ray) const = 0;
};

}  // namespace raylab
