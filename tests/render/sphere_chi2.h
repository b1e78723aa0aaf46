#pragma once
// Chi-square goodness-of-fit of a sampler of directions against the density it claims, as
// pbrt-v4 and Mitsuba 3 test their BSDFs: a histogram of sampled directions over a grid on the
// sphere, the density integrated over each cell by Gauss-Legendre quadrature, cells expected to
// hold fewer than 5 samples pooled, and Pearson's statistic turned into a p-value by the
// regularised incomplete gamma function. Any direction sampler can use it (BSDFs, lights).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "raylab/core/vec3.h"

namespace raylab::test {

/// The upper regularised incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a), the
/// p-value of a chi-square statistic 2x with 2a degrees of freedom: the series of P = 1 - Q
/// below x = a + 1, Lentz's continued fraction for Q above (each converges fast on its side).
inline double gamma_q(double a, double x) {
  if (x <= 0.) return 1.;
  const double log_prefix = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.) {
    double term = 1. / a;
    double sum = term;
    for (int n = 1; n < 100000 && std::fabs(term) > 1e-16 * std::fabs(sum); ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return 1. - sum * std::exp(log_prefix);
  }
  constexpr double kTiny = 1e-300;
  double b = x + 1. - a;
  double c = 1. / kTiny;
  double d = 1. / b;
  double h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.;
    d = an * d + b;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1. / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.) < 1e-15) break;
  }
  return std::exp(log_prefix) * h;
}

/// The unit vector at polar angle `theta` from +z and azimuth `phi`.
inline Vec3 spherical(double theta, double phi) {
  return {static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::sin(theta) * std::sin(phi)),
          static_cast<float>(std::cos(theta))};
}

/// Integral of f(theta, phi) sin(theta) over [t0, t1] x [p0, p1], each side cut into `split`
/// parts with five Gauss-Legendre nodes each. Gauss rather than Simpson: it never evaluates the
/// edges, where a density may jump (the horizon).
template <class F>
double integrate_on_sphere(F f, double t0, double t1, double p0, double p1, int split) {
  constexpr std::array<double, 5> kNodes{-0.9061798459386640, -0.5384693101056831, 0., 0.5384693101056831,
                                         0.9061798459386640};
  constexpr std::array<double, 5> kWeights{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                           0.4786286704993665, 0.2369268850561891};
  double sum = 0.;
  const double ht = (t1 - t0) / split;
  const double hp = (p1 - p0) / split;
  for (int a = 0; a < split; ++a) {
    for (int b = 0; b < split; ++b) {
      for (std::size_t i = 0; i < kNodes.size(); ++i) {
        const double t = t0 + ht * (a + 0.5 * (kNodes[i] + 1.));
        for (std::size_t j = 0; j < kNodes.size(); ++j) {
          const double p = p0 + hp * (b + 0.5 * (kNodes[j] + 1.));
          sum += kWeights[i] * kWeights[j] * f(t, p) * std::sin(t);
        }
      }
    }
  }
  return sum * 0.25 * ht * hp;
}

/// The sphere cut into theta_cells x phi_cells cells, equal in angle (theta from +z; with an
/// even theta_cells the horizon, where densities jump, is a cell boundary), plus one last cell
/// for the outcomes the density does not describe: no sample, or a delta lobe.
struct SphereGrid {
  int theta_cells = 32;  ///< cells in polar angle
  int phi_cells = 64;    ///< cells in azimuth

  /// Number of cells, the last one included.
  int cells() const { return theta_cells * phi_cells + 1; }

  /// The cell holding unit direction `w`.
  int cell_of(Vec3 w) const {
    constexpr double kPi = std::numbers::pi;
    const double theta = std::acos(std::clamp(static_cast<double>(w.z), -1., 1.));
    double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x));
    if (phi < 0.) phi += 2. * kPi;
    const int i = std::min(static_cast<int>(theta / kPi * theta_cells), theta_cells - 1);
    const int j = std::min(static_cast<int>(phi / (2. * kPi) * phi_cells), phi_cells - 1);
    return i * phi_cells + j;
  }
};

