#pragma once
/// \file
/// Where files named inside a scene file may come from.

#include <string>

namespace raylab {

/// Options every loader that follows references to other files takes.
struct LoadOptions {
  /// Allow references (meshes, textures, glTF buffers) that leave the folder of the file that
  /// names them. Off by default: a scene file from elsewhere must not read arbitrary files.
  bool allow_outside_paths = false;
  /// When positive, the largest size an SPD generator object in a scene file may ask for (its
  /// default size counts when it gives none); 0: each generator's own limit. For callers that
  /// must bound the work an untrusted file can ask for (the fuzzer: sphereflakes grow 9-fold per
  /// size step).
  int max_spd_size = 0;
};

/// Resolves `reference` (relative to `base_dir`, or absolute) to a path. Returns an empty string
/// when the result leaves `base_dir` (after resolving `..` and symbolic links) and
/// `allow_outside` is false; the caller reports that with its own position.
std::string resolve_scene_path(const std::string& base_dir, const std::string& reference, bool allow_outside);

/// The folder holding `file` ("." for a bare file name).
std::string folder_of(const std::string& file);

}  // namespace raylab
