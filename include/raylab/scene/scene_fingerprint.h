#pragma once
/// \file
/// A 64-bit fingerprint of everything in a Scene that can change a rendered image: geometry,
/// objects, materials (textures included), lights, camera, camera path and settings. Two scenes
/// with the same fingerprint render the same image; a checkpoint records it so that a render is
/// never resumed over a scene that has changed since. A still (no camera path) has the fingerprint
/// it had before scenes had paths. Not cryptographic: it guards against accidents (an edited file,
/// another scene), not against someone forging a collision.

#include <cstdint>

#include "raylab/scene/scene.h"

namespace raylab {

/// The fingerprint of `scene` (its warnings excepted). Floats are hashed by their bits, so
/// +0 and -0 differ, as they may in an image.
std::uint64_t scene_fingerprint(const Scene& scene);

}  // namespace raylab
