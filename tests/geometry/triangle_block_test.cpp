// intersect_triangle_block must give, in every lane, bit for bit what intersect_triangle gives for
// that lane's triangle: the same hit or miss and the same t, u and v. The wide BVH's leaves rely
// on it to return the same hits as the binary BVH and brute force. Checked on random triangles
// and rays, on the shared edges and vertices of meshes (where watertightness is decided by the
// sign of exact edge functions), on axis-aligned rays and rays with zero, NaN or infinite
// components, on degenerate triangles, on huge and tiny coordinates, at both ends of [tmin, tmax]
// (the block accepts t == tmax, intersect_triangle does not), with lanes filled in any order and
// with unused lanes, which must never hit.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/geometry/triangle.h"
#include "raylab/geometry/triangle_block.h"

namespace raylab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::uint32_t bits(float x) { return std::bit_cast<std::uint32_t>(x); }

// Same bits; two NaNs count as equal (neither result should be NaN on a hit, but if the scalar
// code were compiled with commuted operands the payload could differ).
bool same(float a, float b) { return bits(a) == bits(b) || (std::isnan(a) && std::isnan(b)); }

// What intersect_triangle says for one triangle.
struct Reference {
  bool hit = false;
  float t = 0.f, u = 0.f, v = 0.f;
};

Reference reference(const Triangle& tri, const WatertightRay& wr, float tmin, float tmax) {
  Reference r;
  r.hit = intersect_triangle(tri, wr, tmin, tmax, r.t, r.u, r.v);
  return r;
}

// Counts what the comparisons saw, so a test can insist that its inputs were interesting.
struct Tally {
  long lanes = 0, hits = 0, boundary_hits = 0;
};

// Tests `block` (with `used` lanes, the others empty) against one ray and compares every lane
// with the reference. The block accepts t == tmax where intersect_triangle needs t < tmax: a lane
// the block reports and the reference rejects must sit exactly at tmax and be accepted by the
// reference with the next float above tmax as its limit.
void compare_block(const TriangleBlock4& block, const std::array<bool, 4>& used, const Ray& ray, float tmin, float tmax,
                   Tally& tally, const char* what) {
  const WatertightRay wr(ray);
  alignas(16) float t[4], u[4], v[4];
  for (int i = 0; i < 4; ++i) t[i] = u[i] = v[i] = -12345.f;
  const int mask = intersect_triangle_block(block, wr, tmin, tmax, t, u, v);
  ASSERT_EQ(mask & ~0xF, 0) << what << ": bits beyond the four lanes";
  for (int i = 0; i < 4; ++i) {
    const bool lane_hit = (mask >> i) & 1;
    if (!used[i]) {
      EXPECT_FALSE(lane_hit) << what << ": unused lane " << i << " hit";
      continue;
    }
    ++tally.lanes;
    const Triangle tri = block.triangle(i);
    const Reference ref = reference(tri, wr, tmin, tmax);
    if (ref.hit) {
      ++tally.hits;
      EXPECT_TRUE(lane_hit) << what << ": lane " << i << " missed a hit at t=" << ref.t;
      if (lane_hit) {
        EXPECT_TRUE(same(t[i], ref.t) && same(u[i], ref.u) && same(v[i], ref.v))
            << what << ": lane " << i << " t/u/v " << t[i] << " " << u[i] << " " << v[i] << " vs " << ref.t << " "
            << ref.u << " " << ref.v;
      }
      continue;
    }
    if (!lane_hit) continue;
    // Only allowed at exactly tmax.
    ++tally.boundary_hits;
    EXPECT_EQ(t[i], tmax) << what << ": lane " << i << " hit at t=" << t[i] << " which the reference rejects";
    if (std::isfinite(tmax)) {
      const Reference above = reference(tri, wr, tmin, std::nextafter(tmax, kInf));
      EXPECT_TRUE(above.hit) << what << ": lane " << i;
      EXPECT_TRUE(same(t[i], above.t) && same(u[i], above.u) && same(v[i], above.v)) << what << ": lane " << i;
    }
  }
}

