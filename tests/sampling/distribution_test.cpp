// Distribution1D and Distribution2D against their weights: histograms by a chi-square test,
// densities that integrate to 1 and match the samples bit for bit, and the edges (one bin, all
// weights zero, weights 60 orders of magnitude apart, u at the end of [0, 1)).

#include "raylab/sampling/distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "chi_square.h"
#include "raylab/core/rng.h"

namespace raylab {
namespace {

constexpr float kOneBelow = 0x1.fffffep-1f;
constexpr int kSamples = 200000;

// Counts of kSamples draws per bin, and the counts the weights predict.
test::ChiSquare histogram_test_1d(const Distribution1D& d, const std::vector<float>& weights, std::uint64_t seed) {
  std::vector<double> observed(weights.size(), 0.0), expected(weights.size(), 0.0);
  Pcg32 rng(seed);
  for (int s = 0; s < kSamples; ++s)
    observed[static_cast<std::size_t>(d.sample_continuous(rng.next_float()).index)] += 1.0;
  double sum = 0.0;
  for (float w : weights) sum += w;
  for (std::size_t i = 0; i < weights.size(); ++i)
    expected[i] = kSamples * (sum > 0.0 ? weights[i] / sum : 1.0 / weights.size());
  return test::chi_square_test(observed, expected);
}

// Checks the promises every sample keeps: x in [0, 1), in the bin it names, and a density equal
// to pdf(x) bit for bit.
void expect_consistent(const Distribution1D& d, const Distribution1D::Sample& s) {
  ASSERT_GE(s.x, 0.f);
  ASSERT_LT(s.x, 1.f);
  ASSERT_EQ(piecewise_bin(s.x, d.size()), s.index) << "x = " << s.x;
  ASSERT_EQ(s.pdf, d.pdf(s.x));
}

// The integral of pdf over [0, 1): exact by the bins' midpoints, since pdf is constant in each.
double pdf_integral(const Distribution1D& d) {
  double sum = 0.0;
  for (int i = 0; i < d.size(); ++i) sum += d.pdf((static_cast<float>(i) + 0.5f) / static_cast<float>(d.size()));
  return sum / d.size();
}

const std::vector<float> kWeights = {1.f, 0.f, 3.f, 0.5f, 7.f, 2.f, 0.f, 4.f, 0.25f, 6.f};

TEST(Distribution1D, HistogramMatchesTheWeights) {
  const Distribution1D d(kWeights);
  const test::ChiSquare chi = histogram_test_1d(d, kWeights, 7);
  EXPECT_TRUE(chi.pass()) << chi.describe();
  EXPECT_FLOAT_EQ(d.integral(), 23.75f / 10.f);
}

TEST(Distribution1D, ChiSquareRejectsADensityItDoesNotDraw) {
  // The test above must be able to fail: the same samples against weights with two bins
  // swapped.
  std::vector<float> swapped = kWeights;
  std::swap(swapped[2], swapped[4]);
  EXPECT_FALSE(histogram_test_1d(Distribution1D(kWeights), swapped, 7).pass());
}

TEST(Distribution1D, PointsAreUniformWithinTheirBin) {
  // A histogram ten times finer than the bins: the position within a bin must be uniform too.
  const std::vector<float> weights = {2.f, 1.f, 0.f, 5.f};
  const Distribution1D d(weights);
  std::vector<double> observed(40, 0.0), expected(40, 0.0);
  Pcg32 rng(37);
  for (int s = 0; s < kSamples; ++s)
    observed[static_cast<std::size_t>(piecewise_bin(d.sample_continuous(rng.next_float()).x, 40))] += 1.0;
  for (std::size_t i = 0; i < 40; ++i) expected[i] = kSamples * weights[i / 10] / 8.0 / 10.0;
  const test::ChiSquare chi = test::chi_square_test(observed, expected);
  EXPECT_TRUE(chi.pass()) << chi.describe();
}

TEST(Distribution1D, ZeroWeightBinsAreNeverDrawnAndHaveDensityZero) {
  const Distribution1D d(kWeights);
  Pcg32 rng(11);
  for (int s = 0; s < kSamples; ++s) {
    const Distribution1D::Sample x = d.sample_continuous(rng.next_float());
    ASSERT_NE(x.index, 1);
    ASSERT_NE(x.index, 6);
  }
  EXPECT_EQ(d.pdf(0.15f), 0.f);
  EXPECT_EQ(d.pdf(0.65f), 0.f);
}

TEST(Distribution1D, SampleDensityIsThePdfOfThePoint) {
  const Distribution1D d(kWeights);
  Pcg32 rng(3);
  for (int s = 0; s < 20000; ++s) expect_consistent(d, d.sample_continuous(rng.next_float()));
}

TEST(Distribution1D, PdfIntegratesToOne) {
  EXPECT_NEAR(pdf_integral(Distribution1D(kWeights)), 1.0, 1e-6);
  Pcg32 rng(5);
  std::vector<float> random(1000);
  for (float& w : random) w = rng.next_float() * rng.next_float() * 100.f;
  EXPECT_NEAR(pdf_integral(Distribution1D(random)), 1.0, 1e-5);
}

TEST(Distribution1D, PdfIsProportionalToTheWeights) {
  const Distribution1D d(kWeights);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(d.pdf((i + 0.5f) / 10.f), kWeights[static_cast<std::size_t>(i)] / d.integral(), 1e-5) << "bin " << i;
  }
}

TEST(Distribution1D, OneBinIsTheIdentity) {
  const std::vector<float> one = {3.f};
  const Distribution1D d(one);
  EXPECT_EQ(d.size(), 1);
  EXPECT_EQ(d.integral(), 3.f);
  for (float u : {0.f, 0.25f, 0.5f, 0.75f, kOneBelow}) {
    const Distribution1D::Sample s = d.sample_continuous(u);
    EXPECT_EQ(s.x, u);
    EXPECT_EQ(s.pdf, 1.f);
    EXPECT_EQ(s.index, 0);
  }
}

TEST(Distribution1D, AllZeroWeightsFallBackToUniform) {
  const std::vector<float> zeros(7, 0.f);
  const Distribution1D d(zeros);
  EXPECT_EQ(d.integral(), 0.f);
  for (int i = 0; i < 7; ++i) EXPECT_NEAR(d.pdf((i + 0.5f) / 7.f), 1.f, 1e-6f);
  const test::ChiSquare chi = histogram_test_1d(d, zeros, 13);
  EXPECT_TRUE(chi.pass()) << chi.describe();
}

TEST(Distribution1D, HugeDynamicRangeStaysFiniteAndNormalised) {
  // The float sum of these weights overflows; 1e-30 is far below what a float CDF resolves next
  // to FLT_MAX, so that bin is never drawn and must then report density 0, not one it never
  // delivers.
  const float big = std::numeric_limits<float>::max();
  const std::vector<float> weights = {big, 1e-30f, 0.f, big / 2.f, 1.f, std::numeric_limits<float>::denorm_min()};
  const Distribution1D d(weights);
  EXPECT_TRUE(std::isfinite(d.integral()));
  EXPECT_NEAR(pdf_integral(d), 1.0, 1e-6);
  for (int i = 0; i < d.size(); ++i) EXPECT_TRUE(std::isfinite(d.pdf((i + 0.5f) / 6.f))) << "bin " << i;
  EXPECT_EQ(d.pdf(1.5f / 6.f), 0.f);
  EXPECT_NEAR(d.pdf(0.5f / 6.f), 4.f, 1e-5f);  // 2/3 of the mass in 1/6 of the interval
  EXPECT_NEAR(d.pdf(3.5f / 6.f), 2.f, 1e-5f);
  const test::ChiSquare chi = histogram_test_1d(d, weights, 17);
  EXPECT_TRUE(chi.pass()) << chi.describe();
  Pcg32 rng(19);
  for (int s = 0; s < 20000; ++s) expect_consistent(d, d.sample_continuous(rng.next_float()));
}

TEST(Distribution1D, NeverReturnsOneAndAlwaysLandsInItsBin) {
  // Points next to bin edges, where (i + within) / n rounds into the neighbour: u just below
  // each CDF step of a uniform distribution, for counts whose 1/n is not a float.
  for (int n : {1, 3, 7, 10, 1000, 999983, 1 << 20}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    const Distribution1D d(std::vector<float>(static_cast<std::size_t>(n), 1.f));
    std::vector<float> us = {0.f, kOneBelow, 1.f, 2.f, -1.f, std::numeric_limits<float>::quiet_NaN()};
    Pcg32 rng(static_cast<std::uint64_t>(n));
    for (int k = 0; k < 2000; ++k) {
      const float edge = static_cast<float>(rng.next_u32() % static_cast<std::uint32_t>(n) + 1) / static_cast<float>(n);
      us.push_back(std::nextafter(edge, 0.f));
      us.push_back(std::min(edge, kOneBelow));
    }
    for (float u : us) expect_consistent(d, d.sample_continuous(u));
    EXPECT_EQ(d.sample_continuous(kOneBelow).index, n - 1);
  }
}

TEST(Distribution1D, LandsInItsBinWhenOneBinHoldsNearlyAllTheMass) {
  // A wide step: u one ulp below its top gives within = 1 - 2^-24, and i + within rounds up to
  // i + 1, into the next bin, unless the sampler steps back; at its bottom (i + 0) / n can
  // round below i / n. Every float u near both ends of the step.
  for (int n : {1000, 999983}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    std::vector<float> weights(static_cast<std::size_t>(n), 1.f);
    weights[static_cast<std::size_t>(n / 2)] = 1e9f;
    const Distribution1D d(weights);
    for (float u = 0.9999f; u < 1.f; u = std::nextafter(u, 1.f)) expect_consistent(d, d.sample_continuous(u));
    float u = static_cast<float>((n / 2) / (1e9 + n - 1));
    for (int k = 0; k < 1000; ++k) u = std::nextafter(u, 0.f);
    for (int k = 0; k < 2000; ++k, u = std::nextafter(u, 1.f)) expect_consistent(d, d.sample_continuous(u));
  }
}

TEST(Distribution1D, IsMonotoneInU) {
  // Stratified u give stratified points only if the map keeps their order.
  const Distribution1D d(kWeights);
  float previous = -1.f;
  for (int k = 0; k <= 4096; ++k) {
    const float x = d.sample_continuous(std::min(k / 4096.f, kOneBelow)).x;
    ASSERT_GE(x, previous) << "k = " << k;
    previous = x;
  }
}

TEST(Distribution1D, RejectsBadWeights) {
  EXPECT_THROW(Distribution1D(std::vector<float>{}), std::invalid_argument);
  EXPECT_THROW(Distribution1D(std::vector<float>{1.f, -1.f}), std::invalid_argument);
  EXPECT_THROW(Distribution1D(std::vector<float>{std::numeric_limits<float>::quiet_NaN()}), std::invalid_argument);
  EXPECT_THROW(Distribution1D(std::vector<float>{std::numeric_limits<float>::infinity()}), std::invalid_argument);
}

TEST(PiecewiseBin, ClampsIntoRange) {
  EXPECT_EQ(piecewise_bin(0.f, 4), 0);
  EXPECT_EQ(piecewise_bin(0.25f, 4), 1);
  EXPECT_EQ(piecewise_bin(kOneBelow, 4), 3);
  EXPECT_EQ(piecewise_bin(1.f, 4), 3);
  EXPECT_EQ(piecewise_bin(-0.5f, 4), 0);
  EXPECT_EQ(piecewise_bin(std::numeric_limits<float>::infinity(), 4), 3);
  EXPECT_EQ(piecewise_bin(std::numeric_limits<float>::quiet_NaN(), 4), 0);
}

// An 8 x 6 grid with a zero row (2) and a zero column (5).
std::vector<float> grid_weights() {
  std::vector<float> w(48);
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < 8; ++x)
      w[static_cast<std::size_t>(y * 8 + x)] = y == 2 || x == 5 ? 0.f : 1.f + ((x * 7 + y * 3) % 5);
  }
  return w;
}

