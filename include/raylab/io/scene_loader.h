#pragma once
/// \file
/// Turning what the user named on the command line into a Scene.

#include <optional>
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

/// Ambient light of the fitted look of a bare mesh (RenderSettings::ambient, each channel).
inline constexpr float kMeshAmbient = 0.12f;

/// Samples per pixel of the fitted look of a bare mesh (jittered by the "auto" sampler).
inline constexpr int kMeshSamplesPerPixel = 4;

/// Places the camera to frame the scene's bounds from the front, slightly above and to the right
/// of a mesh standing on `up` (a unit axis; empty: detect_up_axis(), else +Y), adds a key light
/// and a fill light near the camera, and sets the look of a bare mesh: a dark background, a
/// little ambient light (kMeshAmbient) and kMeshSamplesPerPixel samples per pixel. Marks the
/// camera and lights as fitted (Scene::camera_fitted, lights_fitted). Used for bare meshes and
/// scene files without a camera (which keep their own settings and lights).
void fit_camera_and_lights(Scene& scene, std::optional<Vec3> up = std::nullopt);

}  // namespace raylab