/// Histogram of `samples` calls of draw(), which returns std::optional<Vec3>: std::nullopt for
/// an outcome the density does not describe (counted in the grid's last cell).
template <class Draw>
std::vector<double> observed_counts(const SphereGrid& grid, int samples, Draw draw) {
  std::vector<double> counts(static_cast<std::size_t>(grid.cells()), 0.);
  for (int n = 0; n < samples; ++n) {
    const std::optional<Vec3> w = draw();
    ++counts[static_cast<std::size_t>(w ? grid.cell_of(*w) : grid.cells() - 1)];
  }
  return counts;
}

/// Expected histogram of `samples` draws from the density pdf(Vec3) over the sphere; the last
/// cell gets what the density leaves of the total. Each cell side is cut into `split` parts for
/// the quadrature: more for a density with edges inside cells (a light's outline), where the
/// quadrature's error would otherwise be what the test detects.
template <class Pdf>
std::vector<double> expected_counts(const SphereGrid& grid, int samples, Pdf pdf, int split = 2) {
  constexpr double kPi = std::numbers::pi;
  std::vector<double> expected(static_cast<std::size_t>(grid.cells()), 0.);
  const double dt = kPi / grid.theta_cells;
  const double dp = 2. * kPi / grid.phi_cells;
  const auto density = [&](double t, double p) { return static_cast<double>(pdf(spherical(t, p))); };
  double total = 0.;
  for (int i = 0; i < grid.theta_cells; ++i) {
    for (int j = 0; j < grid.phi_cells; ++j) {
      const double e = samples * integrate_on_sphere(density, i * dt, (i + 1) * dt, j * dp, (j + 1) * dp, split);
      expected[static_cast<std::size_t>(i * grid.phi_cells + j)] = e;
      total += e;
    }
  }
  expected.back() = std::max(0., samples - total);
  return expected;
}

/// Outcome of Pearson's test.
struct Chi2Result {
  double p_value = 0.;    ///< probability of a statistic this large if the density is right
  double statistic = 0.;  ///< sum of (observed - expected)^2 / expected
  int dof = 0;            ///< degrees of freedom: cells after pooling, less one
  std::string failure;    ///< non-empty when the test cannot be run fairly (samples where the
                          ///< density is 0, or too few cells)
};

/// Pearson's test of `observed` against `expected` (of equal totals). Cells expected to hold
/// fewer than 5 samples are pooled, adding the next smallest cells until the pool reaches 5, so
/// that the chi-square approximation holds.
inline Chi2Result pearson(const std::vector<double>& observed, const std::vector<double>& expected) {
  Chi2Result r;
  std::vector<std::size_t> order(observed.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
  double pool_expected = 0.;
  double pool_observed = 0.;
  std::size_t k = 0;
  for (; k < order.size() && (expected[order[k]] < 5. || pool_expected < 5.); ++k) {
    const std::size_t c = order[k];
    if (expected[c] == 0. && observed[c] > 0.) {
      r.failure = std::to_string(observed[c]) + " samples in cell " + std::to_string(c) + " of density 0";
      return r;
    }
    pool_expected += expected[c];
    pool_observed += observed[c];
  }
  int cells = 0;
  if (pool_expected > 0.) {
    r.statistic += (pool_observed - pool_expected) * (pool_observed - pool_expected) / pool_expected;
    ++cells;
  }
  for (; k < order.size(); ++k) {
    const std::size_t c = order[k];
    r.statistic += (observed[c] - expected[c]) * (observed[c] - expected[c]) / expected[c];
    ++cells;
  }
  r.dof = cells - 1;
  if (r.dof < 1) {
    r.failure = "fewer than two cells";
    return r;
  }
  r.p_value = gamma_q(0.5 * r.dof, 0.5 * r.statistic);
  return r;
}

}  // namespace raylab::test
