#pragma once
/// \file
/// The salts that keep the library's random streams apart, in one place. Every random choice is
/// a hash of the render's seed and of where it is made (pixel, sample index, ...); two streams
/// that hashed the same arguments would draw the same numbers and correlate (a sample's light
/// choice tied to its position, say). Each stream therefore xors its own salt into the seed
/// first, or, for the ray sets, passes its stream tag as an extra hash argument.
///
/// The values are fixed: every image depends on them, and the reference images under tests/
/// and docs/ with them. A new stream takes a new value, added to kAllSeedSalts below, where a
/// compile-time check keeps them distinct.

#include <array>
#include <cstddef>
#include <cstdint>

namespace raylab {

/// The seed as it is. Three streams predate the salts and keep the plain seed, because reference
/// images depend on their values: the jittered sampler's positions, the adaptive sampler's
/// jittered cells below its 16-sample pattern, and the SPD protocol's generators at the pixel
/// corners. No two of them run in the same render, so they cannot correlate; xoring this salt
/// changes nothing but marks the stream as one of the three.
inline constexpr std::uint64_t kUnsaltedSeed = 0;

/// The random sampler's positions, apart from the jittered sampler's, which hash the same
/// (seed, pixel, index) unsalted.
inline constexpr std::uint64_t kRandomSamplerSalt = 0x7a4d0c3e91b25f68ull;

/// The cmj sampler's per-pixel permutations and jitter, apart from the other samplers'.
inline constexpr std::uint64_t kCmjSamplerSalt = 0x3c6ef372fe94f82bull;

/// The Sobol' sampler's per-pixel scrambles, apart from the other samplers'.
inline constexpr std::uint64_t kSobolSamplerSalt = 0xa54ff53a5f1d36f1ull;

/// The other random decisions along a sample of the uniform samplers (area-light points:
/// sample_path_seed()), apart from the sample's own position.
inline constexpr std::uint64_t kSamplePathSalt = 0x5eedf00dull;

/// The key of a pixel's MultiJitteredPattern (the adaptive sampler's first 16 positions).
inline constexpr std::uint64_t kMultiJitteredPatternSalt = 0x3a17ull;

/// Which of its 16 pattern samples the adaptive sampler traces first in a pixel, apart from
/// the pattern's positions, so that choice is not tied to where the samples lie.
inline constexpr std::uint64_t kAdaptiveBaseSampleSalt = 0xba5eull;

/// The other random decisions along the adaptive sampler's samples (area-light points), apart
/// from the samples' positions.
inline constexpr std::uint64_t kAdaptivePathSalt = 0xada9717eull;

/// The random decisions at the points of the adaptive-corners lattice (area-light points),
/// seeded by the lattice point so that a corner shared by two pixels has one colour.
inline constexpr std::uint64_t kAdaptiveCornersPathSalt = 0xc0e7e5ull;

/// The ray sets' light sample at a primary hit (raylab bench's shadow rays): a stream tag,
/// hashed after (pixel, seed), apart from the same hit's bounce.
inline constexpr std::uint64_t kRaySetLightStream = 1;

/// The ray sets' cosine-weighted bounce at a primary hit (raylab bench's diffuse rays): a
/// stream tag, hashed after (pixel, seed), apart from the same hit's light sample.
inline constexpr std::uint64_t kRaySetBounceStream = 2;

/// The seeds of the twin samplers that give a path its dimension pairs beyond the pixel
/// position (SampleDimensions), apart from the pixel sampler's own seed.
inline constexpr std::uint64_t kSampleDimensionSalt = 0xd1e5a3b7c0f24689ull;

/// The shuffle of sample indices per dimension pair (SampleDimensions), so that sample i's
/// stratum in one pair says nothing of its stratum in another.
inline constexpr std::uint64_t kDimensionShuffleSalt = 0x6b43a9b5e1f0d27cull;

/// The independent numbers of the dimension pairs past the stratified ones (SampleDimensions).
inline constexpr std::uint64_t kDeepDimensionSalt = 0x2f8e6d4c1a0b9375ull;

/// Every salt and stream tag above, for the distinctness check; a new one must be added here.
inline constexpr std::array kAllSeedSalts = {kUnsaltedSeed,           kRandomSamplerSalt,  kCmjSamplerSalt,
                                             kSobolSamplerSalt,       kSamplePathSalt,     kMultiJitteredPatternSalt,
                                             kAdaptiveBaseSampleSalt, kAdaptivePathSalt,   kAdaptiveCornersPathSalt,
                                             kRaySetLightStream,      kRaySetBounceStream, kSampleDimensionSalt,
                                             kDimensionShuffleSalt,   kDeepDimensionSalt};

// Two equal values would make two streams draw the same numbers.
static_assert(
    [] {
      for (std::size_t i = 0; i < kAllSeedSalts.size(); ++i) {
        for (std::size_t j = i + 1; j < kAllSeedSalts.size(); ++j) {
          if (kAllSeedSalts[i] == kAllSeedSalts[j]) return false;
        }
      }
      return true;
    }(),
    "two random streams share a salt: give the new one its own value");

}  // namespace raylab
