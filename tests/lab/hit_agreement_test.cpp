// The lab's one rule for agreeing hits, shared by `raylab compare` and `raylab bench`.

#include "raylab/lab/hit_agreement.h"

#include <gtest/gtest.h>

namespace raylab {
namespace {

TEST(HitAgreement, SamePrimitiveIsTheSameAnswerDifferentOnesAtOneDistanceATie) {
  const Hit miss;
  const Hit a{2.f, 7, 0.f, 0.f};
  EXPECT_EQ(match_hits(miss, miss, 1e-4), HitMatch::kSame);
  EXPECT_EQ(match_hits(a, miss, 1e-4), HitMatch::kDifferent);
  EXPECT_EQ(match_hits(a, Hit{2.5f, 7, 0.f, 0.f}, 1e-4), HitMatch::kSame);
  EXPECT_EQ(match_hits(a, Hit{2.f, 9, 0.f, 0.f}, 1e-4), HitMatch::kTie);
  EXPECT_EQ(match_hits(a, Hit{2.001f, 9, 0.f, 0.f}, 1e-4), HitMatch::kDifferent);
}

TEST(HitAgreement, NearTheOriginTheSlackDecides) {
  Ray ray;
  ray.origin = {100.f, 0.f, 0.f};
  const double slack = origin_slack(ray);
  EXPECT_DOUBLE_EQ(slack, 100.0 * 16.0 / (1 << 24));
  const Hit near{1e-6f, 1, 0.f, 0.f}, other{3e-5f, 2, 0.f, 0.f};  // 30x apart, within 16 ulps of 100
  EXPECT_EQ(match_hits(near, other, 1e-4), HitMatch::kDifferent);
  EXPECT_EQ(match_hits(near, other, 1e-4, slack), HitMatch::kTie);
  EXPECT_TRUE(distances_agree(1.0, 1.00005, 1e-4));
  EXPECT_FALSE(distances_agree(1.0, 1.0002, 1e-4));
  EXPECT_TRUE(distances_agree(1.0, 1.0002, 1e-4, 1e-3));
}

}  // namespace
}  // namespace raylab
