#pragma once
/// \file
/// Turning what the user named on the command line into a Scene.

#include <string>

#include "raylab/scene/scene.h"

namespace raylab {

/// Loads `source`: a built-in scene name ("demo"), or a mesh file (".obj"), which gets a fitted
/// camera, a default light and a grey material. Throws UsageError for an unknown name or
/// extension, InputError for a bad file.
Scene load_scene(const std::string& source);

/// Places the camera to frame the scene's bounds from the front, slightly above and to the right,
/// and adds a key light and a fill light near the camera. Used for bare meshes.
void fit_camera_and_lights(Scene& scene);

}  // namespace raylab
