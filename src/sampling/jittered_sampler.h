#pragma once
/// \file
/// Jittered (stratified) sampling. Internal to the library; created by name through
/// make_pixel_sampler().

#include <cstdint>

#include "grid_sampler.h"
#include "raylab/sampling/pixel_sampler.h"

namespace raylab {

/// Jittered (stratified) sampling: an n x n grid of strata, one uniform random sample in each.
/// Sample `index` lies in column index % n, row index / n. The positions are those of the
/// renderer's original JitteredSampler for square counts (same hash, same PCG32 draws), except
/// that one sample per pixel is jittered over the whole pixel instead of put at its centre.
class JitteredGridSampler final : public GridSampler {
 public:
  /// `n` strata along each axis (n >= 1; spp = n * n).
  JitteredGridSampler(int n, std::uint64_t seed) : GridSampler(n, seed) {}
  /// A uniform position inside stratum (index % n, index / n).
  Sample2 sample(int px, int py, int index) const override;
  /// "jittered".
  std::string_view name() const override { return "jittered"; }
};

}  // namespace raylab
