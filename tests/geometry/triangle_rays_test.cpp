// intersect_triangle_rays must give, in every ray lane, bit for bit what intersect_triangle gives
// for that ray: packet leaves rely on it to return exactly the single-ray hits. Checked on
// random triangles against groups of nearby rays (as a packet's), on rays through the shared
// vertices and edges of a mesh (where the exact edge functions decide), on degenerate
// triangles, at both ends of [tmin, tmax], and with the lanes' ranges all different.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/geometry/triangle.h"
#include "raylab/geometry/triangle_rays.h"

namespace raylab {
namespace {

constexpr int kLanes = simd::kNativeBoxWidth;
using Lanes = simd::WideFloat<kLanes>;

std::uint32_t bits(float x) { return std::bit_cast<std::uint32_t>(x); }

// Lanes of `rays`' watertight constants; false when they do not share one axis permutation.
bool make_lanes(const std::vector<Ray>& rays, WatertightRays<kLanes>& out) {
  std::vector<WatertightRay> w(rays.begin(), rays.end());
  for (const WatertightRay& x : w) {
    if (x.kx != w[0].kx || x.ky != w[0].ky || x.kz != w[0].kz) return false;
  }
  out = watertight_rays<kLanes>(w.data());
  return true;
}

struct Tally {
  long groups = 0, lanes = 0, hits = 0;
};

// Tests triangle `lane` of `block` against `rays` (each with its own [tmin[i], tmax[i]]) and
// compares every lane with intersect_triangle. The kernel accepts t == tmax where the scalar test
// needs t < tmax, so the scalar test gets the next float above tmax as its limit.
void compare(const TriangleBlock4& block, int lane, const std::vector<Ray>& rays, const float* tmin, const float* tmax,
             Tally& tally) {
  WatertightRays<kLanes> lanes;
  if (!make_lanes(rays, lanes)) return;
  ++tally.groups;
  alignas(64) float t[kLanes], u[kLanes], v[kLanes];
  const unsigned mask =
      intersect_triangle_rays<kLanes>(block, lane, lanes, Lanes::load(tmin), Lanes::load(tmax), t, u, v);
  const Triangle tri = block.triangle(lane);
  for (int i = 0; i < kLanes; ++i) {
    ++tally.lanes;
    float rt = 0.f, ru = 0.f, rv = 0.f;
    const bool ref =
        intersect_triangle(tri, WatertightRay(rays[i]), tmin[i], std::nextafter(tmax[i], INFINITY), rt, ru, rv);
    const bool got = (mask >> i) & 1u;
    ASSERT_EQ(got, ref) << "ray lane " << i << ": kernel " << got << ", scalar " << ref << " (t " << rt << ")";
    if (!ref) continue;
    ++tally.hits;
    EXPECT_EQ(bits(t[i]), bits(rt)) << "t of lane " << i;
    EXPECT_EQ(bits(u[i]), bits(ru)) << "u of lane " << i;
    EXPECT_EQ(bits(v[i]), bits(rv)) << "v of lane " << i;
  }
  EXPECT_EQ(mask >> kLanes, 0u) << "bits beyond the lanes";
}

Vec3 random_point(Pcg32& rng, float scale) {
  return {(rng.next_float() * 2.f - 1.f) * scale, (rng.next_float() * 2.f - 1.f) * scale,
          (rng.next_float() * 2.f - 1.f) * scale};
}

// kLanes rays from near `origin` toward points near `target`, as a pixel tile's or a shadow
// packet's rays.
std::vector<Ray> ray_group(Pcg32& rng, Vec3 origin, Vec3 target, float origin_spread, float target_spread) {
  std::vector<Ray> rays(kLanes);
  for (Ray& r : rays) {
    r.origin = origin + random_point(rng, origin_spread);
    r.direction = target + random_point(rng, target_spread) - r.origin;
  }
  return rays;
}

TEST(TriangleRays, RandomTrianglesAndRayGroups) {
  Pcg32 rng(7);
  Tally tally;
  for (int k = 0; k < 3000; ++k) {
    TriangleBlock4 block = empty_triangle_block();
    for (int l = 0; l < 4; ++l) {
      const Vec3 c = random_point(rng, 2.f);
      block.set(l, {c + random_point(rng, 0.5f), c + random_point(rng, 0.5f), c + random_point(rng, 0.5f)},
                static_cast<std::uint32_t>(l));
    }
    const int lane = k % 4;
    const Triangle tri = block.triangle(lane);
    const Vec3 centre = (tri.p0 + tri.p1 + tri.p2) * (1.f / 3.f);
    const std::vector<Ray> rays = ray_group(rng, random_point(rng, 6.f), centre, k % 2 ? 0.f : 0.3f, 0.1f);
    alignas(64) float tmin[kLanes], tmax[kLanes];
    for (int i = 0; i < kLanes; ++i) {
      tmin[i] = i % 3 == 0 ? 0.f : 0.2f * rng.next_float();
      tmax[i] = i % 4 == 0 ? INFINITY : 0.5f + rng.next_float();
    }
    compare(block, lane, rays, tmin, tmax, tally);
  }
  EXPECT_GT(tally.groups, 1000);
  EXPECT_GT(tally.hits, tally.lanes / 10) << "too few hits to mean anything";
}

// Rays aimed exactly at the vertices and edge midpoints of a fan of triangles sharing a vertex:
// the cases the exact edge functions exist for.
TEST(TriangleRays, SharedVerticesAndEdges) {
  Pcg32 rng(11);
  Tally tally;
  const Vec3 hub{0.1f, 0.2f, 0.3f};
  std::vector<Vec3> rim;
  for (int i = 0; i < 6; ++i) {
    const float a = 2.f * 3.14159265f * static_cast<float>(i) / 6.f;
    rim.push_back({hub.x + std::cos(a), hub.y + std::sin(a), hub.z + 0.1f * static_cast<float>(i % 2)});
  }
  std::vector<Vec3> targets{hub};
  for (std::size_t i = 0; i < rim.size(); ++i) {
    targets.push_back(rim[i]);
    targets.push_back((hub + rim[i]) * 0.5f);
    targets.push_back((rim[i] + rim[(i + 1) % rim.size()]) * 0.5f);
  }
  for (std::size_t f = 0; f < rim.size(); ++f) {
    TriangleBlock4 block = empty_triangle_block();
    block.set(0, {hub, rim[f], rim[(f + 1) % rim.size()]}, 0);
    for (int g = 0; g < 40; ++g) {
      std::vector<Ray> rays(kLanes);
      const Vec3 origin = random_point(rng, 1.f) + Vec3{0.f, 0.f, 4.f};
      for (int i = 0; i < kLanes; ++i) {
        rays[i].origin = origin + random_point(rng, 0.01f);
        rays[i].direction = targets[(g * kLanes + i) % targets.size()] - rays[i].origin;
      }
      alignas(64) float tmin[kLanes], tmax[kLanes];
      for (int i = 0; i < kLanes; ++i) tmin[i] = 0.f, tmax[i] = INFINITY;
      compare(block, 0, rays, tmin, tmax, tally);
    }
  }
  EXPECT_GT(tally.groups, 100);
  EXPECT_GT(tally.hits, 200);
}

// Degenerate triangles (a point, a segment, collinear vertices) are never hit, and a range that
// ends exactly at a hit's t keeps it at tmax and drops it at tmin's other side.
TEST(TriangleRays, DegenerateTrianglesAndRangeEnds) {
  Pcg32 rng(3);
  Tally tally;
  const Vec3 p{0.5f, 0.25f, 0.f}, q{1.f, 0.5f, 0.f};
  const Triangle degenerate[] = {{p, p, p}, {p, q, q}, {p, q, p + (q - p) * 0.5f}};
  for (const Triangle& tri : degenerate) {
    TriangleBlock4 block = empty_triangle_block();
    block.set(2, tri, 2);
    const std::vector<Ray> rays = ray_group(rng, {0.7f, 0.4f, 3.f}, p, 0.f, 0.3f);
    alignas(64) float tmin[kLanes], tmax[kLanes];
    for (int i = 0; i < kLanes; ++i) tmin[i] = 0.f, tmax[i] = INFINITY;
    WatertightRays<kLanes> lanes;
    ASSERT_TRUE(make_lanes(rays, lanes));
    alignas(64) float t[kLanes], u[kLanes], v[kLanes];
    EXPECT_EQ(intersect_triangle_rays<kLanes>(block, 2, lanes, Lanes::load(tmin), Lanes::load(tmax), t, u, v), 0u);
  }
  // A flat triangle under a group of rays from above: find each ray's t, then put it at each end.
  TriangleBlock4 block = empty_triangle_block();
  block.set(1, {{-1.f, -1.f, 0.f}, {2.f, -1.f, 0.f}, {-1.f, 2.f, 0.f}}, 1);
  // Targets within 0.1 of (0.2, 0.2, 0) in all three axes: every ray meets the plane well inside.
  const std::vector<Ray> rays = ray_group(rng, {0.f, 0.f, 2.f}, {0.2f, 0.2f, 0.f}, 0.1f, 0.1f);
  alignas(64) float tmin[kLanes], tmax[kLanes], t_hit[kLanes];
  for (int i = 0; i < kLanes; ++i) {
    float u = 0.f, v = 0.f;
    ASSERT_TRUE(intersect_triangle(block.triangle(1), WatertightRay(rays[i]), 0.f, INFINITY, t_hit[i], u, v));
  }
  for (int end = 0; end < 4; ++end) {
    for (int i = 0; i < kLanes; ++i) {
      tmin[i] = end == 0 ? t_hit[i] : end == 1 ? std::nextafter(t_hit[i], INFINITY) : 0.f;
      tmax[i] = end == 2 ? t_hit[i] : end == 3 ? std::nextafter(t_hit[i], 0.f) : INFINITY;
    }
    compare(block, 1, rays, tmin, tmax, tally);
  }
  EXPECT_EQ(tally.groups, 4);
  EXPECT_EQ(tally.hits, 2 * kLanes) << "hits kept at t == tmin and t == tmax, dropped just outside";
}

}  // namespace
}  // namespace raylab
