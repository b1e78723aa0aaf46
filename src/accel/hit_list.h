#pragma once
// The order of an all-hits answer (internal to src/accel): one rule for every structure.

#include <cstddef>
#include <vector>

#include "raylab/core/ray.h"

namespace raylab {

/// Puts `hits[first..]` in the order Accelerator::all_hits promises: by distance, then by
/// primitive id, each primitive once. A structure that references a primitive from several
/// leaves or cells (spatial splits, grids) may report it more than once, always with the same
/// distance, so the copies are neighbours after sorting.
void order_all_hits(std::vector<Hit>& hits, std::size_t first);

}  // namespace raylab
