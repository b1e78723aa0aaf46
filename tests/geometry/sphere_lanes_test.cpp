// The SIMD sphere tests against the scalar test they must reproduce, intersect_sphere: four
// spheres against one ray (sphere_lanes.h) and one sphere against 4, 8 or 16 rays
// (sphere_rays.h, for packets) give in every lane the same answer and bit for bit the same
// distance, on random spheres and rays, on interval ends placed exactly at the roots, and on
// the inputs where float runs out (overflowing discriminants, radii whose square underflows, NaN
// and infinities, zero directions, signed zeros). The ray-parallel test takes each case's ray
// in one lane beside the rays of the cases before it.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "raylab/core/float_neighbour.h"
#include "raylab/core/rng.h"
#include "raylab/geometry/sphere_lanes.h"
#include "raylab/geometry/sphere_rays.h"
#include "recent_rays.h"

namespace raylab {
namespace {

using test::RecentRays;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

float uniform(Pcg32& rng, float lo, float hi) { return lo + (hi - lo) * rng.next_float(); }

Vec3 random_point(Pcg32& rng, float extent) {
  return {uniform(rng, -extent, extent), uniform(rng, -extent, extent), uniform(rng, -extent, extent)};
}

// Four spheres with centres in [-extent, extent]^3 and radii in [r_lo, r_hi).
void random_spheres(Pcg32& rng, Sphere (&spheres)[4], float extent, float r_lo, float r_hi) {
  for (Sphere& s : spheres) s = {random_point(rng, extent), uniform(rng, r_lo, r_hi)};
}

// Tests `sphere` against the first N of `recent`'s rays as lanes, with every lane and with
// every other lane, and compares each lane with intersect_sphere.
template <int N>
void check_rays(const Sphere& sphere, const RecentRays& recent) {
  using F = simd::WideFloat<N>;
  const RayLanes<N> rays = RayLanes<N>::load(recent.ox, recent.oy, recent.oz, recent.dx, recent.dy, recent.dz);
  for (const unsigned lanes : {(1u << N) - 1u, 0x5555u & ((1u << N) - 1u)}) {
    float t[N];
    for (float& x : t) x = -1.f;
    const unsigned mask = intersect_sphere_rays<N>(sphere, rays, lanes, F::load(recent.tmin), F::load(recent.tmax), t);
    EXPECT_EQ(mask & ~lanes, 0u) << "a lane outside the mask";
    for (int i = 0; i < N; ++i) {
      if (((lanes >> i) & 1u) == 0) continue;
      const Ray ray = recent.ray(i);
      float expected = -1.f;
      const bool hit = intersect_sphere(sphere, ray, ray.tmin, ray.tmax, expected);
      const bool got = ((mask >> i) & 1u) != 0;
      EXPECT_EQ(got, hit) << N << " rays, lane " << i << " c=(" << sphere.center.x << ", " << sphere.center.y << ", "
                          << sphere.center.z << ") r=" << sphere.radius << " o=(" << ray.origin.x << ", "
                          << ray.origin.y << ", " << ray.origin.z << ") d=(" << ray.direction.x << ", "
                          << ray.direction.y << ", " << ray.direction.z << ") [" << ray.tmin << ", " << ray.tmax << ")";
      if (got && hit) {
        EXPECT_EQ(std::bit_cast<std::uint32_t>(t[i]), std::bit_cast<std::uint32_t>(expected))
            << N << " rays, lane " << i << ": " << t[i] << " against " << expected;
      }
    }
  }
}

// Tests the four spheres as one set of lanes with several lane masks, and compares each lane
// with intersect_sphere; then adds the ray to `recent` and tests each sphere against the recent
// rays at 4, 8 and 16 lanes. Returns the number of lanes hit (over all masks) so callers can
// check that the cases exercise hits.
int check_lanes(const Sphere (&spheres)[4], const Ray& ray, float tmin, float tmax, RecentRays& recent) {
  recent.push(ray, tmin, tmax);
  for (const Sphere& sphere : spheres) {
    check_rays<4>(sphere, recent);
    check_rays<8>(sphere, recent);
    check_rays<16>(sphere, recent);
  }
  float x[4], y[4], z[4], r[4];
  for (int i = 0; i < 4; ++i) x[i] = spheres[i].center.x, y[i] = spheres[i].center.y, z[i] = spheres[i].center.z;
  for (int i = 0; i < 4; ++i) r[i] = spheres[i].radius;
  const SphereLanes lanes_of{x, y, z, r};
  int hits = 0;
  for (int lanes : {0xF, 0x5, 0x8, 0x0}) {
    float t[4] = {-1.f, -1.f, -1.f, -1.f};
    const int mask = intersect_sphere_lanes(lanes_of, lanes, ray, tmin, tmax, t);
    EXPECT_EQ(mask & ~lanes, 0) << "a lane outside the mask";
    for (int i = 0; i < 4; ++i) {
      if (((lanes >> i) & 1) == 0) continue;
      float expected = -1.f;
      const bool hit = intersect_sphere(spheres[i], ray, tmin, tmax, expected);
      const bool got = ((mask >> i) & 1) != 0;
      EXPECT_EQ(got, hit) << "lane " << i << " c=(" << spheres[i].center.x << ", " << spheres[i].center.y << ", "
                          << spheres[i].center.z << ") r=" << spheres[i].radius << " o=(" << ray.origin.x << ", "
                          << ray.origin.y << ", " << ray.origin.z << ") d=(" << ray.direction.x << ", "
                          << ray.direction.y << ", " << ray.direction.z << ") [" << tmin << ", " << tmax << ")";
      if (got && hit) {
        EXPECT_EQ(std::bit_cast<std::uint32_t>(t[i]), std::bit_cast<std::uint32_t>(expected))
            << "lane " << i << ": " << t[i] << " against " << expected;
      }
      hits += hit ? 1 : 0;
    }
  }
  return hits;
}

TEST(SphereLanes, RandomSpheresAndRaysGiveTheScalarAnswer) {
  RecentRays recent;
  Pcg32 rng(12, 7);
  int hits = 0;
  for (int iter = 0; iter < 20000 && !HasFailure(); ++iter) {
    Sphere spheres[4];
    random_spheres(rng, spheres, 10.f, 0.01f, 3.f);
    Ray ray{random_point(rng, 12.f), 0.f, random_point(rng, 1.f)};
    // Aim at one of the spheres half of the time, so that most sets of lanes hold a hit.
    if (iter % 2 == 0) ray.direction = spheres[iter % 4].center + random_point(rng, 1.f) - ray.origin;
    const float tmin = iter % 3 == 0 ? 0.f : uniform(rng, -2.f, 1.f);
    const float tmax = iter % 5 == 0 ? kInf : uniform(rng, 0.5f, 3.f);
    hits += check_lanes(spheres, ray, tmin, tmax, recent);
  }
  EXPECT_GT(hits, 10000);
}

// Interval ends exactly at each root, and one float either side: where `<` and `<=` differ.
TEST(SphereLanes, IntervalEndsAtTheRoots) {
  RecentRays recent;
  Pcg32 rng(5, 9);
  int hits = 0;
  for (int iter = 0; iter < 3000 && !HasFailure(); ++iter) {
    Sphere spheres[4];
    random_spheres(rng, spheres, 4.f, 0.5f, 2.f);
    Ray ray{random_point(rng, 8.f), 0.f, {}};
    ray.direction = spheres[0].center + random_point(rng, 0.5f) - ray.origin;  // at sphere 0
    float t_near = 0.f, t_far = 0.f;
    if (!intersect_sphere(spheres[0], ray, -kInf, kInf, t_near)) continue;
    if (!intersect_sphere(spheres[0], ray, next_float_up(t_near), kInf, t_far)) t_far = t_near;
    for (const float root : {t_near, t_far}) {
      for (const float end : {std::nextafter(root, -kInf), root, next_float_up(root)}) {
        hits += check_lanes(spheres, ray, end, kInf, recent);
        hits += check_lanes(spheres, ray, -kInf, end, recent);
      }
    }
  }
  EXPECT_GT(hits, 1000);
}

// Where float runs out. Each case sits in every lane position, beside ordinary spheres.
TEST(SphereLanes, ExtremeInputsGiveTheScalarAnswer) {
  RecentRays recent;
  const std::vector<Sphere> odd = {
      {{0.f, 0.f, 0.f}, 3e10f},   // the discriminant overflows for long directions
      {{0.f, 0.f, 0.f}, 1e-30f},  // the radius's square underflows to 0
      {{0.f, 0.f, 0.f}, 0.f},     // no radius
      {{0.f, 0.f, 0.f}, -1.f},    // a negative radius: its square is what counts
      {{kNaN, 0.f, 0.f}, 1.f},    // a NaN centre
      {{0.f, 0.f, 0.f}, kNaN},    // a NaN radius
      {{kInf, 0.f, 0.f}, 1.f},    // an infinite centre
      {{1e4f, 0.f, 0.f}, 1e-4f},  // far and tiny
      {{0.f, 1.f, 0.f}, 1.f},     // tangent to rays along x through the origin
      {{0.f, 0.f, 0.f}, 1.f},     // around the origin (rays start inside)
  };
  const std::vector<Ray> rays = {
      {{-6e10f, 0.f, 0.f}, 0.f, {1e9f, 0.f, 0.f}},    // long direction against the huge sphere
      {{-6e10f, 1e10f, 0.f}, 0.f, {1e9f, 0.f, 0.f}},  // the same, off centre
      {{-5.f, 0.f, 0.f}, 0.f, {1.f, 0.f, 0.f}},
      {{0.f, 0.f, 0.f}, 0.f, {1.f, 0.f, 0.f}},  // through the tangent point; b = +0 or -0
      {{0.f, 0.f, 0.f}, 0.f, {-1.f, -0.f, 0.f}},
      {{-0.f, -0.f, -0.f}, 0.f, {0.f, 0.f, 1e-20f}},  // a direction whose square underflows
      {{1.f, 2.f, 3.f}, 0.f, {0.f, 0.f, 0.f}},        // no direction
      {{0.f, 0.f, 0.f}, 0.f, {kNaN, 1.f, 0.f}},
      {{0.f, 0.f, 0.f}, 0.f, {kInf, 0.f, 0.f}},
      {{0.f, 0.f, 0.f}, 0.f, {1e19f, 1e19f, 0.f}},  // dot(d, d) overflows
      {{1e4f - 5.f, 0.f, 0.f}, 0.f, {1.f, 1e-9f, 0.f}},
  };
  const Sphere plain{{0.5f, -0.25f, 0.f}, 2.f};
  int hits = 0;
  for (const Sphere& s : odd) {
    for (int lane = 0; lane < 4; ++lane) {
      Sphere spheres[4] = {plain, plain, plain, plain};
      spheres[lane] = s;
      spheres[(lane + 1) % 4] = Sphere{{-0.5f, 0.25f, 1.f}, 0.75f};
      for (const Ray& ray : rays) {
        for (const float tmin : {0.f, -kInf, -0.f}) hits += check_lanes(spheres, ray, tmin, kInf, recent);
        hits += check_lanes(spheres, ray, 0.f, 1.f, recent);
      }
    }
  }
  EXPECT_GT(hits, 100);
}

}  // namespace
}  // namespace raylab
