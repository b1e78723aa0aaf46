// The dimension pairs of a path: stratified within a pair like the pixel sampler, shuffled
// between pairs, and addressable (the same arguments give the same numbers).

#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <vector>

#include "raylab/sampling/pixel_sampler.h"
#include "raylab/sampling/sample_dimensions.h"

namespace raylab {
namespace {

// The 4 x 4 stratum of a point of [0, 1)^2.
int stratum(Sample2 s) { return static_cast<int>(s.y * 4.f) * 4 + static_cast<int>(s.x * 4.f); }

TEST(SampleDimensions, EachPairKeepsTheSamplersStratification) {
  for (const char* name : {"jittered", "cmj", "sobol", "regular"}) {
    const std::unique_ptr<PixelSampler> sampler = make_pixel_sampler(name, 16, 5);
    const SampleDimensions dims(*sampler);
    for (int k : {1, 2, 7, SampleDimensions::kStratifiedPairs - 1}) {
      std::set<int> strata;
      for (int i = 0; i < 16; ++i) {
        const Sample2 s = dims.pair(k, 3, 9, i);
        ASSERT_GE(s.x, 0.f);
        ASSERT_LT(s.x, 1.f);
        ASSERT_GE(s.y, 0.f);
        ASSERT_LT(s.y, 1.f);
        strata.insert(stratum(s));
      }
      EXPECT_EQ(strata.size(), 16u) << name << " pair " << k;
    }
  }
}

TEST(SampleDimensions, PairsAreShuffledAgainstEachOtherAndThePosition) {
  // Were sample i in the same stratum in two pairs, the pairs would be correlated (a light
  // sample tied to the pixel position): across many pixels, the strata must agree about as
  // often as chance (1 in 16) says.
  const std::unique_ptr<PixelSampler> sampler = make_pixel_sampler("jittered", 16, 5);
  const SampleDimensions dims(*sampler);
  int same = 0, total = 0;
  for (int px = 0; px < 64; ++px) {
    for (int i = 0; i < 16; ++i) {
      const int position = stratum(sampler->sample(px, 0, i));
      const int first = stratum(dims.pair(1, px, 0, i));
      const int second = stratum(dims.pair(2, px, 0, i));
      same += (position == first) + (first == second);
      total += 2;
    }
  }
  // Chance: total / 16 = 128 expected, standard deviation about 11.
  EXPECT_LT(same, 128 + 5 * 11);
  EXPECT_GT(same, 128 - 5 * 11);
}

TEST(SampleDimensions, SameArgumentsSameNumbersAndDeepPairsAreUniform) {
  const std::unique_ptr<PixelSampler> sampler = make_pixel_sampler("center", 1, 3);
  const SampleDimensions a(*sampler), b(*sampler);
  double sum = 0.0;
  const int n = 4000;
  for (int px = 0; px < n; ++px) {
    for (int k : {1, 5, SampleDimensions::kStratifiedPairs + 3}) {
      const Sample2 s = a.pair(k, px, 1, 0), t = b.pair(k, px, 1, 0);
      EXPECT_EQ(s.x, t.x);
      EXPECT_EQ(s.y, t.y);
      sum += s.x + s.y;
    }
  }
  // The center sampler's twin is random: a mean of 0.5 (standard deviation of the mean about
  // 0.0026 for 24000 numbers).
  EXPECT_NEAR(sum / (n * 6), 0.5, 0.015);
}

}  // namespace
}  // namespace raylab