TEST(Distribution2D, HistogramMatchesTheWeights) {
  const std::vector<float> w = grid_weights();
  const Distribution2D d(w, 8, 6);
  std::vector<double> observed(48, 0.0), expected(48, 0.0);
  Pcg32 rng(23);
  for (int s = 0; s < kSamples; ++s) {
    const Sample2 p = d.sample({rng.next_float(), rng.next_float()}).point;
    observed[static_cast<std::size_t>(piecewise_bin(p.y, 6) * 8 + piecewise_bin(p.x, 8))] += 1.0;
  }
  double sum = 0.0;
  for (float v : w) sum += v;
  for (std::size_t i = 0; i < 48; ++i) expected[i] = kSamples * w[i] / sum;
  const test::ChiSquare chi = test::chi_square_test(observed, expected);
  EXPECT_TRUE(chi.pass()) << chi.describe();
  EXPECT_FLOAT_EQ(d.integral(), static_cast<float>(sum / 48.0));
}

TEST(Distribution2D, SampleDensityIsThePdfOfThePoint) {
  const Distribution2D d(grid_weights(), 8, 6);
  Pcg32 rng(29);
  for (int s = 0; s < 20000; ++s) {
    const Distribution2D::Sample x = d.sample({rng.next_float(), rng.next_float()});
    ASSERT_GE(x.point.x, 0.f);
    ASSERT_LT(x.point.x, 1.f);
    ASSERT_GE(x.point.y, 0.f);
    ASSERT_LT(x.point.y, 1.f);
    ASSERT_GT(x.pdf, 0.f);
    ASSERT_EQ(x.pdf, d.pdf(x.point));
  }
}