// Puts `tris` into one block in lane order `lanes` (lanes[k] is where tris[k] goes); the rest
// of the lanes stay unused.
TriangleBlock4 make_block(const std::vector<Triangle>& tris, const std::array<int, 4>& lanes,
                          std::array<bool, 4>& used) {
  TriangleBlock4 block = empty_triangle_block();
  used = {false, false, false, false};
  for (std::size_t k = 0; k < tris.size(); ++k) {
    block.set(lanes[k], tris[k], static_cast<std::uint32_t>(k));
    used[lanes[k]] = true;
  }
  return block;
}

// Compares every group of up to four of `tris` against `ray`, with the lanes in a rotating order
// (the lane must not matter), and the first group in all 24 orders.
void compare_all(const std::vector<Triangle>& tris, const Ray& ray, float tmin, float tmax, Tally& tally,
                 const char* what, int rotation = 0) {
  std::array<int, 4> perm = {0, 1, 2, 3};
  for (int r = 0; r < rotation % 24; ++r) std::next_permutation(perm.begin(), perm.end());
  for (std::size_t first = 0; first < tris.size(); first += 4) {
    const std::size_t n = std::min<std::size_t>(4, tris.size() - first);
    const std::vector<Triangle> group(tris.begin() + long(first), tris.begin() + long(first + n));
    std::array<bool, 4> used;
    const TriangleBlock4 block = make_block(group, perm, used);
    compare_block(block, used, ray, tmin, tmax, tally, what);
    std::next_permutation(perm.begin(), perm.end());
  }
}

struct Sampler {
  Pcg32 rng;
  explicit Sampler(std::uint64_t seed) : rng(seed, 3) {}
  float uni(float lo, float hi) { return lo + (hi - lo) * rng.next_float(); }
  Vec3 in_box(float lo, float hi) { return {uni(lo, hi), uni(lo, hi), uni(lo, hi)}; }
};

TEST(TriangleBlock, EmptyBlockNeverHits) {
  const TriangleBlock4 block = empty_triangle_block();
  for (int i = 0; i < 4; ++i) EXPECT_EQ(block.id[i], TriangleBlock4::kNoPrimitive);
  const std::array<bool, 4> unused = {false, false, false, false};
  Tally tally;
  Sampler s(1);
  // Rays from anywhere, including the origin where the unused lanes' vertices sit, and NaN.
  std::vector<Ray> rays;
  for (int i = 0; i < 200; ++i) rays.push_back({s.in_box(-2.f, 2.f), 0.f, s.in_box(-1.f, 1.f), kInf});
  rays.push_back({Vec3(0.f), 0.f, {0.f, 0.f, 1.f}, kInf});
  rays.push_back({Vec3(0.f), -kInf, {1.f, 1.f, 1.f}, kInf});
  rays.push_back({{0.f, 0.f, -1.f}, 0.f, {0.f, 0.f, 1.f}, kInf});
  rays.push_back({{kNaN, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}, kInf});
  rays.push_back({Vec3(0.f), 0.f, {kNaN, kNaN, kNaN}, kInf});
  rays.push_back({Vec3(0.f), 0.f, Vec3(0.f), kInf});
  for (const Ray& r : rays) compare_block(block, unused, r, r.tmin, r.tmax, tally, "empty block");
}

TEST(TriangleBlock, RandomTrianglesAndRays) {
  Sampler s(2);
  Tally tally;
  for (int iter = 0; iter < 3000 && !HasFailure(); ++iter) {
    std::vector<Triangle> tris;
    const int n = 1 + static_cast<int>(s.rng.next_u32() % 4);
    for (int k = 0; k < n; ++k) {
      const Vec3 c = s.in_box(-5.f, 5.f);
      const float size = s.uni(0.1f, 4.f);
      tris.push_back({c + s.in_box(-size, size), c + s.in_box(-size, size), c + s.in_box(-size, size)});
    }
    Ray ray;
    ray.origin = s.in_box(-8.f, 8.f);
    // Aim at a point of one of the triangles half of the time, so that many lanes hit.
    if (s.rng.next_float() < 0.5f) {
      const Triangle& t = tris[s.rng.next_u32() % tris.size()];
      const float a = s.uni(-0.1f, 0.7f), b = s.uni(-0.1f, 0.5f);
      ray.direction = (t.p0 + (t.p1 - t.p0) * a + (t.p2 - t.p0) * b - ray.origin) * s.uni(0.1f, 10.f);
    } else {
      ray.direction = s.in_box(-1.f, 1.f);
    }
    const float tmin = s.rng.next_float() < 0.2f ? s.uni(0.f, 2.f) : 0.f;
    const float tmax = s.rng.next_float() < 0.2f ? s.uni(0.f, 3.f) : kInf;
    compare_all(tris, ray, tmin, tmax, tally, "random", iter);
  }
  EXPECT_GT(tally.hits, tally.lanes / 10) << "too few hits to mean anything";
}

