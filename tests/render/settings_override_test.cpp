// Settings given apart from the scene replace the scene's own one by one; what is not given stays.
// And the memory limit: a render over it is refused naming the figures, one under it passes.

#include <gtest/gtest.h>

#include <string>

#include "../test_util.h"
#include "raylab/core/error.h"
#include "raylab/render/memory_limit.h"
#include "raylab/render/settings_override.h"

namespace raylab {
namespace {

TEST(SettingsOverride, ReplacesOnlyWhatIsGiven) {
  RenderSettings s;
  s.width = 100;
  s.sampler = "cmj";
  s.seed = 3;
  SettingsOverride over;
  over.width = 7;
  over.filter = "gaussian";
  over.aa_depth = 2;
  apply_settings_override(s, over);
  EXPECT_EQ(s.width, 7);
  EXPECT_EQ(s.filter, "gaussian");
  EXPECT_EQ(s.aa_depth, 2);
  EXPECT_EQ(s.height, RenderSettings{}.height);
  EXPECT_EQ(s.sampler, "cmj");
  EXPECT_EQ(s.seed, 3u);
}

TEST(SettingsOverride, EveryMemberReachesTheSettings) {
  SettingsOverride over{1, 2, 3, 4, 5, "sobol", "tent", 1.5f, 0.25f, 6};
  RenderSettings s;
  apply_settings_override(s, over);
  EXPECT_EQ(s.width, 1);
  EXPECT_EQ(s.height, 2);
  EXPECT_EQ(s.spp, 3);
  EXPECT_EQ(s.max_depth, 4);
  EXPECT_EQ(s.seed, 5u);
  EXPECT_EQ(s.sampler, "sobol");
  EXPECT_EQ(s.filter, "tent");
  EXPECT_EQ(s.filter_radius, 1.5f);
  EXPECT_EQ(s.aa_threshold, 0.25f);
  EXPECT_EQ(s.aa_depth, 6);
}

TEST(MemoryLimit, OverTheLimitIsRefusedWithTheFigures) {
  RenderMemoryEstimate e;
  e.samples = 1000;
  e.image = 1024;
  e.sums = 2048;
  e.accelerator = 4096;
  EXPECT_NO_THROW(check_memory_limit(e, 8, e.total()));
  test::expect_contains_all(
      test::thrown_message<UsageError>([&] { check_memory_limit(e, 8, e.total() - 1); }),
      {"this render would need about 7.0 KiB", "for 8 primitives; 1000 primary samples", "(--max-memory)"});
  EXPECT_GT(default_memory_limit(), 0u);
}

}  // namespace
}  // namespace raylab
