#pragma once
/// \file
/// Piecewise-constant densities over [0, 1) and [0, 1)^2, sampled by inverting their cumulative
/// distribution: what importance-samples an environment image by its brightness.
///
/// The cumulative distribution is summed in double and stored in float, and the density a
/// sampler reports is the width of a bin's step of that stored CDF (times the bin count), not
/// the weight the caller gave. The two agree to float rounding for every bin that matters; where
/// they do not (a bin holding less than about 2^-24 of the total), the stored CDF is what the
/// sampler really does, so reporting it keeps estimates f / pdf unbiased: a bin too small to be
/// drawn reports density 0 rather than a density it never delivers.

#include <span>
#include <vector>

#include "raylab/sampling/pixel_sampler.h"

namespace raylab {

/// The most bins a distribution may have along one axis: above 2^24 some bins of [0, 1) would
/// hold no float at all, and a sample could not land inside the bin it picked.
inline constexpr int kMaxDistributionBins = 1 << 24;

/// The bin of [0, 1) cut into `n` (1..kMaxDistributionBins) equal bins that holds `x`:
/// floor(x * n), clamped to [0, n - 1]; NaN and negative x give 0. The one rule by which a
/// sample, its density and any lookup keyed on the same bins (a texel) find their bin.
int piecewise_bin(float x, int n);

/// A piecewise-constant density over [0, 1) with `n` equal bins, each of density proportional
/// to its weight. Immutable after construction; sampling allocates nothing.
class Distribution1D {
 public:
  /// A point drawn from the distribution.
  struct Sample {
    float x = 0.f;    ///< in [0, 1), inside bin `index` (piecewise_bin(x, size()) == index)
    float pdf = 0.f;  ///< density at x, equal to pdf(x) bit for bit
    int index = 0;    ///< the bin drawn
  };

  /// A distribution over weights.size() (1..kMaxDistributionBins) bins. Weights must be finite
  /// and >= 0; when they are all 0 the distribution is uniform (integral() stays 0). Throws
  /// std::invalid_argument for an empty or oversized span or a negative or non-finite weight.
  explicit Distribution1D(std::span<const float> weights);

  /// Maps `u` in [0, 1) to a point: the bin whose CDF step holds u (never a bin of zero
  /// probability), then the position of u within that step, linearly. Monotone in u, so
  /// stratified u give stratified points. u outside [0, 1) or NaN is clamped into it.
  Sample sample_continuous(float u) const;

  /// The density sample_continuous() draws x with; 0 in a bin of zero weight.
  float pdf(float x) const;

  /// The integral over [0, 1) of the step function the weights define: their mean.
  float integral() const { return m_integral; }

  /// Number of bins.
  int size() const { return static_cast<int>(m_cdf.size()) - 1; }

 private:
  std::vector<float> m_cdf;  // size() + 1 entries, m_cdf[0] = 0, m_cdf[size()] = 1
  float m_integral = 0.f;
};

/// A piecewise-constant density over [0, 1)^2 on a width x height grid of cells, sampled as a
/// marginal density over rows times a conditional density over the columns of the chosen row.
/// x runs along a row (columns), y across rows: row 0 covers y in [0, 1 / height).
class Distribution2D {
 public:
  /// A point drawn from the distribution.
  struct Sample {
    Sample2 point;    ///< in [0, 1)^2
    float pdf = 0.f;  ///< density at point, equal to pdf(point) bit for bit
  };

  /// A distribution over `weights`: width x height values, row-major from row 0, each finite
  /// and >= 0 (all 0 gives the uniform density). Throws std::invalid_argument when the sizes do
  /// not match, are not positive or exceed kMaxDistributionBins, or for a bad weight.
  Distribution2D(std::span<const float> weights, int width, int height);

  /// Maps `u` to a point: the row from u.y by the marginal, the column from u.x by that row's
  /// conditional. Monotone in each coordinate; clamps u into [0, 1)^2 like Distribution1D.
  Sample sample(Sample2 u) const;

  /// The density sample() draws `point` with: marginal(row) * conditional(column | row).
  float pdf(Sample2 point) const;

  /// The integral over [0, 1)^2 of the step function the weights define: their mean.
  float integral() const { return m_marginal.integral(); }

  /// Cells per row.
  int width() const { return m_width; }
  /// Rows.
  int height() const { return m_height; }

 private:
  int m_width;
  int m_height;
  Distribution1D m_marginal;         // over rows, weighted by each row's integral
  std::vector<float> m_conditional;  // height rows of width + 1 CDF entries, in one block
};

}  // namespace raylab
