#pragma once
/// \file
/// Instancing: one prototype mesh stored once, placed many times under transforms.

#include <cstdint>

#include "raylab/core/transform.h"

namespace raylab {

/// One placement of a prototype Geometry. Its primitives are numbered in the global id space
/// after the scene's own (flat) primitives: global id = flat size + `first_prim_offset` + local id.
struct Instance {
  std::uint32_t prototype = 0;          ///< index of the prototype geometry
  Transform to_world;                   ///< prototype space to world space
  Transform to_local;                   ///< the inverse: world rays are carried into prototype space
  std::uint32_t first_prim_offset = 0;  ///< see above
  std::uint32_t first_object = 0;       ///< scene object id of the prototype's object 0
};

}  // namespace raylab