TEST(Distribution2D, PdfIntegratesToOneAndFollowsTheWeights) {
  const std::vector<float> w = grid_weights();
  const Distribution2D d(w, 8, 6);
  double integral = 0.0;
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < 8; ++x) {
      const float p = d.pdf({(x + 0.5f) / 8.f, (y + 0.5f) / 6.f});
      EXPECT_NEAR(p, w[static_cast<std::size_t>(y * 8 + x)] / d.integral(), 1e-5f) << x << ", " << y;
      integral += p / 48.0;
    }
  }
  EXPECT_NEAR(integral, 1.0, 1e-6);
}

TEST(Distribution2D, AllZeroWeightsFallBackToUniform) {
  const Distribution2D d(std::vector<float>(12, 0.f), 4, 3);
  Pcg32 rng(31);
  for (int s = 0; s < 1000; ++s) {
    const Distribution2D::Sample x = d.sample({rng.next_float(), rng.next_float()});
    ASSERT_NEAR(x.pdf, 1.f, 1e-6f);
  }
}

TEST(Distribution2D, OneCellIsTheIdentity) {
  const Distribution2D d(std::vector<float>{2.f}, 1, 1);
  const Distribution2D::Sample s = d.sample({0.25f, 0.75f});
  EXPECT_EQ(s.point.x, 0.25f);
  EXPECT_EQ(s.point.y, 0.75f);
  EXPECT_EQ(s.pdf, 1.f);
}

TEST(Distribution2D, RejectsSizesThatDoNotMatch) {
  EXPECT_THROW(Distribution2D(std::vector<float>(12, 1.f), 4, 4), std::invalid_argument);
  EXPECT_THROW(Distribution2D(std::vector<float>{}, 0, 0), std::invalid_argument);
  EXPECT_THROW(Distribution2D(std::vector<float>(4, -1.f), 2, 2), std::invalid_argument);
}

}  // namespace
}  // namespace raylab
