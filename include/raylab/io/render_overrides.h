#pragma once
/// \file
/// Everything a caller sets over a loaded scene for one render, applied in one place and one
/// order, so that a render in one process, on MPI ranks and after --resume sees the same scene.

#include "raylab/io/camera_override.h"
#include "raylab/render/settings_override.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Applies `camera` (apply_camera_override), then every member of `settings` but the image size
/// (apply_settings_override), then the image size by the one rule of set_image_size: one side
/// given, the other follows the scene's ratio; both given in another shape, the view widens so
/// that the scene's framing stays whole; then the environment (--env loaded by load_environment
/// and turned by --env-rotate, or --env-rotate alone turning the scene's own). Throws UsageError
/// as apply_camera_override and load_environment do, and for --env-rotate without an environment.
void apply_render_overrides(Scene& scene, const SettingsOverride& settings, const CameraOverride& camera);

}  // namespace raylab
