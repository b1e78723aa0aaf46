#pragma once
/// \file
/// Creating accelerators by name.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/bvh.h"
#include "raylab/accel/irregular_grid.h"
#include "raylab/accel/octree.h"
#include "raylab/accel/two_level_grid.h"
#include "raylab/accel/uniform_grid.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// Parameters for every structure the factory can make; each reads only its own part.
struct AccelConfig {
  BvhConfig bvh;                  ///< used by "bvh" (4-wide) and "bvh2" (binary)
  GridConfig grid;                ///< used by "grid"
  TwoLevelGridConfig grid2;       ///< used by "grid2"
  OctreeConfig octree;            ///< used by "octree"
  IrregularGridConfig irregular;  ///< used by "irregular"
};

/// Names the factory accepts in this build, in the order they are listed to users ("embree"
/// only when raylab was built with Embree 3).
std::span<const std::string_view> accelerator_names();

/// The valid names as one line for messages: "bvh, bvh2, grid, ...".
std::string accelerator_name_list();

/// Builds the structure called `name` over every primitive of `geometry` (which must outlive
/// it). Throws UsageError listing the valid names when `name` is unknown.
std::unique_ptr<Accelerator> make_accelerator(std::string_view name, const Geometry& geometry,
                                              const AccelConfig& config = {});

/// Builds the structure called `name` over the primitives (or groups) `ids` of `geometry` only.
std::unique_ptr<Accelerator> make_accelerator(std::string_view name, const Geometry& geometry,
                                              std::span<const std::uint32_t> ids, const AccelConfig& config = {});

}  // namespace raylab
