#pragma once
// Pearson's chi-square test of a histogram of samples against the counts a density predicts:
// what checks that a sampler draws from the density it reports.

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <sstream>
#include <string>

namespace raylab::test {

/// The outcome of a chi-square test.
struct ChiSquare {
  double statistic = 0.0;  ///< sum of (observed - expected)^2 / expected over the pooled cells
  int dof = 0;             ///< degrees of freedom: pooled cells - 1
  double critical = 0.0;   ///< the statistic's upper 1% point for `dof`
  std::string problem;     ///< why the histogram cannot come from the density ("" when none)

  /// True when the histogram is consistent with the density at significance 0.01.
  bool pass() const { return problem.empty() && statistic <= critical; }
  /// The numbers, for a failure message.
  std::string describe() const {
    std::ostringstream s;
    s << "chi^2 = " << statistic << " with " << dof << " dof (1% critical value " << critical << ")";
    if (!problem.empty()) s << "; " << problem;
    return s.str();
  }
};

/// The upper 1% point of the chi-square distribution with `dof` >= 1 degrees of freedom, by
/// Wilson and Hilferty's cube-root normal approximation (within 1% of the exact value for every
/// dof; 6.59 against 6.63 at 1 dof, 21.70 against 21.67 at 9).
inline double chi_square_critical_1_percent(int dof) {
  const double k = dof;
  const double z = 2.3263478740408408;  // standard normal upper 1% point
  const double c = 1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k));
  return k * c * c * c;
}

/// Pearson's test of `observed` counts against `expected` ones (same length, expected summing to
/// the number of samples). Cells expecting fewer than 5 samples are pooled into one, as the test's
/// approximation needs; a sample in a cell of expectation 0 is a problem by itself.
inline ChiSquare chi_square_test(std::span<const double> observed, std::span<const double> expected) {
  ChiSquare result;
  double pooled_observed = 0.0, pooled_expected = 0.0;
  int cells = 0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] <= 0.0 && observed[i] > 0.0 && result.problem.empty()) {
      result.problem = std::to_string(observed[i]) + " samples in cell " + std::to_string(i) + " of density 0";
    }
    if (expected[i] < 5.0) {
      pooled_observed += observed[i];
      pooled_expected += expected[i];
      continue;
    }
    const double d = observed[i] - expected[i];
    result.statistic += d * d / expected[i];
    ++cells;
  }
  if (pooled_expected > 0.0) {
    const double d = pooled_observed - pooled_expected;
    result.statistic += d * d / pooled_expected;
    ++cells;
  }
  result.dof = cells - 1;
  if (result.dof < 1) {
    result.problem = "fewer than two cells to compare";
    result.critical = std::numeric_limits<double>::infinity();
    return result;
  }
  result.critical = chi_square_critical_1_percent(result.dof);
  return result;
}

}  // namespace raylab::test
