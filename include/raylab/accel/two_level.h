#pragma once
/// \file
/// Bounding-volume wrappers and instancing: a two-level structure whose top level holds simple
/// primitives directly and each mesh or instance as one item, wrapped in a box or a sphere that a
/// ray tests before entering the item's own structure. Any accelerator serves at either level.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/bounding_wrapper.h"
#include "raylab/accel/factory.h"
#include "raylab/geometry/geometry.h"
#include "raylab/geometry/instance.h"

namespace raylab {

/// How to build a scene's structure.
struct SceneAccelOptions {
  std::string top = "bvh";  ///< structure over the top-level items (`--accel`)
  std::string bottom;       ///< structure inside each mesh and prototype (empty: same as top)
  WrapMode wrap = WrapMode::kNone;
  AccelConfig config;               ///< parameters shared by both levels
  std::uint32_t min_mesh_size = 2;  ///< objects with at least this many primitives are wrapped meshes
};

/// Builds the structure for a scene made of `flat` primitives (world space; an object with at
/// least `min_mesh_size` primitives counts as a mesh) and `instances` of `prototypes`. With no
/// instances and WrapMode::kNone this is just the named structure over `flat`. Hits carry global
/// primitive ids (see Instance). The inputs must outlive the result.
std::unique_ptr<Accelerator> make_scene_accelerator(const Geometry& flat, std::span<const Geometry> prototypes,
                                                    std::span<const Instance> instances,
                                                    const SceneAccelOptions& options);

}  // namespace raylab
