// The tie rule of the watertight triangle test (`edge_with_tie_broken` in triangle.h): an edge
// function that is exactly zero gets the sign it would have with the ray moved by an
// infinitesimal, so that each crossing of a surface is counted exactly once. Checked on rays
// built so that the edge functions really are zero: the target point lies on a coarse grid and
// the ray's dominant direction component is a power of two, so the test's shear is exact and the
// target lands exactly on the ray (each test checks that it does). Through the shared edge of two
// triangles: exactly one hit, or 0 or 2 where the two are seen from different sides. Through the
// centre and the spokes of a fan: exactly one. Through the vertices and edges of closed meshes:
// an even number of hits from outside, exactly one from inside a convex one. And the scalar,
// block (4 lanes) and ray-parallel (8 and 16 lanes) kernels agree bit for bit on all of these.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/geometry/triangle.h"
#include "raylab/geometry/triangle_block.h"
#include "raylab/geometry/triangle_rays.h"

namespace raylab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

std::uint32_t bits(float x) { return std::bit_cast<std::uint32_t>(x); }

float uniform(Pcg32& rng, float lo, float hi) { return lo + (hi - lo) * rng.next_float(); }

// A random multiple of 2^-k strictly between -limit and limit.
float on_grid(Pcg32& rng, float limit, int k) {
  const float step = std::ldexp(1.f, -k);
  const int n = static_cast<int>(limit / step) - 1;
  return static_cast<float>(static_cast<int>(rng.next_u32() % std::uint32_t(2 * n + 1)) - n) * step;
}

Vec3 grid_point(Pcg32& rng, float limit, int k) {
  return {on_grid(rng, limit, k), on_grid(rng, limit, k), on_grid(rng, limit, k)};
}

// A direction whose watertight shear is exact: the dominant component is +-2^j, so 1/d[kz] and
// the shears d[kx]/d[kz], d[ky]/d[kz] are exact, and the others are multiples of 1/16 (zero one
// time in eight: axis-aligned), so the sheared coordinates of points on a grid of 2^-8 or
// coarser need few bits and are exact too. A ray from `target - d` along `d` then puts `target`
// exactly at the origin of the sheared plane.
Vec3 exact_direction(Pcg32& rng, int j) {
  const float big = std::ldexp(1.f, j);
  const int kz = static_cast<int>(rng.next_u32() % 3);
  const bool axis_aligned = rng.next_u32() % 8 == 0;
  Vec3 d;
  for (int a = 0; a < 3; ++a) {
    if (a == kz) {
      d[a] = rng.next_u32() % 2 ? big : -big;
    } else {
      d[a] = axis_aligned ? 0.f : on_grid(rng, big, 4);
    }
  }
  return d;
}

// The ray from `target - d` along `d` (target at t = 1).
Ray ray_through(Vec3 target, Vec3 d) { return {target - d, 0.f, d, kInf}; }

// The sheared x and y of `p`, computed as intersect_triangle computes them.
std::array<float, 2> sheared(const WatertightRay& wr, Vec3 p) {
  const Vec3 r = p - wr.origin;
  return {r[wr.kx] - wr.sx * r[wr.kz], r[wr.ky] - wr.sy * r[wr.kz]};
}

// The exact edge function of the edge p -> q for `wr` (zero when the ray meets the edge's line).
double edge_function(const WatertightRay& wr, Vec3 p, Vec3 q) {
  const auto [px, py] = sheared(wr, p);
  const auto [qx, qy] = sheared(wr, q);
  return double(px) * double(qy) - double(py) * double(qx);
}

// The number of triangles of `tris` that `ray` hits, with tmin = 0 and tmax = infinity.
int count_hits(const std::vector<Triangle>& tris, const Ray& ray) {
  const WatertightRay wr(ray);
  int n = 0;
  for (const Triangle& tri : tris) {
    float t, u, v;
    n += intersect_triangle(tri, wr, 0.f, kInf, t, u, v);
  }
  return n;
}

// Cosine between the normal of `tri` and `d`: its sign is the side the ray sees the triangle
// from, near zero when it sees it edge-on.
float facing(const Triangle& tri, Vec3 d) { return dot(normalize(triangle_normal(tri)), normalize(d)); }

// ---------------------------------------------------------------------------------------------
// The kernels