// Both sides of tmin and tmax: the first hit's t as either bound, and the floats next to it.
TEST(TriangleBlock, BothSidesOfTheRangeEnds) {
  Sampler s(3);
  Tally tally;
  int tested = 0;
  for (int iter = 0; iter < 2000 && !HasFailure(); ++iter) {
    const Triangle tri{s.in_box(-3.f, 3.f), s.in_box(-3.f, 3.f), s.in_box(-3.f, 3.f)};
    Ray ray{s.in_box(-6.f, 6.f), 0.f, {}, kInf};
    ray.direction = (tri.p0 + tri.p1 + tri.p2) / 3.f - ray.origin;
    const WatertightRay wr(ray);
    const Reference r = reference(tri, wr, -kInf, kInf);
    if (!r.hit) continue;
    ++tested;
    const float below = std::nextafter(r.t, -kInf), above = std::nextafter(r.t, kInf);
    const std::vector<Triangle> tris = {tri, tri, tri};
    // tmax == t: the block hits (t <= tmax), the reference does not (t < tmax).
    {
      std::array<bool, 4> used;
      const TriangleBlock4 block = make_block(tris, {2, 0, 3, 1}, used);
      alignas(16) float t[4], u[4], v[4];
      const int mask = intersect_triangle_block(block, wr, -kInf, r.t, t, u, v);
      EXPECT_EQ(mask, 0b1101) << "t == tmax must be reported by the block";
      float rt, ru, rv;
      EXPECT_FALSE(intersect_triangle(tri, wr, -kInf, r.t, rt, ru, rv)) << "intersect_triangle needs t < tmax";
      for (int i : {0, 2, 3}) {
        EXPECT_EQ(bits(t[i]), bits(r.t));
        EXPECT_EQ(bits(u[i]), bits(r.u));
        EXPECT_EQ(bits(v[i]), bits(r.v));
      }
    }
    compare_all(tris, ray, -kInf, r.t, tally, "tmax = t", iter);
    compare_all(tris, ray, -kInf, below, tally, "tmax below t", iter);
    compare_all(tris, ray, -kInf, above, tally, "tmax above t", iter);
    compare_all(tris, ray, r.t, kInf, tally, "tmin = t", iter);
    compare_all(tris, ray, above, kInf, tally, "tmin above t", iter);
    compare_all(tris, ray, below, above, tally, "tmin, tmax around t", iter);
    compare_all(tris, ray, r.t, r.t, tally, "tmin = tmax = t", iter);
  }
  EXPECT_GT(tested, 500);
  EXPECT_GT(tally.boundary_hits, 500) << "the t == tmax case was not exercised";
}

