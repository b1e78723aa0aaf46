// CameraPath: exact cameras at key frames, the linear midpoint, the smooth path equal to the
// linear one on constant-velocity keys (even or uneven spacing), the smooth path passing through
// its keys with a continuous velocity, the spline's tangent on uneven keys, clamping, a single
// key, and check() naming the frame where an interpolated camera degenerates.

#include <gtest/gtest.h>

#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>

#include "raylab/scene/camera_path.h"

namespace raylab {
namespace {

using Interpolation = CameraPath::Interpolation;

std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }

// Bit for bit, so that a key frame renders exactly the camera the file wrote.
void expect_identical(const CameraSpec& got, const CameraSpec& want) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(bits(got.from[c]), bits(want.from[c])) << "from " << c;
    EXPECT_EQ(bits(got.at[c]), bits(want.at[c])) << "at " << c;
    EXPECT_EQ(bits(got.up[c]), bits(want.up[c])) << "up " << c;
  }
  EXPECT_EQ(bits(got.vfov_degrees), bits(want.vfov_degrees));
  EXPECT_EQ(bits(got.hither), bits(want.hither));
  EXPECT_EQ(got.fov_span, want.fov_span);
}

void expect_near(Vec3 got, Vec3 want, float tolerance) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

CameraSpec camera(Vec3 from, Vec3 at, Vec3 up = {0.f, 1.f, 0.f}, float fov = 45.f, float hither = 0.f) {
  return {.from = from, .at = at, .up = up, .vfov_degrees = fov, .hither = hither};
}

// Four unevenly spaced keys on a curve, with values that do not round nicely.
CameraPath curved_path(Interpolation interpolation) {
  CameraPath p;
  p.interpolation = interpolation;
  p.keys = {{3, camera({0.1f, 2.f, 10.f}, {0.f, 0.3f, 0.f}, {0.f, 1.f, 0.f}, 40.f, 0.f)},
            {17, camera({7.3f, 2.2f, 7.1f}, {0.2f, 0.f, 0.1f}, {0.1f, 1.f, 0.f}, 33.3f, 0.25f)},
            {24, camera({10.f, 1.7f, -0.3f}, {0.f, 1.f, 0.f}, {0.f, 1.f, 0.2f}, 30.f, 0.1f)},
            {61, camera({-0.7f, 2.9f, -9.9f}, {0.4f, 0.6f, -0.2f}, {0.f, 1.f, 0.f}, 51.7f, 0.f)}};
  p.keys[1].camera.fov_span = CameraSpec::FovSpan::kPixelCentres;
  return p;
}

TEST(CameraPath, KeyFramesGiveTheKeysCameraExactly) {
  for (Interpolation interpolation : {Interpolation::kLinear, Interpolation::kSmooth}) {
    const CameraPath p = curved_path(interpolation);
    for (const CameraKey& k : p.keys) {
      SCOPED_TRACE(k.frame);
      expect_identical(p.at(k.frame), k.camera);
      expect_identical(p.at_time(k.frame), k.camera);
    }
  }
}

