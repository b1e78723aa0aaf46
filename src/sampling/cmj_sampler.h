#pragma once
/// \file
/// Correlated multi-jittered sampling (Kensler 2013). Internal to the library; created by name
/// through make_pixel_sampler().

#include "raylab/sampling/pixel_sampler.h"

namespace raylab {

/// Correlated multi-jittered samples: N = cols * rows samples, with rows the largest divisor of
/// N not above sqrt(N) and cols = N / rows (wider than tall; a 1-row strip when N is prime).
/// The pattern is stratified three ways at once: one sample in each of the cols x rows cells,
/// one in each of the N columns of width 1/N, and one in each of the N rows of height 1/N.
/// Rows and columns are shuffled by hash-based permutations keyed per pixel, so every pixel has
/// its own pattern; the sub-cell shuffle is shared by all cells of a row or column (that is the
/// "correlated" part, which keeps the samples evenly spread in 2D as well).
class CmjSampler final : public PixelSampler {
 public:
  /// Any `spp` >= 1.
  CmjSampler(int spp, std::uint64_t seed);
  /// Sample `index` of pixel (px, py).
  Sample2 sample(int px, int py, int index) const override;
  /// "cmj".
  std::string_view name() const override { return "cmj"; }

  /// Cells along x.
  int cols() const { return m_cols; }
  /// Cells along y.
  int rows() const { return m_rows; }

 private:
  int m_cols;
  int m_rows;
};

}  // namespace raylab
