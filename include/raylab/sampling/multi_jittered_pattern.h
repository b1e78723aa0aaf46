#pragma once
/// \file
/// The 16-sample multi-jittered pattern of a pixel (Chiu, Shirley and Wang 1994), from which the
/// adaptive sampler takes the positions of its first two refinement levels.

#include <cstdint>

#include "raylab/sampling/pixel_sampler.h"  // Sample2

namespace raylab {

/// A pixel's multi-jittered pattern of 16 samples: one in each cell of a 4 x 4 grid, like
/// 16-sample jittered sampling, and also one in each of the 16 columns and 16 rows of width
/// 1/16, which halves the error on edges near the axes. Per column of cells a random ordering of
/// the four sub-columns its cells use, per row of cells one of the four sub-rows, and a uniform
/// offset in each sample's 1/16 x 1/16 square. The pattern is keyed by (seed, pixel), and each
/// sample is computable on its own, in any order.
class MultiJitteredPattern {
 public:
  /// Samples in the pattern.
  static constexpr int kSize = 16;

  /// The pattern of pixel (px, py) for `seed`.
  MultiJitteredPattern(std::uint64_t seed, int px, int py);

  /// Sample `i` (0 <= i < kSize), in [0, 1)^2: it lies in cell (i % 4, i / 4) of the 4 x 4 grid.
  Sample2 sample(int i) const;

 private:
  std::uint64_t m_key;
};

}  // namespace raylab
