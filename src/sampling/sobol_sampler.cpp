#include "sobol_sampler.h"

#include "raylab/core/rng.h"
#include "raylab/sampling/seed_salts.h"
#include "raylab/sampling/stratum.h"

namespace raylab {

namespace {

/// Mirrors the 32 bits of `v`: bit 0 becomes bit 31.
constexpr std::uint32_t reverse_bits(std::uint32_t v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
  return (v >> 16) | (v << 16);
}

}  // namespace

std::uint32_t sobol_bits(std::uint32_t index, int dimension) {
  if (dimension == 0) return reverse_bits(index);
  // Dimension 1 (primitive polynomial x + 1, all initial direction numbers 1): direction number
  // j is the previous one xor itself shifted right by one, starting from 1/2, so the generator
  // matrix is Pascal's triangle modulo 2.
  std::uint32_t result = 0;
  for (std::uint32_t direction = 0x80000000u; index != 0; index >>= 1, direction ^= direction >> 1) {
    if (index & 1u) result ^= direction;
  }
  return result;
}

std::uint32_t owen_scramble(std::uint32_t bits, std::uint64_t key) {
  // After reversal the first (most significant) digit is bit 0. Every step below changes bit b
  // by a function of bits below b only: adding a constant (carries move up), xor with the value
  // times an even number, multiplication by an odd number. So digit b is flipped by a function
  // of the key and of the digits before it, which is exactly a nested uniform scramble; the
  // constant additions make the first digit's flip depend on the key.
  std::uint32_t x = reverse_bits(bits);
  for (int round = 0; round < 4; ++round) {
    key = mix64(key + static_cast<std::uint64_t>(round));
    x += static_cast<std::uint32_t>(key);
    x ^= x * (static_cast<std::uint32_t>(key >> 32) << 1);
    x *= static_cast<std::uint32_t>(key >> 31) | 1u;
  }
  return reverse_bits(x);
}

Sample2 SobolSampler::sample(int px, int py, int index) const {
  const std::uint64_t pixel_key =
      hash_seed(seed() ^ kSobolSamplerSalt, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py));
  const auto i = static_cast<std::uint32_t>(index);
  // One independent scramble per dimension: scrambling both with one key would tie them.
  const std::uint32_t x = owen_scramble(sobol_bits(i, 0), mix64(pixel_key));
  const std::uint32_t y = owen_scramble(sobol_bits(i, 1), mix64(pixel_key + 0x9e3779b97f4a7c15ull));
  // The top 24 bits decide every elementary interval up to 2^24 samples, so truncating to a
  // float keeps the net property.
  return {bits_to_unit_float(x), bits_to_unit_float(y)};
}

}  // namespace raylab
