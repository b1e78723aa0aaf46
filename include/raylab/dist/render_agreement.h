#pragma once
/// \file
/// What the ranks of a distributed render must agree on before any work is exchanged.

#include <cstdint>

#include "raylab/io/checkpoint_file.h"

namespace raylab::dist {

/// A hash of everything that decides the image, as a checkpoint header records it (the scene's
/// fingerprint, the settings' names and values): DistributedOptions::agreement.
std::uint64_t render_agreement(const RenderCheckpoint& header);

}  // namespace raylab::dist
