// The SIMD cylinder rejections against the scalar one they must reproduce,
// cylinder_surely_missed: four cylinders against one ray (cylinder_lanes.h) and one cylinder
// against 4, 8 or 16 rays (cylinder_rays.h, for packets) give in every lane the same answer, on
// random cylinders and cones and rays near them (where the rejection's margin decides), on rays
// along or across the axis, and on the inputs where float runs out (tiny and huge directions,
// NaN and infinities, flat cones whose rejection is off, degenerate axes). The ray-parallel
// test takes each case's ray in one lane beside the rays of the cases before it.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "../accel/test_scenes.h"
#include "raylab/geometry/cylinder_lanes.h"
#include "raylab/geometry/cylinder_rays.h"
#include "recent_rays.h"

namespace raylab {
namespace {

using test::RecentRays;

using test_scenes::kInf;
using test_scenes::Sampler;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// A point in the cube [-extent, extent]^3.
Vec3 random_point(Sampler& s, float extent) { return s.in_box(Vec3(-extent), Vec3(extent)); }

// Rejects the first N of `recent`'s rays for the cylinder of `frame` as lanes, with every lane
// and with every other lane, and compares each lane with cylinder_surely_missed.
template <int N>
void check_rays(const CylinderFrame& frame, const RecentRays& recent) {
  const RayLanes<N> rays = RayLanes<N>::load(recent.ox, recent.oy, recent.oz, recent.dx, recent.dy, recent.dz);
  for (const unsigned lanes : {(1u << N) - 1u, 0x5555u & ((1u << N) - 1u)}) {
    const unsigned mask = cylinders_surely_missed_by_rays<N>(frame, rays, lanes);
    EXPECT_EQ(mask & ~lanes, 0u) << "a lane outside the mask";
    for (int i = 0; i < N; ++i) {
      if (((lanes >> i) & 1u) == 0) continue;
      const Ray ray = recent.ray(i);
      EXPECT_EQ(((mask >> i) & 1u) != 0, cylinder_surely_missed(frame, ray))
          << N << " rays, lane " << i << " base=(" << frame.base.x << ", " << frame.base.y << ", " << frame.base.z
          << ") axis=(" << frame.axis.x << ", " << frame.axis.y << ", " << frame.axis.z << ") R=" << frame.reject_radius
          << " o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=(" << ray.direction.x
          << ", " << ray.direction.y << ", " << ray.direction.z << ")";
    }
  }
}

// Stores the four cylinders' frames as lanes (through CylinderLaneArrays, as the wide BVH does,
// at position `at` of a longer list) and compares each lane with cylinder_surely_missed for
// several lane masks. Returns the number of lanes rejected, so callers can check that the cases
// exercise both answers. Then adds the ray to `recent` and rejects the recent rays for each
// cylinder at 4, 8 and 16 lanes.
int check_lanes(const Cylinder (&cylinders)[4], const Ray& ray, RecentRays& recent) {
  constexpr std::size_t at = 3;
  CylinderLaneArrays arrays;
  arrays.assign(at + 4);
  CylinderFrame frames[4];
  for (int i = 0; i < 4; ++i) {
    frames[i] = cylinder_frame(cylinders[i]);
    arrays.set(at + static_cast<std::size_t>(i), frames[i]);
    EXPECT_TRUE(arrays.holds(at + static_cast<std::size_t>(i), frames[i]));
  }
  int rejected = 0;
  for (int lanes : {0xF, 0x6, 0x1, 0x0}) {
    const int mask = cylinders_surely_missed(arrays.at(at), lanes, ray);
    EXPECT_EQ(mask & ~lanes, 0) << "a lane outside the mask";
    for (int i = 0; i < 4; ++i) {
      if (((lanes >> i) & 1) == 0) continue;
      const bool expected = cylinder_surely_missed(frames[i], ray);
      const bool got = ((mask >> i) & 1) != 0;
      const Cylinder& c = cylinders[i];
      EXPECT_EQ(got, expected) << "lane " << i << " base=(" << c.base.x << ", " << c.base.y << ", " << c.base.z
                               << ") r=" << c.base_radius << " apex=(" << c.apex.x << ", " << c.apex.y << ", "
                               << c.apex.z << ") r=" << c.apex_radius << " o=(" << ray.origin.x << ", " << ray.origin.y
                               << ", " << ray.origin.z << ") d=(" << ray.direction.x << ", " << ray.direction.y << ", "
                               << ray.direction.z << ")";
      rejected += got ? 1 : 0;
    }
  }
  recent.push(ray);
  for (const CylinderFrame& frame : frames) {
    check_rays<4>(frame, recent);
    check_rays<8>(frame, recent);
    check_rays<16>(frame, recent);
  }
  return rejected;
}

Cylinder random_cylinder(Sampler& s, float extent) {
  const Vec3 base = random_point(s, extent);
  const float r0 = s.uni(0.05f, 2.f);
  // Cylinders, cones, and now and then a flat cone (rejection off) or a negative radius.
  const float r1 = s.rng.next_u32() % 4 == 0 ? s.uni(-1.f, 3.f) : r0;
  return {base, r0, base + random_point(s, 4.f), r1};
}

TEST(CylinderLanes, RandomCylindersAndRaysGiveTheScalarAnswer) {
  RecentRays recent;
  Sampler s(31);
  int rejected = 0, judged = 0;
  for (int iter = 0; iter < 20000 && !HasFailure(); ++iter) {
    Cylinder cylinders[4];
    for (Cylinder& c : cylinders) c = random_cylinder(s, 10.f);
    Ray ray{random_point(s, 12.f), 0.f, random_point(s, 1.f)};
    // Aim near one of the cylinders' axes half of the time: lines passing within a few radii,
    // where the margin decides.
    if (iter % 2 == 0) {
      const Cylinder& c = cylinders[iter % 4];
      const Vec3 on_axis = c.base + (c.apex - c.base) * s.rng.next_float();
      ray.direction = on_axis + random_point(s, 2.f * std::fabs(c.base_radius) + 0.1f) - ray.origin;
    }
    if (iter % 7 == 0) ray.direction = ray.direction * 1e-3f;  // lengths far from 1
    if (iter % 11 == 0) ray.direction = ray.direction * 1e3f;
    rejected += check_lanes(cylinders, ray, recent);
    judged += 4 + 2 + 1;
  }
  EXPECT_GT(rejected, judged / 10);
  EXPECT_LT(rejected, judged * 9 / 10);
}

// Rays parallel to an axis (never judged), across it at the smallest judged angle and just
// below it, and lines passing at the margin's edge of the radius.
TEST(CylinderLanes, AnglesAndDistancesAtTheLimitsGiveTheScalarAnswer) {
  RecentRays recent;
  Sampler s(8);
  const Cylinder along_z{{0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 5.f}, 1.f};
  int rejected = 0;
  for (int iter = 0; iter < 4000 && !HasFailure(); ++iter) {
    Cylinder cylinders[4] = {along_z, random_cylinder(s, 3.f), along_z, random_cylinder(s, 3.f)};
    const float sine = iter % 3 == 0 ? 0.f : s.uni(0.095f, 0.105f);
    const float off = s.uni(0.99f, 1.01f) * (1.f + 4e-5f * s.uni(0.f, 200.f));
    const Ray ray{{off, s.uni(-50.f, 50.f), s.uni(-10.f, 10.f)},
                  0.f,
                  {0.f, sine, std::sqrt(1.f - sine * sine) * (iter % 2 == 0 ? 1.f : -1.f)}};
    rejected += check_lanes(cylinders, ray, recent);
  }
  EXPECT_GT(rejected, 100);
}

// Where float runs out. Each odd cylinder sits in every lane position beside ordinary ones.
TEST(CylinderLanes, ExtremeInputsGiveTheScalarAnswer) {
  RecentRays recent;
  const std::vector<Cylinder> odd = {
      {{0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 0.f}, 1.f},           // no axis
      {{0.f, 0.f, 0.f}, 0.5f, {0.f, 0.f, 1.f}, 3.f},          // flatter than 45 degrees: rejection off
      {{0.f, 0.f, 0.f}, 0.f, {0.f, 1.f, 0.f}, 0.f},           // no radius
      {{0.f, 0.f, 0.f}, -1.f, {1.f, 0.f, 0.f}, -1.f},         // negative radii
      {{kNaN, 0.f, 0.f}, 1.f, {0.f, 0.f, 1.f}, 1.f},          // a NaN base
      {{0.f, 0.f, 0.f}, kNaN, {0.f, 0.f, 1.f}, 1.f},          // a NaN radius
      {{kInf, 0.f, 0.f}, 1.f, {0.f, 0.f, 1.f}, 1.f},          // an infinite base
      {{1e20f, 0.f, 0.f}, 1.f, {1e20f, 0.f, 1.f}, 1.f},       // far away: |f| beyond float's squares
      {{0.f, 0.f, 0.f}, 1e-20f, {0.f, 0.f, 1e-19f}, 1e-20f},  // tiny
  };
  const std::vector<Ray> rays = {
      {{5.f, 0.f, 0.f}, 0.f, {0.f, 1.f, 0.f}},    // beside the z axis, across it
      {{0.5f, 0.f, -5.f}, 0.f, {0.f, 0.f, 1.f}},  // along it
      {{0.f, 5.f, 0.f}, 0.f, {1.f, 0.f, 0.f}},      {{1.f, 2.f, 3.f}, 0.f, {0.f, 0.f, 0.f}},  // no direction
      {{1.f, 2.f, 3.f}, 0.f, {1e-7f, 0.f, 0.f}},                                              // |d|^2 below 1e-12
      {{1.f, 2.f, 3.f}, 0.f, {2e6f, 0.f, 0.f}},                                               // |d|^2 above 1e12
      {{0.f, 3.f, 0.f}, 0.f, {kNaN, 1.f, 0.f}},                                               // a NaN direction
      {{0.f, 3.f, 0.f}, 0.f, {kInf, 0.f, 0.f}},                                               // an infinite direction
      {{kNaN, 3.f, 0.f}, 0.f, {1.f, 0.f, 0.f}},                                               // a NaN origin
      {{1e19f, 3.f, 0.f}, 0.f, {-1.f, 0.f, 0.5f}},   // far origin: far_sq overflows
      {{2.f, 1e-20f, 0.f}, 0.f, {0.f, 0.f, 1.f}},    // along an axis
      {{-0.f, -0.f, -0.f}, 0.f, {-0.f, 1.f, -0.f}},  // signed zeros
  };
  const Cylinder plain{{0.5f, -0.25f, 0.f}, 0.3f, {0.5f, -0.25f, 2.f}, 0.3f};
  const Cylinder cone{{-3.f, 1.f, 0.f}, 1.f, {-1.f, 2.f, 1.f}, 0.2f};
  int rejected = 0;
  for (const Cylinder& c : odd) {
    for (int lane = 0; lane < 4; ++lane) {
      Cylinder cylinders[4] = {plain, cone, plain, cone};
      cylinders[lane] = c;
      for (const Ray& ray : rays) rejected += check_lanes(cylinders, ray, recent);
    }
  }
  EXPECT_GT(rejected, 0);
}

TEST(CylinderLanes, EmptyArraysHoldNothing) {
  CylinderLaneArrays arrays;
  EXPECT_TRUE(arrays.empty());
  arrays.assign(0);
  EXPECT_TRUE(arrays.empty());
  EXPECT_EQ(arrays.bytes(), 0u);
  arrays.assign(5);
  EXPECT_EQ(arrays.size(), 8u);  // 3 of padding
  EXPECT_EQ(arrays.bytes(), 8u * 28u);
}

}  // namespace
}  // namespace raylab