struct KernelTally {
  long compared = 0, hits = 0;
};

// `tris` against `rays` (tmin 0, tmax infinity) in the ray-parallel kernel at width N: the rays
// grouped by their axis permutation, N at a time (a short group padded with its first ray),
// each lane compared bit for bit with intersect_triangle.
template <int N>
void compare_ray_parallel(const std::vector<Triangle>& tris, const std::vector<Ray>& rays, KernelTally& tally) {
  using F = simd::WideFloat<N>;
  std::map<std::array<int, 3>, std::vector<WatertightRay>> groups;
  for (const Ray& r : rays) {
    const WatertightRay wr(r);
    groups[{wr.kx, wr.ky, wr.kz}].push_back(wr);
  }
  alignas(64) float tmin[N], tmax[N], t[N], u[N], v[N];
  for (int i = 0; i < N; ++i) tmin[i] = 0.f, tmax[i] = kInf;
  for (const auto& [axes, group] : groups) {
    for (std::size_t first = 0; first < group.size(); first += N) {
      WatertightRay lane_rays[N];
      for (int i = 0; i < N; ++i) lane_rays[i] = first + i < group.size() ? group[first + i] : group[first];
      const WatertightRays<N> lanes = watertight_rays<N>(lane_rays);
      for (std::size_t k = 0; k < tris.size(); ++k) {
        TriangleBlock4 block = empty_triangle_block();
        const int lane = static_cast<int>(k % 4);
        block.set(lane, tris[k], static_cast<std::uint32_t>(k));
        const unsigned mask = intersect_triangle_rays<N>(block, lane, lanes, F::load(tmin), F::load(tmax), t, u, v);
        for (int i = 0; i < N; ++i) {
          float rt = 0.f, ru = 0.f, rv = 0.f;
          const bool ref = intersect_triangle(tris[k], lane_rays[i], 0.f, kInf, rt, ru, rv);
          ++tally.compared;
          ASSERT_EQ(((mask >> i) & 1u) != 0, ref) << "width " << N << ", ray lane " << i << ", triangle " << k;
          if (!ref) continue;
          ++tally.hits;
          ASSERT_TRUE(bits(t[i]) == bits(rt) && bits(u[i]) == bits(ru) && bits(v[i]) == bits(rv))
              << "width " << N << ", ray lane " << i << ", triangle " << k;
        }
      }
    }
  }
}

// `tris` against `rays` in the block kernel (the triangles four at a time, in two lane orders,
// the last block's free lanes unused) and in the ray-parallel kernel at both its widths, 8 and
// 16 (each of them SIMD or scalar as the build allows), each answer compared bit for bit with
// intersect_triangle's.
void expect_kernels_agree(const std::vector<Triangle>& tris, const std::vector<Ray>& rays) {
  KernelTally block_tally, rays_tally;
  for (const Ray& ray : rays) {
    const WatertightRay wr(ray);
    for (std::size_t first = 0; first < tris.size(); first += 4) {
      const std::size_t n = std::min<std::size_t>(4, tris.size() - first);
      for (const bool reversed : {false, true}) {
        TriangleBlock4 block = empty_triangle_block();
        for (std::size_t k = 0; k < n; ++k) {
          block.set(reversed ? 3 - int(k) : int(k), tris[first + k], static_cast<std::uint32_t>(first + k));
        }
        alignas(16) float t[4], u[4], v[4];
        const int mask = intersect_triangle_block(block, wr, 0.f, kInf, t, u, v);
        for (int lane = 0; lane < 4; ++lane) {
          const bool lane_hit = (mask >> lane) & 1;
          if (block.id[lane] == TriangleBlock4::kNoPrimitive) {
            ASSERT_FALSE(lane_hit) << "unused lane " << lane << " hit";
            continue;
          }
          float rt = 0.f, ru = 0.f, rv = 0.f;
          const bool ref = intersect_triangle(tris[block.id[lane]], wr, 0.f, kInf, rt, ru, rv);
          ++block_tally.compared;
          ASSERT_EQ(lane_hit, ref) << "block lane " << lane << ", triangle " << block.id[lane];
          if (!ref) continue;
          ++block_tally.hits;
          ASSERT_TRUE(bits(t[lane]) == bits(rt) && bits(u[lane]) == bits(ru) && bits(v[lane]) == bits(rv))
              << "block lane " << lane << ", triangle " << block.id[lane];
        }
      }
    }
  }
  compare_ray_parallel<8>(tris, rays, rays_tally);
  compare_ray_parallel<16>(tris, rays, rays_tally);
  EXPECT_GT(block_tally.hits, 0);
  EXPECT_GT(rays_tally.hits, 0);
}

