#pragma once
/// \file
/// raylab's own scene format (`.json`), documented in docs/scene-format.md and described by the
/// JSON Schema scenes/scene.schema.json.

#include <string>
#include <string_view>

#include "raylab/io/scene_paths.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// The scene-format version this build reads.
inline constexpr int kSceneFormatVersion = 1;

/// Loads scene file `path`. Relative paths inside resolve against the file's folder.
Scene load_scene_json(const std::string& path, const LoadOptions& options = {});

/// Parses scene JSON `text` (named `file` in messages; references resolve against `base_dir`).
/// Throws InputError `file:line:col: ...` for a syntax error, an unknown key (naming the valid
/// ones), a value of the wrong type or out of range, an unknown material or mesh name, or a
/// referenced file that is refused or bad.
Scene parse_scene_json(std::string_view text, const std::string& file, const std::string& base_dir,
                       const LoadOptions& options = {});

}  // namespace raylab
