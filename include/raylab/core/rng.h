#pragma once
/// \file
/// PCG32 random numbers and the hashing that makes every sample addressable.

#include <cstdint>

namespace raylab {

/// 64-bit finaliser (SplitMix64 / Stafford variant 13): a good bijective mixer, used to derive
/// independent seeds from (pixel, sample index, seed) without any shared state.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/// Hashes up to four integers into one 64-bit seed.
constexpr std::uint64_t hash_seed(std::uint64_t a, std::uint64_t b = 0, std::uint64_t c = 0, std::uint64_t d = 0) {
  std::uint64_t h = mix64(a + 0x9e3779b97f4a7c15ull);
  h = mix64(h ^ (b + 0x9e3779b97f4a7c15ull));
  h = mix64(h ^ (c + 0x9e3779b97f4a7c15ull));
  return mix64(h ^ (d + 0x9e3779b97f4a7c15ull));
}

/// O'Neill's PCG32 (XSH-RR, 64-bit state): small, fast, statistically strong, and seekable by
/// choosing the stream. Deterministic for a given (seed, stream).
class Pcg32 {
 public:
  /// Seeds the generator; different `stream` values give independent sequences.
  explicit constexpr Pcg32(std::uint64_t seed = 0x853c49e6748fea9bull, std::uint64_t stream = 0xda3e39cb94b95bdbull)
      : m_state(0), m_inc((stream << 1u) | 1u) {
    next_u32();
    m_state += seed;
    next_u32();
  }

  /// Next uniformly distributed 32-bit integer.
  constexpr std::uint32_t next_u32() {
    const std::uint64_t old = m_state;
    m_state = old * 6364136223846793005ull + m_inc;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
  }

  /// Next float uniformly distributed in [0, 1) (24 random bits, never returns 1).
  constexpr float next_float() { return static_cast<float>(next_u32() >> 8) * 0x1p-24f; }

 private:
  std::uint64_t m_state;
  std::uint64_t m_inc;
};

}  // namespace raylab