// ---------------------------------------------------------------------------------------------
// The rule itself

// Non-zero edge functions keep their value; a zero one takes the sign of py - qy, else of
// qx - px; one that is zero only because it rounded to zero in float gets its exact sign.
TEST(TriangleTieRule, EdgeWithTieBroken) {
  EXPECT_EQ(edge_with_tie_broken(0.25f, 1.f, 2.f, 3.f, 4.f), 0.25f);
  EXPECT_EQ(edge_with_tie_broken(-3.f, 1.f, 2.f, 3.f, 4.f), -3.f);
  // p = (1, 2), q = (2, 4): collinear with the ray; py - qy = -2.
  EXPECT_LT(edge_with_tie_broken(0.f, 1.f, 2.f, 2.f, 4.f), 0.f);
  EXPECT_GT(edge_with_tie_broken(0.f, 2.f, 4.f, 1.f, 2.f), 0.f);
  EXPECT_LT(edge_with_tie_broken(-0.f, 1.f, 2.f, 2.f, 4.f), 0.f);
  // p = (1, 0), q = (3, 0): py == qy, so the sign of qx - px.
  EXPECT_GT(edge_with_tie_broken(0.f, 1.f, 0.f, 3.f, 0.f), 0.f);
  EXPECT_LT(edge_with_tie_broken(0.f, 3.f, 0.f, 1.f, 0.f), 0.f);
  // p == q: an edge of no length, the triangle has det == 0 anyway.
  EXPECT_EQ(edge_with_tie_broken(0.f, 1.f, 2.f, 1.f, 2.f), 0.f);
  // Exactly 1e-60 and -1e-60, which float rounds to zero: the exact sign, not the tie rule (which
  // would give the sign of qx - px = -1e-30 here, the opposite).
  const float e = static_cast<float>(double(1e-30f) * double(1e-30f));
  ASSERT_EQ(e, 0.f);
  EXPECT_GT(edge_with_tie_broken(e, 1e-30f, 0.f, 0.f, 1e-30f), 0.f);
  EXPECT_LT(edge_with_tie_broken(-e, 0.f, 1e-30f, 1e-30f, 0.f), 0.f);
}

// On small integer coordinates (many exact zeros): the edge q -> p always gets the opposite sign
// of p -> q, never zero unless p == q, and the sign of a tie is the sign of the edge function
// with the ray really moved by (eps, eps^2) (eps = 2^-10, so the perturbed value is exact in
// double and its first-order term dominates).
TEST(TriangleTieRule, TiesAreAntisymmetricAndMatchTheMovedRay) {
  Pcg32 rng(1, 1);
  int ties = 0;
  for (int i = 0; i < 20000; ++i) {
    auto coord = [&] { return static_cast<float>(static_cast<int>(rng.next_u32() % 9) - 4); };
    const float px = coord(), py = coord(), qx = coord(), qy = coord();
    const float pq = static_cast<float>(double(px) * double(qy) - double(py) * double(qx));
    const float qp = static_cast<float>(double(qx) * double(py) - double(qy) * double(px));
    const float a = edge_with_tie_broken(pq, px, py, qx, qy);
    const float b = edge_with_tie_broken(qp, qx, qy, px, py);
    if (px == qx && py == qy) {
      EXPECT_EQ(a, 0.f);
      EXPECT_EQ(b, 0.f);
      continue;
    }
    ASSERT_NE(a, 0.f);
    ASSERT_EQ(a<0.f, b> 0.f) << px << " " << py << " " << qx << " " << qy;
    if (pq != 0.f) continue;
    ++ties;
    const double eps = 0x1p-10, eps2 = eps * eps;
    const double moved = (double(px) - eps) * (double(qy) - eps2) - (double(py) - eps2) * (double(qx) - eps);
    ASSERT_NE(moved, 0.0);
    EXPECT_EQ(a < 0.f, moved < 0.0) << px << " " << py << " " << qx << " " << qy;
  }
  EXPECT_GT(ties, 1000);
}

