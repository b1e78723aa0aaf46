// The seed salts keep their historical values: every image, and the reference images under
// tests/ and docs/, depend on them. A change here is a change of every render's pixels, to be
// made on purpose, with the references regenerated, not by tidying the registry.

#include <gtest/gtest.h>

#include <set>

#include "raylab/sampling/seed_salts.h"

namespace raylab {
namespace {

TEST(SeedSalts, KeepTheValuesTheImagesWereMadeWith) {
  EXPECT_EQ(kUnsaltedSeed, 0u);
  EXPECT_EQ(kRandomSamplerSalt, 0x7a4d0c3e91b25f68ull);
  EXPECT_EQ(kCmjSamplerSalt, 0x3c6ef372fe94f82bull);
  EXPECT_EQ(kSobolSamplerSalt, 0xa54ff53a5f1d36f1ull);
  EXPECT_EQ(kSamplePathSalt, 0x5eedf00dull);
  EXPECT_EQ(kMultiJitteredPatternSalt, 0x3a17ull);
  EXPECT_EQ(kAdaptiveBaseSampleSalt, 0xba5eull);
  EXPECT_EQ(kAdaptivePathSalt, 0xada9717eull);
  EXPECT_EQ(kAdaptiveCornersPathSalt, 0xc0e7e5ull);
  EXPECT_EQ(kRaySetLightStream, 1u);
  EXPECT_EQ(kRaySetBounceStream, 2u);
  EXPECT_EQ(kSampleDimensionSalt, 0xd1e5a3b7c0f24689ull);
  EXPECT_EQ(kDimensionShuffleSalt, 0x6b43a9b5e1f0d27cull);
  EXPECT_EQ(kDeepDimensionSalt, 0x2f8e6d4c1a0b9375ull);
}

TEST(SeedSalts, AreAllDistinct) {
  // The header checks this at compile time; this says so again where a reader of the tests looks.
  const std::set<std::uint64_t> distinct(kAllSeedSalts.begin(), kAllSeedSalts.end());
  EXPECT_EQ(distinct.size(), kAllSeedSalts.size());
  EXPECT_EQ(kAllSeedSalts.size(), 14u) << "a new salt belongs in kAllSeedSalts and in the test above";
}

}  // namespace
}  // namespace raylab
