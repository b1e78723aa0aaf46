#pragma once
/// \file
/// Eric Haines' Standard Procedural Databases (SPD 3.14), built in: `spd:NAME` or
/// `spd:NAME?size=N` wherever a scene is accepted.

#include <span>
#include <string>
#include <string_view>

#include "raylab/scene/nff_builder.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// One SPD generator.
struct SpdGenerator {
  std::string_view name;         ///< "balls", "gears", ...
  std::string_view description;  ///< one line for --list-scenes
  int default_size;              ///< the SPD program's default size factor
  int max_size;                  ///< largest size accepted (beyond it the scene would not fit in memory)
  /// Emits the scene at size factor `size` (1..max_size) through `out`, in the SPD program's order.
  void (*generate)(int size, NffSceneBuilder& out);
};

/// The seven generators, in alphabetical order.
std::span<const SpdGenerator> spd_generators();

/// True when `source` starts with "spd:".
bool is_spd_source(std::string_view source);

/// A generator and the size factor a source asks it for.
struct SpdSource {
  const SpdGenerator* generator = nullptr;  ///< never null once parsed
  int size = 0;                             ///< 1..generator->max_size
};

/// The generator and size `source` names ("spd:balls" is balls at its default size,
/// "spd:balls?size=6" at size 6). Throws UsageError for an unknown name, an unknown parameter,
/// or a size out of range, listing what is valid.
SpdSource parse_spd_source(std::string_view source);

/// Builds the scene `source` names (see parse_spd_source, which throws the same errors).
Scene make_spd_scene(std::string_view source);

}  // namespace raylab
