#pragma once
/// \file
/// Embree 3 as an accelerator (`--accel embree`): the reference tracer behind the same interface.

#include <cstdint>
#include <memory>
#include <span>

#include "raylab/accel/accelerator.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// True when raylab was built with Embree 3.
bool embree_available();

/// Builds an Embree scene over the primitives (or groups) `ids` of `geometry`. Throws UsageError
/// when raylab was built without Embree.
std::unique_ptr<Accelerator> make_embree_accelerator(const Geometry& geometry, std::span<const std::uint32_t> ids);

}  // namespace raylab
