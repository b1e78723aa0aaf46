// The float rejection in front of the cylinder test (cylinder_surely_missed) may only turn away
// rays the double-precision test misses: intersect_cylinder must give intersect_cylinder_exact's
// answers bit for bit, on random rays and on the hardest ones, lines that pass the axis at the
// radius to within a few parts in a million, and rays that leave the surface itself (as
// reflected and shadow rays do). And it must actually reject most rays that pass beside, or it
// buys nothing.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/geometry/cylinder.h"

namespace raylab {
namespace {

struct Answer {
  bool hit = false;
  float t = 0.f, height = 0.f;
};

bool same(const Answer& a, const Answer& b) {
  return a.hit == b.hit &&
         (!a.hit || (std::bit_cast<std::uint32_t>(a.t) == std::bit_cast<std::uint32_t>(b.t) &&
                     std::bit_cast<std::uint32_t>(a.height) == std::bit_cast<std::uint32_t>(b.height)));
}

Answer filtered(const CylinderFrame& f, const Ray& r) {
  Answer a;
  a.hit = intersect_cylinder(f, r, r.tmin, r.tmax, a.t, a.height);
  return a;
}

Answer exact(const CylinderFrame& f, const Ray& r) {
  Answer a;
  a.hit = intersect_cylinder_exact(f, r, r.tmin, r.tmax, a.t, a.height);
  return a;
}

Vec3 random_unit(Pcg32& rng) {
  for (;;) {
    const Vec3 v{2.f * rng.next_float() - 1.f, 2.f * rng.next_float() - 1.f, 2.f * rng.next_float() - 1.f};
    const float l = length(v);
    if (l > 0.1f && l <= 1.f) return v / l;
  }
}

// Cylinders and cones of several sizes and slopes, at several distances from the origin
// (the rings' segments, the tree's tapering branches, a flat cone past the 45-degree limit).
std::vector<Cylinder> shapes() {
  return {
      {{0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 4.f}, 1.f},
      {{0.930995f, 2.61313f, 0.f}, 0.07412f, {0.287693f, 1.7277f, 0.f}, 0.07412f},
      {{1.f, 2.f, 3.f}, 0.3f, {1.5f, 2.5f, 7.f}, 0.05f},
      {{0.f, 0.f, 0.f}, 1.f, {0.f, 1.f, 0.f}, 0.f},
      {{100.f, -50.f, 20.f}, 2.f, {103.f, -46.f, 20.f}, 2.f},
      {{0.f, 0.f, 0.f}, 3.f, {0.f, 0.5f, 0.f}, 0.5f},  // radius changes faster than height
      {{1e-3f, 2e-3f, 0.f}, 1e-4f, {1.2e-3f, 2.5e-3f, 1e-4f}, 1e-4f},
  };
}

TEST(CylinderRejection, RandomRaysGetTheExactAnswers) {
  Pcg32 rng(31);
  int rejected = 0, beside = 0;
  for (const Cylinder& c : shapes()) {
    const CylinderFrame f = cylinder_frame(c);
    const Vec3 mid = (c.base + c.apex) * 0.5f;
    const float scale = length(c.apex - c.base) + std::fmax(c.base_radius, c.apex_radius);
    for (int i = 0; i < 20000; ++i) {
      // Aim at a point near the shape from a few sizes away, so that many rays pass close.
      const Vec3 target = mid + random_unit(rng) * (scale * rng.next_float());
      const Vec3 origin = target + random_unit(rng) * (scale * (0.5f + 8.f * rng.next_float()));
      const Ray ray{origin, 0.f, (target - origin) * (0.25f + 4.f * rng.next_float())};
      const Answer e = exact(f, ray);
      ASSERT_TRUE(same(filtered(f, ray), e)) << "shape " << c.base.x << " ray " << i;
      if (!e.hit) ++beside;
      if (cylinder_surely_missed(f, ray)) ++rejected;
    }
  }
  // Most of the rays that miss are turned away by the float test.
  EXPECT_GT(rejected, beside / 2) << rejected << " of " << beside;
}

TEST(CylinderRejection, LinesGrazingTheRadiusGetTheExactAnswers) {
  Pcg32 rng(7);
  int tried = 0;
  for (const Cylinder& c : shapes()) {
    const CylinderFrame f = cylinder_frame(c);
    const Vec3 w = normalize(c.apex - c.base);
    const float radius = std::fmax(c.base_radius, c.apex_radius);
    for (int i = 0; i < 4000; ++i) {
      // A line at distance radius * (1 + e) from the axis, |e| up to 1e-3, crossing the
      // perpendicular to the axis through a point of the height range.
      const float e = (2.f * rng.next_float() - 1.f) * std::pow(10.f, -3.f - 4.f * rng.next_float());
      Vec3 side = cross(w, random_unit(rng));
      if (length(side) < 1e-3f) continue;
      side = normalize(side);
      const Vec3 along = normalize(cross(w, side));  // perpendicular to the axis and to `side`
      const Vec3 foot = c.base + (c.apex - c.base) * rng.next_float() + side * (radius * (1.f + e));
      // Tilt the line out of the perpendicular plane by up to about 80 degrees.
      const Vec3 dir = normalize(along + w * (5.f * (2.f * rng.next_float() - 1.f)));
      const float back = (0.5f + 10.f * rng.next_float()) * radius + length(c.apex - c.base);
      const Ray ray{foot - dir * back, 0.f, dir};
      ASSERT_TRUE(same(filtered(f, ray), exact(f, ray))) << "shape " << c.base.x << " ray " << i << " e " << e;
      ++tried;
    }
  }
  EXPECT_GT(tried, 20000);
}

// Rays leaving a point of the surface, moved off it by relative amounts from 1e-2 down to 1e-9
// (below float's resolution) to either side, in every direction, from tmin 0, from a negative
// tmin and from a positive one: the rejection must never turn away a ray the double test hits
// (the ones that cross the cylinder, or start inside it, or from before the origin).
TEST(CylinderRejection, RaysLeavingTheSurfaceGetTheExactAnswers) {
  Pcg32 rng(45);
  int hits = 0, misses = 0;
  for (const Cylinder& c : shapes()) {
    const CylinderFrame f = cylinder_frame(c);
    const Vec3 axis = c.apex - c.base;
    const Vec3 w = normalize(axis);
    for (int i = 0; i < 20000; ++i) {
      const float height = rng.next_float();
      Vec3 across = cross(w, random_unit(rng));
      if (length(across) < 1e-3f) continue;
      across = normalize(across);
      const float radius = c.base_radius + (c.apex_radius - c.base_radius) * height;
      const float offset = (rng.next_float() < 0.5f ? 1.f : -1.f) * std::pow(10.f, -2.f - 7.f * rng.next_float());
      const Vec3 origin = c.base + axis * height + across * (radius * (1.f + offset));
      const Vec3 dir = random_unit(rng) * (0.25f + 4.f * rng.next_float());
      const float tmin = i % 8 == 0 ? -0.5f : (i % 8 == 1 ? 1e-3f : 0.f);
      const Ray ray{origin, tmin, dir};
      const Answer e = exact(f, ray);
      ASSERT_TRUE(same(filtered(f, ray), e)) << "shape " << c.base.x << " ray " << i << " offset " << offset;
      (e.hit ? hits : misses) += 1;
    }
  }
  // Both answers occur often: the cases reach the rays that re-enter and those that leave.
  EXPECT_GT(hits, 10000);
  EXPECT_GT(misses, 10000);
}

TEST(CylinderRejection, DegenerateRaysAreLeftToTheExactTest) {
  const CylinderFrame f = cylinder_frame({{0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 4.f}, 1.f});
  const float nan = std::nanf("");
  const float inf = INFINITY;
  for (const Ray& ray : {Ray{{5.f, 0.f, 2.f}, 0.f, {0.f, 0.f, 0.f}}, Ray{{5.f, 0.f, 2.f}, 0.f, {nan, 0.f, 0.f}},
                         Ray{{nan, 0.f, 2.f}, 0.f, {-1.f, 0.f, 0.f}}, Ray{{5.f, 0.f, 2.f}, 0.f, {-inf, 0.f, 0.f}},
                         Ray{{5.f, 0.f, 2.f}, 0.f, {0.f, 0.f, 1.f}}, Ray{{1e30f, 0.f, 2.f}, 0.f, {0.f, 1.f, 0.f}},
                         Ray{{5.f, 0.f, 2.f}, 0.f, {-1e-20f, 0.f, 0.f}}}) {
    EXPECT_FALSE(cylinder_surely_missed(f, ray)) << ray.origin.x << " " << ray.direction.x;
    EXPECT_TRUE(same(filtered(f, ray), exact(f, ray)));
  }
  // A flat cone (radius changing faster than height) is never judged by the float test.
  const CylinderFrame flat = cylinder_frame({{0.f, 0.f, 0.f}, 3.f, {0.f, 0.5f, 0.f}, 0.5f});
  EXPECT_FALSE(cylinder_surely_missed(flat, Ray{{100.f, 0.25f, 50.f}, 0.f, {0.f, 0.f, -1.f}}));
  // A line that far beside a cylinder is.
  EXPECT_TRUE(cylinder_surely_missed(f, Ray{{100.f, 2.f, 50.f}, 0.f, {0.f, -1.f, 0.f}}));
}

}  // namespace
}  // namespace raylab