// A height-field grid and a fan: rays aimed exactly at shared vertices and at points of shared
// edges, from many directions. Besides equality with the reference, the mesh must not leak: a
// ray through the interior of the mesh hits at least one triangle in some lane.
TEST(TriangleBlock, SharedEdgesAndVerticesOfMeshes) {
  Sampler s(4);
  constexpr int kN = 6;
  Vec3 grid[kN + 1][kN + 1];
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i)
      grid[j][i] = {float(i) * 0.37f - 1.1f, float(j) * 0.29f - 0.9f, 0.13f * std::sin(float(i * 3 + j * 5))};
  std::vector<Triangle> mesh;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      mesh.push_back({grid[j][i], grid[j][i + 1], grid[j + 1][i + 1]});
      mesh.push_back({grid[j][i], grid[j + 1][i + 1], grid[j + 1][i]});
    }
  // A fan of 13 triangles around a centre vertex, closed.
  const Vec3 centre{0.3f, 0.1f, 2.f};
  std::vector<Vec3> rim;
  for (int k = 0; k < 13; ++k) {
    const float a = float(k) * 6.2831853f / 13.f;
    rim.push_back(centre + Vec3{std::cos(a) * 1.3f, std::sin(a) * 0.7f, 0.2f * std::cos(3.f * a)});
  }
  std::vector<Triangle> fan;
  for (int k = 0; k < 13; ++k) fan.push_back({centre, rim[k], rim[(k + 1) % 13]});

  // Targets: interior vertices, midpoints and other points of interior edges.
  std::vector<Vec3> grid_targets, fan_targets;
  for (int j = 1; j < kN; ++j)
    for (int i = 1; i < kN; ++i) {
      grid_targets.push_back(grid[j][i]);
      for (const float a : {0.5f, 0.25f, 1.f / 3.f}) {
        grid_targets.push_back(grid[j][i] + (grid[j][i + 1] - grid[j][i]) * a);
        grid_targets.push_back(grid[j][i] + (grid[j + 1][i + 1] - grid[j][i]) * a);
        grid_targets.push_back(grid[j][i] + (grid[j + 1][i] - grid[j][i]) * a);
      }
    }
  fan_targets.push_back(centre);
  for (int k = 0; k < 13; ++k)
    for (const float a : {0.5f, 0.1f, 0.9f}) fan_targets.push_back(centre + (rim[k] - centre) * a);

  Tally tally;
  int leaks = 0, rays = 0;
  auto shoot = [&](const std::vector<Triangle>& tris, const std::vector<Vec3>& targets, float height, int seed_offset) {
    for (std::size_t k = 0; k < targets.size(); ++k) {
      for (int d = 0; d < 8; ++d) {
        Ray ray;
        const Vec3 off = s.in_box(-1.f, 1.f);
        switch (d) {
          case 0:  // straight down and straight up (axis-aligned, zero x and y components)
            ray.origin = targets[k] + Vec3{0.f, 0.f, height};
            ray.direction = {0.f, 0.f, -1.f};
            break;
          case 1:
            ray.origin = targets[k] - Vec3{0.f, 0.f, height};
            ray.direction = {-0.f, 0.f, 2.f};
            break;
          default:  // from a random point above or below, through the target
            ray.origin = targets[k] + Vec3{off.x, off.y, d % 2 ? height : -height};
            ray.direction = (targets[k] - ray.origin) * s.uni(0.5f, 3.f);
            break;
        }
        ++rays;
        compare_all(tris, ray, 0.f, kInf, tally, "mesh", int(k) * 8 + d + seed_offset);
        // Watertight: at least one triangle of the mesh is hit.
        const WatertightRay wr(ray);
        bool any = false;
        for (std::size_t first = 0; first < tris.size() && !any; first += 4) {
          const std::size_t n = std::min<std::size_t>(4, tris.size() - first);
          std::array<bool, 4> used;
          const TriangleBlock4 block = make_block(
              std::vector<Triangle>(tris.begin() + long(first), tris.begin() + long(first + n)), {0, 1, 2, 3}, used);
          alignas(16) float t[4], u[4], v[4];
          any = intersect_triangle_block(block, wr, 0.f, kInf, t, u, v) != 0;
        }
        if (!any && ++leaks <= 5) {
          ADD_FAILURE() << "ray through a shared edge or vertex leaked: o=(" << ray.origin.x << ", " << ray.origin.y
                        << ", " << ray.origin.z << ") d=(" << ray.direction.x << ", " << ray.direction.y << ", "
                        << ray.direction.z << ")";
        }
      }
    }
  };
  shoot(mesh, grid_targets, 3.f, 0);
  shoot(fan, fan_targets, 2.f, 5);
  EXPECT_EQ(leaks, 0) << "of " << rays << " rays";
  EXPECT_GE(tally.hits, rays);
}

