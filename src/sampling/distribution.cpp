#include "raylab/sampling/distribution.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace raylab {
namespace {

// The largest float below 1: where a sample in [0, 1) ends.
constexpr float kOneBelow = 0x1.fffffep-1f;

// Returns `n` when a distribution may have that many bins along one axis; throws otherwise.
std::size_t check_bin_count(std::size_t n, const char* what) {
  if (n == 0 || n > static_cast<std::size_t>(kMaxDistributionBins)) {
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(n) + " bins (need 1 to 2^24)");
  }
  return n;
}

// Throws unless `w` can weigh a bin; returns it as a double for the sums.
double checked_weight(float w) {
  if (!(w >= 0.f) || !std::isfinite(w)) {
    throw std::invalid_argument("distribution weight " + std::to_string(w) + " is negative or not finite");
  }
  return w;
}

// Writes the CDF of `weights` into `cdf` (weights.size() + 1 entries) and returns the sum of the
// weights. The running sum is kept in double: a float sum would drop small weights after large
// ones and could overflow on weights near FLT_MAX. All-zero weights give the uniform CDF.
double build_cdf(std::span<const float> weights, std::span<float> cdf) {
  const std::size_t n = weights.size();
  double sum = 0.0;
  for (float w : weights) sum += checked_weight(w);
  double running = 0.0;
  cdf[0] = 0.f;
  for (std::size_t i = 1; i < n; ++i) {
    running += sum > 0.0 ? static_cast<double>(weights[i - 1]) : 1.0;
    cdf[i] = static_cast<float>(running / (sum > 0.0 ? sum : static_cast<double>(n)));
  }
  // Exactly 1, so that every u in [0, 1) lies below the last step.
  cdf[n] = 1.f;
  return sum;
}

// Density of bin `i` of `cdf`: its step's width times the bin count. Every caller goes through
// here, so that a sample's density and pdf() of the sampled point are the same float.
float bin_pdf(std::span<const float> cdf, int i) {
  const int n = static_cast<int>(cdf.size()) - 1;
  return (cdf[i + 1] - cdf[i]) * static_cast<float>(n);
}

Distribution1D::Sample sample_cdf(std::span<const float> cdf, float u) {
  const int n = static_cast<int>(cdf.size()) - 1;
  if (!(u >= 0.f)) u = 0.f;  // NaN too
  u = std::min(u, kOneBelow);
  // The step holding u is the one before the first CDF entry above it. The search starts at
  // cdf[1], and cdf[n] = 1 > u, so it always finds one; steps of zero width are skipped because
  // their upper end is not above u whenever their lower end is not.
  const auto above = std::upper_bound(cdf.begin() + 1, cdf.end(), u);
  const int i = std::clamp(static_cast<int>(above - cdf.begin()) - 1, 0, n - 1);
  const float width = cdf[i + 1] - cdf[i];
  const float within = std::min((u - cdf[i]) / width, kOneBelow);
  float x = std::min((static_cast<float>(i) + within) / static_cast<float>(n), kOneBelow);
  // (i + within) / n rounds, and near a bin's upper edge it can round into the next bin (or,
  // for large n, fall short of this one). Step to the neighbouring float until the point lies
  // in bin i by piecewise_bin's own rule: a bin of [0, 1) with n <= 2^24 always holds a float,
  // and the rounding error is a few ulps, so this takes a step or two at most.
  while (piecewise_bin(x, n) > i) x = std::nextafter(x, 0.f);
  while (piecewise_bin(x, n) < i) x = std::nextafter(x, 1.f);
  return {x, bin_pdf(cdf, i), i};
}

float pdf_cdf(std::span<const float> cdf, float x) {
  return bin_pdf(cdf, piecewise_bin(x, static_cast<int>(cdf.size()) - 1));
}

// The mean weight of each row: the marginal's weights. Also validates every weight.
std::vector<float> row_means(std::span<const float> weights, int width, int height) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("Distribution2D: width and height must be positive");
  check_bin_count(static_cast<std::size_t>(width), "Distribution2D width");
  check_bin_count(static_cast<std::size_t>(height), "Distribution2D height");
  if (weights.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("Distribution2D: " + std::to_string(weights.size()) + " weights for " +
                                std::to_string(width) + " x " + std::to_string(height) + " cells");
  }
  std::vector<float> means(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    double sum = 0.0;
    for (int x = 0; x < width; ++x) sum += checked_weight(weights[static_cast<std::size_t>(y) * width + x]);
    means[static_cast<std::size_t>(y)] = static_cast<float>(sum / width);
  }
  return means;
}

}  // namespace

int piecewise_bin(float x, int n) {
  if (!(x > 0.f)) return 0;
  const float scaled = x * static_cast<float>(n);
  if (!(scaled < static_cast<float>(n))) return n - 1;  // x >= 1 and +inf; keeps the cast defined
  return std::min(static_cast<int>(scaled), n - 1);
}

Distribution1D::Distribution1D(std::span<const float> weights)
    : m_cdf(check_bin_count(weights.size(), "Distribution1D") + 1) {
  m_integral = static_cast<float>(build_cdf(weights, m_cdf) / static_cast<double>(weights.size()));
}

Distribution1D::Sample Distribution1D::sample_continuous(float u) const { return sample_cdf(m_cdf, u); }

float Distribution1D::pdf(float x) const { return pdf_cdf(m_cdf, x); }

Distribution2D::Distribution2D(std::span<const float> weights, int width, int height)
    : m_width(width), m_height(height), m_marginal(row_means(weights, width, height)) {
  const std::size_t stride = static_cast<std::size_t>(width) + 1;
  m_conditional.resize(stride * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    build_cdf(weights.subspan(static_cast<std::size_t>(y) * width, static_cast<std::size_t>(width)),
              std::span<float>(m_conditional).subspan(y * stride, stride));
  }
}

Distribution2D::Sample Distribution2D::sample(Sample2 u) const {
  const std::size_t stride = static_cast<std::size_t>(m_width) + 1;
  const Distribution1D::Sample row = m_marginal.sample_continuous(u.y);
  const Distribution1D::Sample column =
      sample_cdf(std::span<const float>(m_conditional).subspan(row.index * stride, stride), u.x);
  return {{column.x, row.x}, row.pdf * column.pdf};
}

float Distribution2D::pdf(Sample2 point) const {
  const std::size_t stride = static_cast<std::size_t>(m_width) + 1;
  const std::size_t row = static_cast<std::size_t>(piecewise_bin(point.y, m_height));
  return m_marginal.pdf(point.y) *
         pdf_cdf(std::span<const float>(m_conditional).subspan(row * stride, stride), point.x);
}

}  // namespace raylab
