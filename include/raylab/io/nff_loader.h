#pragma once
/// \file
/// Eric Haines' Neutral File Format: reader.

#include <string>
#include <string_view>

#include "raylab/scene/mesh_builder.h"
#include "raylab/scene/nff_builder.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Parses NFF `text` (named `file` in messages) entity by entity into `out`. Throws InputError
/// `file:line:col: ...` on the first malformed entity. Does not call out.finish().
void parse_nff(std::string_view text, const std::string& file, NffSceneBuilder& out);

/// Loads NFF file `path` into `scene` (which should be empty); returns what polygons were added
/// and dropped.
MeshLoadReport load_nff(const std::string& path, Scene& scene);

}  // namespace raylab
