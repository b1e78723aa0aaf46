// The CPU requirements of this build: they follow its -march, and the machine running the tests
// meets them (it loaded the library).

#include "raylab/core/cpu_features.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace raylab {
namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(CpuFeatures, NoneMissingOnTheMachineThatLoadedTheLibrary) { EXPECT_TRUE(missing_cpu_features().empty()); }

// The tests are compiled with the library's -march, so their predefined macros say what the
// library may use.
TEST(CpuFeatures, RequiredFollowTheBuildsMarch) {
  const std::vector<std::string> required = required_cpu_features();
#ifdef __AVX2__
  EXPECT_TRUE(contains(required, "avx2"));
#else
  EXPECT_FALSE(contains(required, "avx2"));
#endif
#ifdef __FMA__
  EXPECT_TRUE(contains(required, "fma"));
#else
  EXPECT_FALSE(contains(required, "fma"));
#endif
#ifdef __AVX512F__
  EXPECT_TRUE(contains(required, "avx512f"));
#else
  EXPECT_FALSE(contains(required, "avx512f"));
#endif
#ifdef __BMI2__
  EXPECT_TRUE(contains(required, "bmi2"));
#else
  EXPECT_FALSE(contains(required, "bmi2"));
#endif
}

TEST(CpuFeatures, X86_64V3IsItsThirteenExtensions) {
  if (std::string(build_cpu_arch()) != "x86-64-v3") GTEST_SKIP() << "built with -march=" << build_cpu_arch();
  const std::vector<std::string> required = required_cpu_features();
  const std::set<std::string> got(required.begin(), required.end());
  const std::set<std::string> want = {"sse3", "ssse3", "sse4.1", "sse4.2", "popcnt", "avx",  "avx2",
                                      "fma",  "bmi",   "bmi2",   "f16c",   "movbe",  "lzcnt"};
  EXPECT_EQ(got, want);
  EXPECT_EQ(got.size(), required.size()) << "a feature is listed twice";
}

}  // namespace
}  // namespace raylab