TEST(CameraPath, LinearIsTheWeightedAverageOfItsTwoKeys) {
  CameraPath p;
  p.keys = {{10, camera({0.f, 0.f, 10.f}, {0.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, 40.f, 0.f)},
            {20, camera({10.f, 2.f, 0.f}, {1.f, 3.f, -1.f}, {1.f, 1.f, 0.f}, 30.f, 1.f)}};
  p.keys[0].camera.fov_span = CameraSpec::FovSpan::kPixelCentres;
  const CameraSpec mid = p.at(15);
  expect_near(mid.from, {5.f, 1.f, 5.f}, 1e-6f);
  expect_near(mid.at, {0.5f, 1.5f, -0.5f}, 1e-6f);
  expect_near(mid.up, {0.5f, 1.f, 0.f}, 1e-6f);
  EXPECT_NEAR(mid.vfov_degrees, 35.f, 1e-5f);
  EXPECT_NEAR(mid.hither, 0.5f, 1e-7f);
  EXPECT_EQ(mid.fov_span, CameraSpec::FovSpan::kPixelCentres);  // from the earlier key
  const CameraSpec fifth = p.at(12);
  expect_near(fifth.from, {2.f, 0.4f, 8.f}, 1e-6f);
  EXPECT_NEAR(fifth.vfov_degrees, 38.f, 1e-5f);
  EXPECT_EQ(p.at(20).fov_span, CameraSpec::FovSpan::kImageEdges);
}

// Keys whose positions are linear in the frame number: the smooth path must not overshoot or
// ease, whatever the spacing of the keys.
void expect_smooth_equals_linear(const std::vector<int>& frames) {
  CameraPath linear;
  const Vec3 eye0{1.f, 2.f, 3.f}, eye_velocity{0.5f, -0.25f, 0.125f};
  const Vec3 target0{0.f, 0.f, -4.f}, target_velocity{-0.1f, 0.05f, 0.f};
  for (int f : frames) {
    const float t = static_cast<float>(f);
    linear.keys.push_back({f, camera(eye0 + eye_velocity * t, target0 + target_velocity * t)});
  }
  CameraPath smooth = linear;
  smooth.interpolation = Interpolation::kSmooth;
  for (int f = frames.front() - 5; f <= frames.back() + 5; ++f) {
    SCOPED_TRACE(f);
    const CameraSpec a = linear.at(f), b = smooth.at(f);
    expect_near(b.from, a.from, 1e-5f);
    expect_near(b.at, a.at, 1e-5f);
    expect_near(b.up, a.up, 1e-5f);
  }
}

TEST(CameraPath, SmoothOnConstantVelocityKeysIsTheLinearPath) {
  expect_smooth_equals_linear({0, 12, 24, 36, 48});
  expect_smooth_equals_linear({0, 5, 20, 21, 40});
  expect_smooth_equals_linear({7, 9});
}

TEST(CameraPath, SmoothPassesThroughKeysWithAContinuousVelocity) {
  // Keys far apart, so that one frame is a small step and differences approximate derivatives.
  CameraPath smooth;
  smooth.interpolation = Interpolation::kSmooth;
  const float r = 10.f;
  const int frames[] = {0, 1000, 2500, 3200, 5000};
  for (int i = 0; i < 5; ++i) {
    const float a = 1.3f * static_cast<float>(i);
    smooth.keys.push_back({frames[i], camera({r * std::cos(a), 2.f, r * std::sin(a)}, {0.f, 0.f, 0.f})});
  }
  CameraPath linear = smooth;
  linear.interpolation = Interpolation::kLinear;
  for (int i = 1; i < 4; ++i) {
    const int k = frames[i];
    SCOPED_TRACE(k);
    // Continuous: one frame away from a key, the eye is within one frame's travel of it.
    const Vec3 key = smooth.at(k).from;
    EXPECT_LT(length(smooth.at(k - 1).from - key), 0.05f);
    EXPECT_LT(length(smooth.at(k + 1).from - key), 0.05f);
    // Velocity continuous: the step into the key equals the step out of it, up to the curvature;
    // the linear path turns a corner there.
    const Vec3 in = key - smooth.at(k - 1).from, out = smooth.at(k + 1).from - key;
    EXPECT_LT(length(out - in), 1e-2f * length(in));
    const Vec3 lin_in = key - linear.at(k - 1).from, lin_out = linear.at(k + 1).from - key;
    EXPECT_GT(length(lin_out - lin_in), 0.1f * length(lin_in));
    // And fractional times close in on the key from both sides.
    expect_near(smooth.at_time(k - 1e-3).from, key, 1e-4f);
    expect_near(smooth.at_time(k + 1e-3).from, key, 1e-4f);
  }
  // Between keys the smooth path is a curve, not the chord.
  EXPECT_GT(length(smooth.at(1250).from - linear.at(1250).from), 0.1f);
}

TEST(CameraPath, SmoothTangentIsTheParabolaThroughAKeyAndItsNeighbours) {
  // x = f^2 at unevenly spaced frames 0, 1, 3: the parabola through them is x = f^2 itself, whose
  // slope at frame 1 is 2. The central difference over the neighbours would say 9 / 3 = 3; a
  // spline on key indices, ignoring the spacing, 4.5 per frame coming in and 2.25 going out.
  CameraPath p;
  p.interpolation = Interpolation::kSmooth;
  for (int f : {0, 1, 3}) {
    const float x = static_cast<float>(f * f);
    p.keys.push_back({f, camera({x, 0.f, 5.f}, {x, 0.f, 0.f})});
  }
  const double h = 1e-3;
  const double slope = (p.at_time(1 + h).from.x - p.at_time(1 - h).from.x) / (2 * h);
  EXPECT_NEAR(slope, 2.0, 1e-2);
}

TEST(CameraPath, FramesOutsideTheKeysAreClampedToTheEndKeys) {
  for (Interpolation interpolation : {Interpolation::kLinear, Interpolation::kSmooth}) {
    const CameraPath p = curved_path(interpolation);
    for (int f : {INT_MIN, -1, 0, 2}) expect_identical(p.at(f), p.keys.front().camera);
    for (int f : {62, 100, INT_MAX}) expect_identical(p.at(f), p.keys.back().camera);
    expect_identical(p.at_time(std::nan("")), p.keys.front().camera);
  }
}

TEST(CameraPath, OneKeyIsTheSameCameraAtEveryFrame) {
  for (Interpolation interpolation : {Interpolation::kLinear, Interpolation::kSmooth}) {
    CameraPath p;
    p.interpolation = interpolation;
    p.keys = {{5, camera({1.f, 2.f, 3.f}, {0.f, 0.1f, 0.f}, {0.f, 1.f, 0.f}, 33.f, 0.5f)}};
    EXPECT_FALSE(p.empty());
    EXPECT_EQ(p.first_frame(), 5);
    EXPECT_EQ(p.last_frame(), 5);
    for (int f : {INT_MIN, 0, 4, 5, 6, 1000}) expect_identical(p.at(f), p.keys[0].camera);
    EXPECT_EQ(p.check(), std::nullopt);
  }
}

TEST(CameraPath, CheckNamesTheFrameWhereTheCameraDegenerates) {
  EXPECT_TRUE(CameraPath{}.empty());
  EXPECT_EQ(CameraPath{}.check(), std::nullopt);
  EXPECT_EQ(curved_path(Interpolation::kSmooth).check(), std::nullopt);

  // The eye passes through the point it looks at, half way between two valid keys.
  CameraPath through;
  through.keys = {{0, camera({-1.f, 0.f, 0.f}, {0.f, 0.f, 0.f})}, {10, camera({1.f, 0.f, 0.f}, {0.f, 0.f, 0.f})}};
  ASSERT_TRUE(through.check().has_value());
  EXPECT_EQ(*through.check(), "the camera at frame 5 has 'from' and 'at' at the same point");

  // 'up' turns through zero.
  CameraPath flip;
  flip.keys = {{4, camera({0.f, 0.f, 5.f}, {0.f, 0.f, 0.f}, {0.f, 1.f, 0.f})},
               {6, camera({0.f, 0.f, 5.f}, {0.f, 0.f, 0.f}, {0.f, -1.f, 0.f})}};
  ASSERT_TRUE(flip.check().has_value());
  EXPECT_NE(flip.check()->find("frame 5 has 'up' parallel"), std::string::npos) << *flip.check();

  CameraPath unordered = curved_path(Interpolation::kLinear);
  unordered.keys[2].frame = 17;
  ASSERT_TRUE(unordered.check().has_value());
  EXPECT_EQ(*unordered.check(), "key 2 (frame 17) does not come after key 1 (frame 17): frames must strictly increase");
}

}  // namespace
}  // namespace raylab
