#pragma once
/// \file
/// Jittered (stratified) pixel samples, addressable by (pixel, sample index, seed).

#include <cstdint>

#include "raylab/sampling/pixel_sampler.h"

namespace raylab {

/// Jittered sampling: `spp` samples laid on the most nearly square nx * ny grid with
/// nx * ny == spp (a 1 x spp strip for primes), one uniformly random sample per stratum.
/// Stateless and deterministic: sample `index` of pixel (px, py) depends only on its arguments,
/// so images do not depend on thread count or tile order.
class JitteredSampler {
 public:
  /// A sampler for `spp` samples per pixel (spp >= 1) and global `seed`.
  JitteredSampler(int spp, std::uint64_t seed);

  /// Position of sample `index` (0 <= index < spp) within pixel (px, py), in [0, 1)^2.
  Sample2 pixel_sample(int px, int py, int index) const;

  /// A seed for the other random decisions made along sample `index` of pixel (px, py)
  /// (area light samples), independent of the position.
  std::uint64_t path_seed(int px, int py, int index) const;

  /// Samples per pixel.
  int spp() const { return m_spp; }
  /// Strata along x and y (nx * ny == spp).
  int strata_x() const { return m_nx; }
  /// Strata along y.
  int strata_y() const { return m_ny; }

 private:
  int m_spp;
  int m_nx;
  int m_ny;
  std::uint64_t m_seed;
};

}  // namespace raylab
