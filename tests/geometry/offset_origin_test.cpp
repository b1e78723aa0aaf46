// Spawned rays' origins: offset_origin, and the two precomputed origins shading reads instead
// (OffsetOrigins, ShadingPoint), which must be its bits exactly.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "raylab/core/rng.h"
#include "raylab/geometry/shading.h"
#include "raylab/render/whitted.h"

namespace raylab {
namespace {

bool same_bits(Vec3 a, Vec3 b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

Vec3 random_unit(Pcg32& rng) {
  for (;;) {
    const Vec3 v{2.f * rng.next_float() - 1.f, 2.f * rng.next_float() - 1.f, 2.f * rng.next_float() - 1.f};
    const float l2 = dot(v, v);
    if (l2 > 1e-4f && l2 <= 1.f) return v * (1.f / std::sqrt(l2));
  }
}

TEST(OffsetOrigin, MovesOffTheSurfaceTowardTheRaysSide) {
  const Vec3 p{0.f, 0.f, 0.f}, n{0.f, 0.f, 1.f};
  EXPECT_TRUE(same_bits(offset_origin(p, n, {0.f, 1.f, 1.f}), Vec3{0.f, 0.f, 1e-4f}));
  EXPECT_TRUE(same_bits(offset_origin(p, n, {0.f, 1.f, -1.f}), Vec3{0.f, 0.f, -1e-4f}));
  // A grazing direction (in the tangent plane) counts as n's side.
  EXPECT_TRUE(same_bits(offset_origin(p, n, {1.f, 0.f, 0.f}), Vec3{0.f, 0.f, 1e-4f}));
  // Far from the origin the offset grows with the largest coordinate.
  const Vec3 far = offset_origin({1000.f, -3.f, 2.f}, n, {0.f, 0.f, 1.f});
  EXPECT_FLOAT_EQ(far.z, 2.f + 0.1f);
}

TEST(OffsetOrigin, PrecomputedOriginsAreItsBits) {
  Pcg32 rng(7);
  for (int i = 0; i < 20000; ++i) {
    const float scale = std::pow(10.f, 6.f * rng.next_float() - 3.f);
    const Vec3 p = random_unit(rng) * scale, n = random_unit(rng), dir = random_unit(rng);
    ASSERT_TRUE(same_bits(offset_origins(p, n).toward(dir, n), offset_origin(p, n, dir))) << i;

    SurfaceInteraction si;
    si.position = p;
    si.geometric_normal = n;
    si.shading_normal = random_unit(rng);
    si.front_face = (i & 1) != 0;
    for (ShadowFacing facing : {ShadowFacing::kViewer, ShadowFacing::kOutward}) {
      const ShadingPoint at = WhittedIntegrator::shading_point(si, facing);
      ASSERT_TRUE(same_bits(at.origin_toward(dir), offset_origin(p, n, dir))) << i;
    }
  }
}

}  // namespace
}  // namespace raylab
