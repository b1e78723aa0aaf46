#pragma once
/// \file
/// The reference image of `raylab quality`: read from a file the user names, or rendered once
/// and cached on disk ("auto"), keyed by everything that changes it.

#include <functional>
#include <string>

#include "raylab/accel/accelerator.h"
#include "raylab/lab/quality_study.h"
#include "raylab/render/film.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// The folder where auto references are cached when none is given:
/// $XDG_CACHE_HOME/raylab/references, else $HOME/.cache/raylab/references, else
/// .raylab-cache (in the working folder). Empty variables count as unset.
std::string default_reference_cache_dir();

/// A key naming a scene source for the reference cache: `source` itself, followed by
/// " hash64:" and 16 hex digits of Hash64::of of the file's bytes when `source` is a regular file.
/// Only the named file is hashed: a mesh that a scene file references can change unseen (then
/// delete the cached reference or pass --reference); built-in scenes and generators are keyed
/// by name (their code changing bumps kReferenceFormatVersion).
std::string scene_source_key(const std::string& source);

/// Reads a user-given reference image (.exr or .pfm: linear floats; an 8-bit PNG would clip and
/// quantise the very errors being measured). Throws UsageError for another extension and
/// InputError naming the file when it cannot be read.
Film load_reference_file(const std::string& path);

/// Where a reference came from.
struct ReferenceImage {
  Film film{0, 0};
  std::string path;         ///< the file read or written; empty when rendered and not cached
  bool from_cache = false;  ///< an auto reference found in the cache
  bool rendered = false;    ///< rendered by this call
  /// For the report: "REF.exr", "auto: 1024 spp jittered, cached at PATH" and the like.
  std::string description;
};

/// The reference of a study of `scene` (whose settings give size, filter and depth):
///  - options.reference is a path: load_reference_file, then its size is checked;
///  - "auto": options.cache_dir/reference_file_name(...) when that file exists and reads as an
///    image of the right size; otherwise rendered (render_reference with `accel`) and, when
///    cache_dir is set, written there atomically (the folder is created and checked for
///    writing before the render starts).
/// Throws InputError naming both sizes when a reference file is not the scene's image size,
/// and InputError when the cache folder cannot be made or written. `on_progress` gets the
/// reference render's (tiles done, tiles total) and may be empty.
ReferenceImage obtain_reference(const Scene& scene, const Accelerator& accel, const QualityOptions& options,
                                const std::function<void(int, int)>& on_progress = {});

}  // namespace raylab
