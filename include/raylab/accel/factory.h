#pragma once
/// \file
/// Creating accelerators by name.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/bvh.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// Parameters for every structure the factory can make; each reads only its own part.
struct AccelConfig {
  BvhConfig bvh;  ///< used by "bvh" (4-wide) and "bvh2" (binary)
};

/// Names the factory accepts, in the order they are listed to users.
std::span<const std::string_view> accelerator_names();

/// Builds the structure called `name` over `geometry` (which must outlive it). Throws UsageError
/// listing the valid names when `name` is unknown.
std::unique_ptr<Accelerator> make_accelerator(std::string_view name, const Geometry& geometry,
                                              const AccelConfig& config = {});

}  // namespace raylab
