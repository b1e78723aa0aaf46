#pragma once
/// \file
/// Going on with a checkpoint: what a render leaves unsaid is taken from the checkpoint (so that
/// `raylab render --resume FILE` alone goes on with the same scene and settings), and a render
/// that differs from the checkpoint in anything that decides the image is refused.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "raylab/io/camera_override.h"
#include "raylab/io/checkpoint_file.h"
#include "raylab/render/settings_override.h"

namespace raylab {

/// The parts of a render request a checkpoint can fill in; an empty member was not given.
struct ResumableRequest {
  std::optional<std::string> scene;  ///< the scene as named (file, built-in, spd:...)
  std::optional<std::string> accel;  ///< the acceleration structure
  std::optional<int> passes;         ///< passes over the image
  /// Of these the checkpoint fills width, height, spp, max depth, seed, sampler, filter and filter
  /// radius; not the adaptive samplers' parameters (a checkpoint is of a uniform sampler).
  SettingsOverride settings;
  /// The checkpoint fills every camera part it records (camera_settings) and the request lacks.
  CameraOverride camera;
};

/// The environment parts of `s` given (--env, --env-rotate), as a checkpoint records them after
/// image_settings(): only those given, so that other checkpoints read as before.
std::vector<std::pair<std::string, std::string>> environment_settings(const SettingsOverride& s);

/// The parts of `camera` given, as a checkpoint records them after image_settings(): only those
/// given, so that a checkpoint without camera parts reads as it did before they existed.
std::vector<std::pair<std::string, std::string>> camera_settings(const CameraOverride& camera);

/// Fills every member of `request` not given from `saved`, the checkpoint read from `path`; a
/// setting the checkpoint does not record stays empty. Throws InputError (`path`) when a recorded
/// value is not a valid number.
void fill_from_checkpoint(ResumableRequest& request, const RenderCheckpoint& saved, const std::string& path);

/// Throws InputError (`path`) "cannot resume: ..." with one line per checkpoint_differences()
/// when the render `now` would not go on with `saved`, the checkpoint read from `path`.
void check_resumable(const RenderCheckpoint& saved, const RenderCheckpoint& now, const std::string& path);

}  // namespace raylab
