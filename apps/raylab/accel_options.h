#pragma once
/// \file
/// The acceleration-structure options shared by `render` and `compare`.

#include <CLI/CLI.hpp>
#include <string>

#include "raylab/accel/two_level.h"

namespace raylab::cli {

/// Structure parameters as the command line sets them (the structure name itself is added by
/// each command: `render --accel NAME`, `compare --accels A,B,...`).
struct AccelArgs {
  SceneAccelOptions options;
  std::string wrap = "none";
};

/// Adds --grid-density, --octree-max-items, --octree-max-depth, --bvh-spatial-splits, --wrap and
/// --bottom-accel.
void add_accel_parameter_options(CLI::App& cmd, AccelArgs& args);

/// The accelerator names this build knows, for CLI11's IsMember check.
std::vector<std::string> accelerator_choices();

}  // namespace raylab::cli
