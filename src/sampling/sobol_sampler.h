#pragma once
/// \file
/// Owen-scrambled Sobol' (0,2)-sequence samples. Internal to the library; created by name
/// through make_pixel_sampler().

#include <cstdint>

#include "raylab/sampling/pixel_sampler.h"

namespace raylab {

/// The first two dimensions of the Sobol' sequence (van der Corput in base 2, then Sobol's
/// second dimension), Owen-scrambled by a hash keyed per (pixel, seed, dimension). With
/// spp = 2^k the samples of a pixel form a (0, k, 2)-net: each elementary interval of area
/// 1 / spp (2^a x 2^b cells with a + b = k) holds exactly one sample. Scrambling keeps that
/// property and gives every pixel its own, unbiased pattern.
class SobolSampler final : public PixelSampler {
 public:
  /// `spp` must be a power of two.
  SobolSampler(int spp, std::uint64_t seed) : PixelSampler(spp, seed) {}
  /// Sample `index` of pixel (px, py).
  Sample2 sample(int px, int py, int index) const override;
  /// "sobol".
  std::string_view name() const override { return "sobol"; }
};

/// Unscrambled Sobol' point `index` in dimension 0 (van der Corput) or 1, as a 32-bit binary
/// fraction (the value is bits / 2^32).
std::uint32_t sobol_bits(std::uint32_t index, int dimension);

/// Nested uniform (Owen) scramble of the 32-bit binary fraction `bits`, keyed by `key`: each
/// digit is flipped or not by a hash of the key and of the digits above it.
std::uint32_t owen_scramble(std::uint32_t bits, std::uint64_t key);

}  // namespace raylab
