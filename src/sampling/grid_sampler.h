#pragma once
/// \file
/// The base of the samplers that put each sample in its own stratum of an n x n grid. Internal
/// to the library.

#include <cstdint>

#include "raylab/sampling/pixel_sampler.h"

namespace raylab {

/// A sampler of n * n samples per pixel that puts sample `index` in stratum (index % n,
/// index / n) of an n x n grid. The regular and jittered samplers differ only in where a sample
/// lies inside its stratum, so the count and the numbering of the strata are kept here, once.
class GridSampler : public PixelSampler {
 public:
  /// Strata along each axis.
  int strata() const { return m_n; }

 protected:
  /// `n` strata along each axis (n >= 1; spp = n * n).
  GridSampler(int n, std::uint64_t seed) : PixelSampler(n * n, seed), m_n(n) {}

  /// The column of the stratum that holds sample `index`.
  int column(int index) const { return index % m_n; }

  /// The row of the stratum that holds sample `index`.
  int row(int index) const { return index / m_n; }

 private:
  int m_n;
};

}  // namespace raylab