// Rays along the axes and with zero, -0, tiny, NaN and infinite components; zero and NaN
// directions; NaN and infinite origins; degenerate triangles (a point, a segment, collinear
// vertices, repeated vertices), triangles in the axis planes.
TEST(TriangleBlock, AwkwardRaysAndDegenerateTriangles) {
  Sampler s(5);
  std::vector<Triangle> tris = {
      {{-1.f, -1.f, 2.f}, {1.f, -1.f, 2.f}, {0.f, 1.f, 2.f}},        // facing z
      {{0.f, -1.f, -1.f}, {0.f, 1.f, -1.f}, {0.f, 0.f, 1.f}},        // in the x = 0 plane
      {{-1.f, 0.f, -1.f}, {1.f, 0.f, -1.f}, {0.f, 0.f, 1.f}},        // in the y = 0 plane
      {{0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}},  // a point
      {{0.f, 0.f, 0.f}, {1.f, 1.f, 1.f}, {2.f, 2.f, 2.f}},           // collinear
      {{-1.f, 0.f, 1.f}, {-1.f, 0.f, 1.f}, {1.f, 0.f, 1.f}},         // a repeated vertex
      {{-1.f, 0.f, 3.f}, {1.f, 0.f, 3.f}, {0.f, 1e-30f, 3.f}},       // nearly a segment
      {{-2.f, -2.f, -3.f}, {2.f, -2.f, -3.f}, {-2.f, 2.f, -3.f}},    // behind some origins
  };
  const float comps[] = {0.f, -0.f, 1.f, -1.f, 0.5f, -2.f, 1e-45f, -1e-45f, 1e-30f, 1e30f, kInf, -kInf, kNaN};
  const float origins[] = {0.f, -0.f, 0.25f, -0.5f, 1.f, -3.f, 5.f, kNaN, kInf};
  Tally tally;
  for (int iter = 0; iter < 6000 && !HasFailure(); ++iter) {
    Ray ray;
    for (int a = 0; a < 3; ++a) {
      ray.direction[a] = comps[s.rng.next_u32() % std::size(comps)];
      // Mostly ordinary origins; the NaN and infinite ones rarely, so that many rays can hit.
      ray.origin[a] = s.rng.next_float() < 0.9f ? origins[s.rng.next_u32() % 7] : origins[s.rng.next_u32() % 9];
    }
    if (iter % 7 == 0) ray.direction = Vec3(0.f);
    const float tmin = iter % 5 == 0 ? -kInf : 0.f;
    const float tmax = iter % 3 == 0 ? 10.f : kInf;
    compare_all(tris, ray, tmin, tmax, tally, "awkward", iter);
  }
  EXPECT_GT(tally.hits, 1000);
}

// Coordinates from 1e-30 to 1e30 (products that overflow to infinity or round to zero in float
// but not in the exact double edge functions), far from the origin and tiny close to it.
TEST(TriangleBlock, HugeAndTinyCoordinates) {
  Sampler s(6);
  Tally tally;
  for (int iter = 0; iter < 4000 && !HasFailure(); ++iter) {
    const float scale = std::pow(10.f, s.uni(-30.f, 30.f));
    const Vec3 c = s.in_box(-1.f, 1.f) * (s.rng.next_float() < 0.5f ? scale : 1.f);
    std::vector<Triangle> tris;
    for (int k = 0; k < 4; ++k) {
      tris.push_back({c + s.in_box(-scale, scale), c + s.in_box(-scale, scale), c + s.in_box(-scale, scale)});
    }
    Ray ray;
    ray.origin = c + s.in_box(-3.f * scale, 3.f * scale);
    const Triangle& t = tris[iter % 4];
    ray.direction = (t.p0 + t.p1 + t.p2) / 3.f - ray.origin;
    if (iter % 4 == 1) ray.direction = ray.direction * 1e-20f;
    if (iter % 4 == 2) ray.direction = ray.direction * 1e20f;
    compare_all(tris, ray, 0.f, kInf, tally, "scaled", iter);
  }
  EXPECT_GT(tally.hits, 2000);
}

}  // namespace
}  // namespace raylab