// ---------------------------------------------------------------------------------------------
// Two triangles sharing an edge

// Quads p, q, r, s on a grid, split along p-q into (p, q, r) and (q, p, s) (consistent
// windings), in random orientations, some of them flat in a coordinate plane and shot along that
// plane's axis. Rays exactly through points p + (q - p) * k / 8 of the shared edge from random
// directions: the edge function of p-q is exactly zero (checked), and the ray hits exactly one
// of the two triangles when it sees both from the same side, none or both at a fold it sees
// from different sides. Rays from random float origins to random points of the edge, not exact,
// must do the same.
TEST(TriangleTieRule, RayThroughASharedEdgeHitsOneOfTheTwoTriangles) {
  Pcg32 rng(2, 2);
  int once = 0, folds = 0, exact = 0;
  for (int iter = 0; iter < 1500 && !HasFailure(); ++iter) {
    Vec3 p = grid_point(rng, 4.f, 5), q = grid_point(rng, 4.f, 5), r = grid_point(rng, 4.f, 5);
    Vec3 s = p + q - r + grid_point(rng, 0.5f, 5);  // across the line p-q from r
    const int flat_axis = iter % 4 == 3 ? static_cast<int>(rng.next_u32() % 3) : -1;
    if (flat_axis >= 0) {
      const float level = on_grid(rng, 2.f, 5);
      p[flat_axis] = q[flat_axis] = r[flat_axis] = s[flat_axis] = level;
    }
    const std::vector<Triangle> tris = {{p, q, r}, {q, p, s}};
    if (length(triangle_normal(tris[0])) < 0.5f || length(triangle_normal(tris[1])) < 0.5f) continue;
    std::vector<Ray> rays;
    for (int k = 1; k < 8; ++k) {
      const Vec3 target = p + (q - p) * (static_cast<float>(k) / 8.f);
      Vec3 d = exact_direction(rng, 3 + static_cast<int>(rng.next_u32() % 2));
      if (flat_axis >= 0) {
        d = Vec3(0.f);
        d[flat_axis] = k % 2 ? 8.f : -16.f;
      }
      const Ray ray = ray_through(target, d);
      ASSERT_EQ(edge_function(WatertightRay(ray), p, q), 0.0) << "the construction is not exact";
      ++exact;
      rays.push_back(ray);
    }
    for (int k = 0; k < 4; ++k) {
      const Vec3 target = lerp(p, q, uniform(rng, 0.05f, 0.95f));
      const Vec3 o = Vec3{uniform(rng, -9.f, 9.f), uniform(rng, -9.f, 9.f), uniform(rng, -9.f, 9.f)};
      rays.push_back({o, 0.f, (target - o) * uniform(rng, 0.5f, 2.f), kInf});
    }
    for (const Ray& ray : rays) {
      const float f0 = facing(tris[0], ray.direction), f1 = facing(tris[1], ray.direction);
      if (std::abs(f0) < 0.02f || std::abs(f1) < 0.02f) continue;  // (nearly) edge-on
      const int hits = count_hits(tris, ray);
      if ((f0 > 0.f) == (f1 > 0.f)) {
        ++once;
        ASSERT_EQ(hits, 1) << "iteration " << iter << ": a ray through the shared edge of two triangles seen from "
                           << "one side";
      } else {
        ++folds;
        ASSERT_NE(hits, 1) << "iteration " << iter << ": a ray grazing a fold";
      }
    }
    expect_kernels_agree(tris, rays);
  }
  EXPECT_GT(exact, 5000);
  EXPECT_GT(once, 4000);
  EXPECT_GT(folds, 200);
}

// ---------------------------------------------------------------------------------------------
// A fan around a vertex

