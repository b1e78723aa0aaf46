#pragma once
/// \file
/// Turning what the user named on the command line into a Scene.

#include <span>
#include <string>
#include <string_view>

#include "raylab/io/scene_paths.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Loads `source`: a built-in scene name ("demo", "cornell"), an SPD generator ("spd:balls",
/// "spd:balls?size=6"), or a file by its extension: a scene (.json, .nff) or a mesh (.obj,
/// .gltf, .glb, .ply, .off, .stl), which gets a fitted camera and lights. Throws UsageError for
/// an unknown name or extension, InputError for a bad file.
Scene load_scene(const std::string& source, const LoadOptions& options = {});

/// Loads mesh file `path` (.obj, .gltf, .glb, .ply, .off, .stl) as a scene of its own: the
/// file's materials where the format has them, else one grey material; no lights; a camera only
/// from a glTF file that has one. Zero-area faces dropped are noted in `Scene::warnings`.
Scene load_mesh(const std::string& path, const LoadOptions& options = {});

/// The file extensions load_scene accepts, with a dot (".json", ...).
std::span<const std::string_view> scene_file_extensions();

/// Places the camera to frame the scene's bounds from the front, slightly above and to the right,
/// and adds a key light and a fill light near the camera. Used for bare meshes.
void fit_camera_and_lights(Scene& scene);

}  // namespace raylab
