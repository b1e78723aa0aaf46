#pragma once
/// \file
/// The camera flags of `render`, `compare` and `quality`, alike in all three: --up for a fitted
/// camera, and --camera-from, --camera-at, --camera-up, --fov and --orbit for any scene.

#include <CLI/CLI.hpp>

#include "raylab/io/camera_override.h"

namespace raylab::cli {

/// Adds the camera flags to `cmd`, in its help group "Camera", filling `camera` as they are
/// parsed. A value that is not a vector, an axis or a field of view is a usage error naming its
/// flag; what only the scene can tell (from == at, up along the view) is apply_camera_override's.
void add_camera_options(CLI::App& cmd, CameraOverride& camera);

/// The camera flags as they read in messages ("--up, --camera-from, ...").
inline constexpr char kCameraFlagList[] = "--up, --camera-from, --camera-at, --camera-up, --fov, --orbit";

}  // namespace raylab::cli