// Six triangles around a centre, nearly flat (the rim alternates a little above and below the
// plane), in random orientations, some of them with flipped windings (the rule is geometric: the
// moved ray lies in exactly one triangle whatever the windings). Rays exactly through the centre
// (all six spokes have edge functions exactly zero, checked) and through points of the spokes,
// from every direction that sees the whole fan from one side, hit exactly one triangle.
TEST(TriangleTieRule, RayThroughTheCentreOfAFanHitsOneTriangle) {
  Pcg32 rng(3, 3);
  const float hexagon[6][2] = {{2.f, 0.f}, {1.f, 2.f}, {-1.f, 2.f}, {-2.f, 0.f}, {-1.f, -2.f}, {1.f, -2.f}};
  int tested = 0, through_centre = 0;
  for (int iter = 0; iter < 600 && !HasFailure(); ++iter) {
    const Vec3 centre = grid_point(rng, 2.f, 3);
    const Vec3 u = grid_point(rng, 1.f, 3), v = grid_point(rng, 1.f, 3), w = grid_point(rng, 1.f, 3);
    const Vec3 n = cross(u, v);
    if (length(n) < 0.3f) continue;
    std::vector<Vec3> rim;
    for (int k = 0; k < 6; ++k) {
      rim.push_back(centre + u * hexagon[k][0] + v * hexagon[k][1] + w * (k % 2 ? 0.125f : -0.125f));
    }
    std::vector<Triangle> fan;
    for (int k = 0; k < 6; ++k) {
      const bool flip = iter % 2 == 1 && rng.next_u32() % 2 == 0;
      fan.push_back(flip ? Triangle{centre, rim[(k + 1) % 6], rim[k]} : Triangle{centre, rim[k], rim[(k + 1) % 6]});
    }
    std::vector<Ray> rays;
    for (int i = 0; i < 12; ++i) {
      const int spoke = static_cast<int>(rng.next_u32() % 6);
      const bool centre_target = i < 6;
      const Vec3 target = centre_target ? centre : centre + (rim[spoke] - centre) * (float(1 + i % 3) / 4.f);
      // The first along the z axis (the fan's plane is random, so this is just another exact
      // direction), the others random.
      const Vec3 d = i == 0 ? Vec3{0.f, 0.f, 16.f} : exact_direction(rng, 4);
      const Ray ray = ray_through(target, d);
      const WatertightRay wr(ray);
      if (centre_target) {
        for (int k = 0; k < 6; ++k)
          ASSERT_EQ(edge_function(wr, centre, rim[k]), 0.0) << "the construction is not exact";
      } else {
        ASSERT_EQ(edge_function(wr, centre, rim[spoke]), 0.0) << "the construction is not exact";
      }
      rays.push_back(ray);
    }
    // And from random float origins, not exact.
    for (int i = 0; i < 4; ++i) {
      const Vec3 o = centre + Vec3{uniform(rng, -9.f, 9.f), uniform(rng, -9.f, 9.f), uniform(rng, -9.f, 9.f)};
      rays.push_back({o, 0.f, centre - o, kInf});
    }
    for (std::size_t r = 0; r < rays.size(); ++r) {
      const Ray& ray = rays[r];
      int front = 0, back = 0;
      for (int k = 0; k < 6; ++k) {
        // The side of the consistently wound triangle k.
        const float f = facing({centre, rim[k], rim[(k + 1) % 6]}, ray.direction);
        front += f > 0.05f;
        back += f < -0.05f;
      }
      // Some triangle seen edge-on or from the other side: the fan may fold over the centre.
      if (front != 6 && back != 6) continue;
      ++tested;
      through_centre += r < 6;  // the exact rays through the centre
      ASSERT_EQ(count_hits(fan, ray), 1) << "iteration " << iter << ": o=(" << ray.origin.x << ", " << ray.origin.y
                                         << ", " << ray.origin.z << ") d=(" << ray.direction.x << ", "
                                         << ray.direction.y << ", " << ray.direction.z << ")";
    }
    expect_kernels_agree(fan, rays);
  }
  EXPECT_GT(tested, 4000);
  EXPECT_GT(through_centre, 1500);
}

// ---------------------------------------------------------------------------------------------
// Closed meshes

struct Mesh {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> f;
  std::vector<Triangle> triangles() const {
    std::vector<Triangle> t;
    for (const auto& face : f) t.push_back({v[face[0]], v[face[1]], v[face[2]]});
    return t;
  }
  // The number of faces of each edge, the edge as (lower index, higher index).
  std::map<std::pair<int, int>, int> edges() const {
    std::map<std::pair<int, int>, int> count;
    for (const auto& face : f)
      for (int k = 0; k < 3; ++k) ++count[std::minmax(face[k], face[(k + 1) % 3])];
    return count;
  }
  // Whether every edge is shared by exactly two faces.
  bool closed() const {
    const auto count = edges();
    return std::all_of(count.begin(), count.end(), [](const auto& e) { return e.second == 2; });
  }
};

