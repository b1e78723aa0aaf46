#pragma once
/// \file
/// The per-sample random generator of the random and jittered samplers. Internal to the library.

#include <cstdint>

#include "raylab/core/rng.h"

namespace raylab::detail {

/// The generator of sample `index` of pixel (px, py) for `seed`. Hashing every coordinate
/// (rather than advancing one shared generator) is what makes a sample addressable in any
/// order; samplers that share this hash keep their streams apart by salting `seed`.
inline Pcg32 sample_rng(std::uint64_t seed, int px, int py, int index) {
  return Pcg32(hash_seed(seed, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py),
                         static_cast<std::uint64_t>(index)));
}

}  // namespace raylab::detail
