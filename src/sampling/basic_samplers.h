#pragma once
/// \file
/// The simple pixel samplers: center, regular grid and independent random. Jittered sampling
/// has its own file (jittered_sampler.h).
/// Internal to the library; created by name through make_pixel_sampler().

#include <cstdint>

#include "grid_sampler.h"
#include "raylab/sampling/pixel_sampler.h"

namespace raylab {

/// One sample per pixel, at its centre: the classic one ray per pixel.
class CenterSampler final : public PixelSampler {
 public:
  /// `spp` must be 1.
  explicit CenterSampler(std::uint64_t seed) : PixelSampler(1, seed) {}
  /// Always (0.5, 0.5).
  Sample2 sample(int px, int py, int index) const override;
  /// "center".
  std::string_view name() const override { return "center"; }
};

/// n * n samples at the centres of an n x n grid of strata, the same in every pixel. Sample
/// `index` lies in column index % n, row index / n.
class RegularSampler final : public GridSampler {
 public:
  /// `n` strata along each axis (n >= 1; spp = n * n).
  RegularSampler(int n, std::uint64_t seed) : GridSampler(n, seed) {}
  /// The centre of stratum (index % n, index / n).
  Sample2 sample(int px, int py, int index) const override;
  /// "regular".
  std::string_view name() const override { return "regular"; }
};

/// Independent uniform samples: each (pixel, index, seed) hashes to its own random position.
class RandomSampler final : public PixelSampler {
 public:
  /// Any `spp` >= 1.
  RandomSampler(int spp, std::uint64_t seed) : PixelSampler(spp, seed) {}
  /// A uniform position, independent of every other (pixel, index).
  Sample2 sample(int px, int py, int index) const override;
  /// "random".
  std::string_view name() const override { return "random"; }
};

}  // namespace raylab