// The cube [-2, 2]^3, each face split in two along one diagonal or the other; `corner` moves
// vertex 7 (+2, +2, +2), which can dent it.
Mesh cube(Vec3 corner = {2.f, 2.f, 2.f}) {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.v.push_back({i & 1 ? 2.f : -2.f, i & 2 ? 2.f : -2.f, i & 4 ? 2.f : -2.f});
  m.v[7] = corner;
  const int quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  for (int k = 0; k < 6; ++k) {
    const int* q = quads[k];
    if (k % 2) {
      m.f.push_back({q[0], q[1], q[2]});
      m.f.push_back({q[0], q[2], q[3]});
    } else {
      m.f.push_back({q[1], q[2], q[3]});
      m.f.push_back({q[1], q[3], q[0]});
    }
  }
  return m;
}

Mesh octahedron() {
  Mesh m;
  m.v = {{3.f, 0.f, 0.f}, {-3.f, 0.f, 0.f}, {0.f, 3.f, 0.f}, {0.f, -3.f, 0.f}, {0.f, 0.f, 3.f}, {0.f, 0.f, -3.f}};
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) m.f.push_back({x, y, z});
  return m;
}

// The icosahedron's faces on integer vertices (0, +-2, +-3) and their cyclic permutations.
Mesh icosahedron() {
  Mesh m;
  m.v = {{-2, 3, 0},  {2, 3, 0},  {-2, -3, 0}, {2, -3, 0}, {0, -2, 3},  {0, 2, 3},
         {0, -2, -3}, {0, 2, -3}, {3, 0, -2},  {3, 0, 2},  {-3, 0, -2}, {-3, 0, 2}};
  m.f = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
         {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
         {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return m;
}

// `m` with each face split in four and the vertices pushed onto the sphere of radius 3: float
// coordinates off any grid.
Mesh subdivided_on_sphere(const Mesh& m) {
  Mesh s;
  s.v = m.v;
  std::map<std::pair<int, int>, int> mid;
  auto midpoint = [&](int a, int b) {
    const auto [it, fresh] = mid.try_emplace(std::minmax(a, b), static_cast<int>(s.v.size()));
    if (fresh) s.v.push_back((s.v[a] + s.v[b]) * 0.5f);
    return it->second;
  };
  for (const auto& f : m.f) {
    const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
    s.f.insert(s.f.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
  }
  for (Vec3& x : s.v) x = normalize(x) * 3.f;
  return s;
}

// Rays through every vertex and every edge midpoint of `m` from many directions: exact ones
// (edge functions exactly zero at the target, checked) and float ones from random origins. From
// outside the bounding box each ray must hit an even number of triangles (a closed surface is
// entered as often as it is left; a ray through a shared edge or vertex counted twice or not at
// all would be odd). When `inside` is given, rays from origins it accepts (inside a convex mesh)
// must hit exactly one triangle. `exact_grid` says whether the vertices are on the grid that
// makes the exact rays exact.
void expect_crossings_counted_once(const Mesh& m, bool exact_grid, const std::function<bool(Vec3)>& inside,
                                   std::uint64_t seed) {
  ASSERT_TRUE(m.closed());
  const std::vector<Triangle> tris = m.triangles();
  Vec3 lo(kInf), hi(-kInf);
  for (Vec3 p : m.v) lo = min(lo, p), hi = max(hi, p);
  auto outside_box = [&](Vec3 o) {
    return o.x < lo.x - 0.1f || o.y < lo.y - 0.1f || o.z < lo.z - 0.1f || o.x > hi.x + 0.1f || o.y > hi.y + 0.1f ||
           o.z > hi.z + 0.1f;
  };
  // Targets: each vertex (first of the pair, second -1) and each edge's midpoint.
  std::vector<std::pair<int, int>> targets;
  for (int i = 0; i < static_cast<int>(m.v.size()); ++i) targets.push_back({i, -1});
  for (const auto& [edge, faces] : m.edges()) targets.push_back(edge);
  Pcg32 rng(seed, 7);
  std::vector<Ray> all;
  int outside = 0, crossing = 0, from_inside = 0, exact = 0;
  for (const auto& [a, b] : targets) {
    const Vec3 target = b < 0 ? m.v[a] : (m.v[a] + m.v[b]) * 0.5f;
    for (int i = 0; i < 24; ++i) {
      Ray ray;
      const int kind = i % 3;
      bool exact_ray = false;
      if (kind == 0 && exact_grid) {  // exact, from outside
        ray = ray_through(target, exact_direction(rng, 4));
        exact_ray = true;
      } else if (kind == 1 && exact_grid && inside) {  // exact, from inside
        for (int attempt = 0; attempt < 200 && !exact_ray; ++attempt) {
          ray = ray_through(target, exact_direction(rng, static_cast<int>(rng.next_u32() % 2)));
          exact_ray = inside(ray.origin);
        }
        if (!exact_ray) continue;
      } else if (kind == 1 && inside) {  // float, from inside
        const Vec3 o = Vec3{uniform(rng, -1.f, 1.f), uniform(rng, -1.f, 1.f), uniform(rng, -1.f, 1.f)};
        ray = {o, 0.f, target - o, kInf};
      } else {  // float, from outside
        const Vec3 o = normalize(Vec3{uniform(rng, -1.f, 1.f), uniform(rng, -1.f, 1.f), uniform(rng, -1.f, 1.f)}) *
                       uniform(rng, 6.f, 20.f);
        ray = {o, 0.f, (target - o) * uniform(rng, 0.25f, 4.f), kInf};
      }
      if (exact_ray) {
        const WatertightRay wr(ray);
        const auto [x, y] = sheared(wr, target);
        ASSERT_TRUE(x == 0.f && y == 0.f) << "the construction is not exact";
        if (b >= 0) {
          ASSERT_EQ(edge_function(wr, m.v[a], m.v[b]), 0.0) << "the construction is not exact";
        }
        ++exact;
      }
      const int hits = count_hits(tris, ray);
      if (outside_box(ray.origin)) {
        ++outside;
        crossing += hits > 0;
        ASSERT_EQ(hits % 2, 0) << "target " << a << ", " << b << ": o=(" << ray.origin.x << ", " << ray.origin.y << ", "
                               << ray.origin.z << ") d=(" << ray.direction.x << ", " << ray.direction.y << ", "
                               << ray.direction.z << ") hits " << hits << " triangles";
      } else if (inside && inside(ray.origin)) {
        ++from_inside;
        ASSERT_EQ(hits, 1) << "target " << a << ", " << b << ": o=(" << ray.origin.x << ", " << ray.origin.y << ", "
                           << ray.origin.z << ") d=(" << ray.direction.x << ", " << ray.direction.y << ", "
                           << ray.direction.z << ") from inside";
      }
      all.push_back(ray);
    }
  }
  EXPECT_GT(crossing, outside / 2) << "of " << outside << " rays from outside";
  if (exact_grid) {
    EXPECT_GT(exact, int(targets.size()) * 6);
  }
  if (inside) {
    EXPECT_GT(from_inside, int(targets.size()) * 5);
  }
  expect_kernels_agree(tris, all);
}

TEST(TriangleTieRule, CubeCountsEachCrossingOnce) {
  expect_crossings_counted_once(
      cube(), true,
      [](Vec3 o) {
        return std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)}) < 1.9f;
      },
      11);
}

TEST(TriangleTieRule, DentedCubeCountsEachCrossingOnce) {
  expect_crossings_counted_once(cube({1.f, 1.f, 1.f}), true, nullptr, 12);
}

TEST(TriangleTieRule, OctahedronCountsEachCrossingOnce) {
  expect_crossings_counted_once(
      octahedron(), true, [](Vec3 o) { return std::abs(o.x) + std::abs(o.y) + std::abs(o.z) < 2.9f; }, 13);
}

TEST(TriangleTieRule, IcosahedronCountsEachCrossingOnce) {
  expect_crossings_counted_once(icosahedron(), true, nullptr, 14);
}

TEST(TriangleTieRule, IcosphereCountsEachCrossingOnce) {
  expect_crossings_counted_once(subdivided_on_sphere(icosahedron()), false, nullptr, 15);
}

}  // namespace
}  // namespace raylab
