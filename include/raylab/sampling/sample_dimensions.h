#pragma once
/// \file
/// The dimensions of a camera sample beyond its position in the pixel: what a path tracer's
/// random decisions (light choice, light point, scattering direction, Russian roulette) draw
/// from, addressed like the position by (pixel, sample index), so that an image is the same for
/// any thread count, tile order, MPI rank count and across interrupt and resume.
///
/// Layout: pair 0 is the pixel position, from the render's pixel sampler itself. Pair k >= 1
/// comes from a twin of that sampler (same kind, same spp, its own seed), with the sample
/// indices shuffled per pair and pixel (detail::shuffle, a cheap keyed bijection): within one pair the spp samples of a
/// pixel keep the sampler's stratification (jittered strata, cmj's n-rooks, Sobol's (0,2)-net), and between pairs they
/// are independent, as with pbrt's padded samplers. A jittered twin is not a JitteredGridSampler
/// object: its offsets inside the stratum come from one hash of the pair's key and the stratum
/// (the sampler's own per-sample generator costs five times as much, and a path asks for two to
/// three pairs at every vertex); the stratum rule is the same, point_in_interval. Samplers that place every pixel's
/// samples alike (center, regular) have random twins (random, jittered): a path needs random numbers. Pairs from
/// kStratifiedPairs on are independent uniform numbers.

#include <cstdint>
#include <memory>
#include <vector>

#include "raylab/sampling/pixel_sampler.h"

namespace raylab {

/// The dimension pairs of every camera sample of a render (see the file comment).
class SampleDimensions {
 public:
  /// Pairs 1 .. kStratifiedPairs - 1 are stratified; later pairs are independent numbers.
  static constexpr int kStratifiedPairs = 32;

  /// The pairs of the samples that `pixel_sampler` places.
  explicit SampleDimensions(const PixelSampler& pixel_sampler);
  ~SampleDimensions();
  SampleDimensions(SampleDimensions&&) noexcept;
  SampleDimensions& operator=(SampleDimensions&&) noexcept;

  /// Pair `k` (>= 1) of sample `index` of pixel (px, py), in [0, 1)^2.
  Sample2 pair(int k, int px, int py, int index) const { return pair(k, px, py, index, pixel_key(px, py)); }

  /// What every pair of pixel (px, py) shares: hashed once per sample by SampleSource rather
  /// than once per pair.
  std::uint64_t pixel_key(int px, int py) const;
  /// pair(k, px, py, index), with `key` = pixel_key(px, py).
  Sample2 pair(int k, int px, int py, int index, std::uint64_t key) const;

 private:
  std::vector<std::unique_ptr<PixelSampler>> m_twins;  // m_twins[k - 1] gives pair k (empty when jittered)
  int m_jittered_strata = 0;                           // n when the twins are jittered (spp = n * n), else 0
  int m_spp;
  std::uint64_t m_seed;
};

}  // namespace raylab
