#pragma once
/// \file
/// Eric Haines' Neutral File Format: writer.

#include <string>

#include "raylab/scene/scene.h"

namespace raylab {

/// The NFF text of `scene`: the view (`v`), background (`b`), lights (`l`), then each object's
/// material (`f`, written again only when the material changes) followed by its primitives.
/// Spheres become `s`, cylinders and cones `c`, triangles `p 3` (or `pp 3` when they carry
/// shading normals), quads `p 4` and disks 32-sided `p` polygons. Numbers are printed so that
/// parse_nff reads back exactly the same floats, so a Scene that came from NFF survives
/// load -> encode -> load unchanged. What NFF cannot say (non-point lights, an edge-to-edge field of
/// view, falloff, emission, textures, sky gradients) is approximated and noted in `#` comments.
std::string encode_nff(const Scene& scene);

}  // namespace raylab
