// Ray-primitive tests against analytic answers, the watertightness of the triangle test on closed
// meshes, and the surface data computed afterwards (shading.h).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/geometry/geometry.h"
#include "raylab/geometry/shading.h"

namespace raylab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

Vec3 random_unit(Pcg32& rng) {
  for (;;) {
    const Vec3 p{2.f * rng.next_float() - 1.f, 2.f * rng.next_float() - 1.f, 2.f * rng.next_float() - 1.f};
    const float l2 = dot(p, p);
    if (l2 > 1e-4f && l2 <= 1.f) return p / std::sqrt(l2);
  }
}

// ---------------------------------------------------------------------------------------------
// Spheres

TEST(Sphere, HitFromOutsideAtDistanceMinusRadius) {
  const Sphere s{{0.f, 0.f, 10.f}, 2.f};
  float t = 0.f;
  ASSERT_TRUE(intersect_sphere(s, Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}}, 0.f, kInf, t));
  EXPECT_FLOAT_EQ(t, 8.f);
  // t is measured in units of the (non-unit) direction.
  ASSERT_TRUE(intersect_sphere(s, Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 2.f}}, 0.f, kInf, t));
  EXPECT_FLOAT_EQ(t, 4.f);
  // [tmin, tmax) clips: below the near root the far root is returned; beyond both, nothing.
  const Ray r{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  EXPECT_FALSE(intersect_sphere(s, r, 0.f, 8.f, t));  // tmax is exclusive
  ASSERT_TRUE(intersect_sphere(s, r, 9.f, kInf, t));
  EXPECT_FLOAT_EQ(t, 12.f);
  EXPECT_FALSE(intersect_sphere(s, r, 12.5f, kInf, t));
}

TEST(Sphere, RayStartingInsideHitsFarSide) {
  const Sphere s{{1.f, 2.f, 3.f}, 2.f};
  float t = 0.f;
  ASSERT_TRUE(intersect_sphere(s, Ray{{1.f, 2.f, 3.f}, 0.f, {1.f, 0.f, 0.f}}, 0.f, kInf, t));
  EXPECT_FLOAT_EQ(t, 2.f);
  ASSERT_TRUE(intersect_sphere(s, Ray{{1.5f, 2.f, 3.f}, 0.f, {-1.f, 0.f, 0.f}}, 0.f, kInf, t));
  EXPECT_FLOAT_EQ(t, 2.5f);
}

TEST(Sphere, GrazingTangentAndMiss) {
  const Sphere s{{0.f, 0.f, 10.f}, 2.f};
  float t = 0.f;
  // Exactly tangent: touches at (2, 0, 10).
  ASSERT_TRUE(intersect_sphere(s, Ray{{2.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}}, 0.f, kInf, t));
  EXPECT_NEAR(t, 10.f, 1e-5f);
  // Just inside the silhouette: a shallow chord around z = 10.
  ASSERT_TRUE(intersect_sphere(s, Ray{{1.999f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}}, 0.f, kInf, t));
  EXPECT_NEAR(t, 10.0 - std::sqrt(4.0 - 1.999 * 1.999), 1e-4);
  EXPECT_FALSE(intersect_sphere(s, Ray{{2.001f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}}, 0.f, kInf, t));
  // Behind the ray, and off to the side.
  EXPECT_FALSE(intersect_sphere(s, Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, -1.f}}, 0.f, kInf, t));
  EXPECT_FALSE(intersect_sphere(s, Ray{{0.f, 0.f, 0.f}, 0.f, {1.f, 0.f, 0.f}}, 0.f, kInf, t));
}

TEST(Sphere, FarAwaySphereKeepsRelativeAccuracy) {
  // A naive discriminant b^2 - c at |centre| = 1e4 loses everything to cancellation (ulp of 1e8
  // is 8, the answer is of order 1); the geometric form must keep t to 1e-5 relative.
  const Sphere s{{1e4f, 0.f, 0.f}, 1.f};
  float t = 0.f;
  ASSERT_TRUE(intersect_sphere(s, Ray{{0.f, 0.f, 0.f}, 0.f, {1.f, 0.f, 0.f}}, 0.f, kInf, t));
  EXPECT_NEAR(t, 9999.0, 9999.0 * 1e-5);
  Pcg32 rng(5, 5);
  for (int i = 0; i < 1000; ++i) {
    // A visible point on the sphere (normal within ~70 degrees of the viewer), seen from the origin.
    Vec3 n = random_unit(rng);
    if (n.x > -0.35f) continue;
    const double px = 1e4 + double(n.x), py = n.y, pz = n.z;
    const Vec3 d = normalize(Vec3{float(px), float(py), float(pz)});
    ASSERT_TRUE(intersect_sphere(s, Ray{{0.f, 0.f, 0.f}, 0.f, d}, 0.f, kInf, t));
    const double expected = std::sqrt(px * px + py * py + pz * pz);
    EXPECT_NEAR(t, expected, expected * 1e-5);
  }
}

TEST(Sphere, LongDirectionAgainstHugeSphereDoesNotOverflow) {
  // |d|^2 = 1e18 times (radius^2 - distance^2) = 9e20 overflows float; the hit is still at
  // (6e10 - 3e10) / 1e9 = 30 and the far side at 90, never a false hit at t = 0.
  const Sphere s{{0.f, 0.f, 0.f}, 3e10f};
  const Ray r{{-6e10f, 0.f, 0.f}, 0.f, {1e9f, 0.f, 0.f}};
  float t = -1.f;
  ASSERT_TRUE(intersect_sphere(s, r, 0.f, kInf, t));
  EXPECT_NEAR(t, 30.f, 30.f * 1e-5f);
  ASSERT_TRUE(intersect_sphere(s, r, 31.f, kInf, t));
  EXPECT_NEAR(t, 90.f, 90.f * 1e-5f);
  // Beside the sphere by more than its radius: no hit, however large the numbers.
  EXPECT_FALSE(intersect_sphere(s, Ray{{-6e10f, 3.1e10f, 0.f}, 0.f, {1e9f, 0.f, 0.f}}, 0.f, kInf, t));
}

// ---------------------------------------------------------------------------------------------
// Triangles

bool hit_triangle(const Triangle& tri, const Ray& ray, float& t, float& u, float& v, float tmin = 0.f,
                  float tmax = kInf) {
  return intersect_triangle(tri, WatertightRay(ray), tmin, tmax, t, u, v);
}

TEST(Triangle, BarycentricsOfKnownPoint) {
  const Triangle tri{{0.f, 0.f, 0.f}, {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}};
  float t, u, v;
  ASSERT_TRUE(hit_triangle(tri, Ray{{0.25f, 0.5f, 1.f}, 0.f, {0.f, 0.f, -1.f}}, t, u, v));
  EXPECT_FLOAT_EQ(t, 1.f);
  EXPECT_FLOAT_EQ(u, 0.25f);  // weight of p1
  EXPECT_FLOAT_EQ(v, 0.5f);   // weight of p2
  // From behind (no culling), obliquely, with a non-unit direction.
  ASSERT_TRUE(hit_triangle(tri, Ray{{-0.75f, 0.5f, -2.f}, 0.f, {0.5f, 0.f, 1.f}}, t, u, v));
  EXPECT_FLOAT_EQ(t, 2.f);
  EXPECT_FLOAT_EQ(u, 0.25f);
  EXPECT_FLOAT_EQ(v, 0.5f);
  // tmax is exclusive, tmin inclusive.
  EXPECT_FALSE(hit_triangle(tri, Ray{{0.25f, 0.5f, 1.f}, 0.f, {0.f, 0.f, -1.f}}, t, u, v, 0.f, 1.f));
  EXPECT_TRUE(hit_triangle(tri, Ray{{0.25f, 0.5f, 1.f}, 0.f, {0.f, 0.f, -1.f}}, t, u, v, 1.f, 1.5f));
}

// A point on an edge or at a vertex belongs to exactly one of the triangles around it (the tie
// rule of edge_with_tie_broken), so it is checked with the triangle's neighbours: the unit cells of
// [-1, 2]^2 split like `tri` (the lower left half of cell (0, 0)) cover every point of `tri`
// with a whole fan. A ray straight down through each vertex and through a point of each edge
// hits exactly one of the 18 triangles, at t = 1, and the barycentrics of that triangle give the
// point back. A lone triangle still owns some of its boundary, depending on the ray's direction:
// for these rays, its edge p0-p1 (v = 0) and its vertex p0, but not its hypotenuse.
TEST(Triangle, EdgeAndVertexHitsAndNearMisses) {
  const Triangle tri{{0.f, 0.f, 0.f}, {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}};
  const Vec3 down{0.f, 0.f, -1.f};
  std::vector<Triangle> cells;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      const Vec3 o{float(i), float(j), 0.f};
      cells.push_back({o, o + Vec3{1.f, 0.f, 0.f}, o + Vec3{0.f, 1.f, 0.f}});
      cells.push_back({o + Vec3{1.f, 0.f, 0.f}, o + Vec3{1.f, 1.f, 0.f}, o + Vec3{0.f, 1.f, 0.f}});
    }
  for (const Vec3 point :
       {tri.p0, tri.p1, tri.p2, Vec3{0.5f, 0.f, 0.f}, Vec3{0.5f, 0.5f, 0.f}, Vec3{0.f, 0.25f, 0.f}}) {
    const Ray ray{point + Vec3{0.f, 0.f, 1.f}, 0.f, down};
    int hits = 0;
    for (const Triangle& cell : cells) {
      float t, u, v;
      if (!hit_triangle(cell, ray, t, u, v)) continue;
      ++hits;
      EXPECT_EQ(t, 1.f);
      const Vec3 back = cell.p0 * (1.f - u - v) + cell.p1 * u + cell.p2 * v;
      EXPECT_EQ(back, point) << "(" << back.x << ", " << back.y << ") for (" << point.x << ", " << point.y << ")";
    }
    EXPECT_EQ(hits, 1) << "(" << point.x << ", " << point.y << ")";
  }
  float t, u, v;
  ASSERT_TRUE(hit_triangle(tri, Ray{{0.5f, 0.f, 1.f}, 0.f, down}, t, u, v));  // edge p0-p1
  EXPECT_FLOAT_EQ(v, 0.f);
  ASSERT_TRUE(hit_triangle(tri, Ray{{0.f, 0.f, 1.f}, 0.f, down}, t, u, v));  // vertex p0
  EXPECT_FLOAT_EQ(u, 0.f);
  EXPECT_FLOAT_EQ(v, 0.f);
  EXPECT_FALSE(hit_triangle(tri, Ray{{0.5f, 0.5f, 1.f}, 0.f, down}, t, u, v));  // hypotenuse: the neighbour's
  EXPECT_FALSE(hit_triangle(tri, Ray{{-1e-3f, 0.5f, 1.f}, 0.f, down}, t, u, v));
  EXPECT_FALSE(hit_triangle(tri, Ray{{0.501f, 0.5f, 1.f}, 0.f, down}, t, u, v));
  // Parallel to the plane, and a degenerate (collinear) triangle.
  EXPECT_FALSE(hit_triangle(tri, Ray{{-1.f, 0.2f, 0.f}, 0.f, {1.f, 0.f, 0.f}}, t, u, v));
  const Triangle flat{{0.f, 0.f, 0.f}, {1.f, 1.f, 0.f}, {2.f, 2.f, 0.f}};
  EXPECT_FALSE(hit_triangle(flat, Ray{{1.f, 1.f, 1.f}, 0.f, down}, t, u, v));
}

// Indexed triangle meshes for the watertightness test.
struct Mesh {
  std::vector<Vec3> v;
  std::vector<std::array<std::uint32_t, 3>> f;
  Triangle tri(std::size_t i) const { return {v[f[i][0]], v[f[i][1]], v[f[i][2]]}; }
};

// Winds every face so its normal points away from `inside` (the meshes below are star-shaped).
void orient_outward(Mesh& m, Vec3 inside) {
  for (std::size_t i = 0; i < m.f.size(); ++i) {
    const Triangle t = m.tri(i);
    if (dot(triangle_normal(t), (t.p0 + t.p1 + t.p2) / 3.f - inside) < 0.f) std::swap(m.f[i][1], m.f[i][2]);
  }
}

Mesh octahedron() {
  Mesh m;
  m.v = {{1.f, 0.f, 0.f}, {-1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, -1.f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 0.f, -1.f}};
  for (std::uint32_t x : {0u, 1u})
    for (std::uint32_t y : {2u, 3u})
      for (std::uint32_t z : {4u, 5u}) m.f.push_back({x, y, z});
  orient_outward(m, {});
  return m;
}

// Icosahedron subdivided `levels` times, vertices pushed onto a sphere of radius `r` at `c`:
// many long shared edges in general directions and vertices shared by 5 or 6 faces.
Mesh icosphere(int levels, Vec3 c, float r) {
  const float p = (1.f + std::sqrt(5.f)) / 2.f;
  Mesh m;
  m.v = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
         {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
  m.f = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
         {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
         {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& x : m.v) x = normalize(x);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto [it, fresh] = mid.try_emplace(key, static_cast<std::uint32_t>(m.v.size()));
      if (fresh) m.v.push_back(normalize(m.v[a] + m.v[b]));
      return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> faces;
    for (const auto& f : m.f) {
      const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      faces.insert(faces.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    m.f = std::move(faces);
  }
  for (auto& x : m.v) x = c + x * r;
  orient_outward(m, c);
  return m;
}

// An open height field (n x n cells, two triangles each), rotated and moved far from the origin
// where float spacing is coarse. Only its interior edges and vertices are shared.
Mesh height_field(int n, Pcg32& rng) {
  Mesh m;
  const Vec3 offset{1000.f, -700.f, 300.f};
  const Vec3 ex = normalize(Vec3{1.f, 0.3f, 0.1f});
  const Vec3 ey = normalize(cross(Vec3{0.2f, 0.1f, 1.f}, ex));
  const Vec3 ez = cross(ex, ey);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.v.push_back(offset + ex * float(i) + ey * float(j) + ez * (0.4f * rng.next_float()));
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.f.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.f.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// Shoots rays exactly through shared edges (lerps of the two endpoints) and shared vertices of
// `m` from random origins and requires each to hit some triangle where it crosses the surface.
// Origins from which a face around the point is seen edge-on or from the other side than the
// rest (a silhouette) are skipped: there a ray may legitimately just touch the surface and miss.
// The faces considered are the whole fans of the vertices involved, because a lerp rounded to
// float near an endpoint can land in any face around that endpoint.
void expect_watertight(const Mesh& m, Vec3 lo, Vec3 hi, int rays_per_feature, std::uint64_t seed) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_count;
  std::vector<std::vector<std::uint32_t>> fan(m.v.size());
  for (std::uint32_t i = 0; i < m.f.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      ++edge_count[std::minmax(m.f[i][k], m.f[i][(k + 1) % 3])];
      fan[m.f[i][k]].push_back(i);
    }
  // A vertex is interior when each neighbour shares two of its faces (a closed fan).
  std::vector<bool> interior(m.v.size(), true);
  for (std::uint32_t vi = 0; vi < m.v.size(); ++vi) {
    std::map<std::uint32_t, int> ring;
    for (std::uint32_t fi : fan[vi])
      for (std::uint32_t w : m.f[fi]) ++ring[w];
    for (const auto& [w, count] : ring) interior[vi] = interior[vi] && (w == vi || count == 2);
  }
  Pcg32 rng(seed, 3);
  auto random_origin = [&](Vec3 target, const std::vector<std::uint32_t>& faces, Vec3& o) {
    for (int attempt = 0; attempt < 100; ++attempt) {
      o = lo + (hi - lo) * Vec3{rng.next_float(), rng.next_float(), rng.next_float()};
      int pos = 0, neg = 0;
      for (std::uint32_t fi : faces) {
        const float c = dot(normalize(triangle_normal(m.tri(fi))), normalize(o - target));
        pos += c > 1e-2f;
        neg += c < -1e-2f;
      }
      if (pos == int(faces.size()) || neg == int(faces.size())) return true;
    }
    return false;
  };
  auto crosses = [&](Vec3 o, Vec3 target) {
    const Ray ray{o, 0.f, target - o};  // the target is at t = 1
    const WatertightRay wr(ray);
    float t, u, v;
    for (std::size_t i = 0; i < m.f.size(); ++i)
      if (intersect_triangle(m.tri(i), wr, 1.f - 1e-3f, 1.f + 1e-3f, t, u, v)) return true;
    return false;
  };
  int tested = 0, leaks = 0;
  for (const auto& [edge, count] : edge_count) {
    const auto [a, b] = edge;
    if (count != 2 || !interior[a] || !interior[b]) continue;
    std::vector<std::uint32_t> faces = fan[a];
    faces.insert(faces.end(), fan[b].begin(), fan[b].end());
    for (int r = 0; r < rays_per_feature; ++r) {
      // Mostly interior points, sometimes within an ulp or so of an endpoint.
      const float s = r % 4 == 0 ? float(r % 8 == 0 ? 1e-7 : 1.0 - 6e-8) : rng.next_float();
      const Vec3 target = lerp(m.v[a], m.v[b], s);
      Vec3 o;
      if (!random_origin(target, faces, o)) continue;
      ++tested;
      leaks += !crosses(o, target);
    }
  }
  for (std::uint32_t vi = 0; vi < m.v.size(); ++vi) {
    if (!interior[vi]) continue;
    for (int r = 0; r < rays_per_feature; ++r) {
      Vec3 o;
      if (!random_origin(m.v[vi], fan[vi], o)) continue;
      ++tested;
      leaks += !crosses(o, m.v[vi]);
    }
  }
  EXPECT_GT(tested, 100);
  EXPECT_EQ(leaks, 0) << "of " << tested << " rays through shared edges and vertices";
}

TEST(TriangleWatertight, Octahedron) {
  const Mesh m = octahedron();
  ASSERT_EQ(m.f.size(), 8u);
  expect_watertight(m, Vec3(-0.3f), Vec3(0.3f), 200, 1);  // from inside: no silhouettes at all
  expect_watertight(m, Vec3(-5.f), Vec3(5.f), 200, 2);
}

TEST(TriangleWatertight, Icosphere) {
  const Mesh m = icosphere(2, {0.3f, -0.2f, 0.1f}, 3.f);
  ASSERT_EQ(m.f.size(), 320u);
  expect_watertight(m, Vec3(-1.2f), Vec3(1.2f), 12, 3);  // inside
  expect_watertight(m, Vec3(-20.f), Vec3(20.f), 12, 4);
}

TEST(TriangleWatertight, RotatedHeightFieldFarFromOrigin) {
  Pcg32 rng(11, 11);
  const Mesh m = height_field(12, rng);
  Box3 b;
  for (Vec3 p : m.v) b.extend(p);
  expect_watertight(m, b.lo - Vec3(10.f), b.hi + Vec3(10.f), 12, 5);
}

// ---------------------------------------------------------------------------------------------
// Cylinders and cones (open, no caps)

// Where the ray from `o` along `d`, for t in [0, tmax), first meets the open cylinder or cone `c`:
// its distance and its height fraction (0 at the base, 1 at the apex); nothing when it misses.
struct CylinderHit {
  float t = 0.f, height = 0.f;
};

std::optional<CylinderHit> cylinder_hit(const Cylinder& c, Vec3 o, Vec3 d, float tmax = kInf) {
  CylinderHit hit;
  if (!intersect_cylinder(c, Ray{o, 0.f, d}, 0.f, tmax, hit.t, hit.height)) return std::nullopt;
  return hit;
}

// Expects the ray from `o` along `d` to meet `c` at distance `t` and height fraction `height`.
void expect_cylinder_hit(const Cylinder& c, Vec3 o, Vec3 d, float t, float height) {
  const std::optional<CylinderHit> hit = cylinder_hit(c, o, d);
  ASSERT_TRUE(hit);
  EXPECT_FLOAT_EQ(hit->t, t);
  EXPECT_FLOAT_EQ(hit->height, height);
}

TEST(Cylinder, PerpendicularRayHitsAtDistanceMinusRadius) {
  const Cylinder c{{0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 4.f}, 1.f};
  expect_cylinder_hit(c, {5.f, 0.f, 2.f}, {-1.f, 0.f, 0.f}, 4.f, 0.5f);
  // A tilted axis and a general direction, against the closed-form distance to the axis line.
  const Cylinder tilted{{1.f, 2.f, 3.f}, 0.5f, {4.f, 6.f, 3.f}, 0.5f};  // axis along (0.6, 0.8, 0)
  const Vec3 foot{2.5f, 4.f, 3.f};                                      // on the axis, halfway
  const std::optional<CylinderHit> hit = cylinder_hit(tilted, foot + Vec3{0.f, 0.f, 10.f}, {0.f, 0.f, -1.f});
  ASSERT_TRUE(hit);
  EXPECT_FLOAT_EQ(hit->t, 9.5f);
  EXPECT_NEAR(hit->height, 0.5f, 1e-6f);
}

TEST(Cylinder, InsideHitsFarWallParallelInsideMisses) {
  const Cylinder c{{0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 4.f}, 1.f};
  const std::optional<CylinderHit> inside = cylinder_hit(c, {0.5f, 0.f, 2.f}, {-1.f, 0.f, 0.f});
  ASSERT_TRUE(inside);
  EXPECT_FLOAT_EQ(inside->t, 1.5f);
  // Along the axis, inside or outside: an open tube has nothing to hit.
  EXPECT_FALSE(cylinder_hit(c, {0.5f, 0.f, -1.f}, {0.f, 0.f, 1.f}));
  EXPECT_FALSE(cylinder_hit(c, {2.f, 0.f, -1.f}, {0.f, 0.f, 1.f}));
}

TEST(Cylinder, HitsOutsideHeightRangeAreRejected) {
  const Cylinder c{{0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 4.f}, 1.f};
  EXPECT_FALSE(cylinder_hit(c, {5.f, 0.f, 4.5f}, {-1.f, 0.f, 0.f}));
  EXPECT_FALSE(cylinder_hit(c, {5.f, 0.f, -0.5f}, {-1.f, 0.f, 0.f}));
  // Entering through the open top: the near root (z = 5) is above the apex, the far one counts.
  expect_cylinder_hit(c, {-3.f, 0.f, 7.f}, {1.f, 0.f, -1.f}, 4.f, 0.75f);
  EXPECT_FALSE(cylinder_hit(c, {5.f, 0.f, 2.f}, {-1.f, 0.f, 0.f}, 4.f));  // tmax
}

TEST(Cone, PerpendicularAndGeneratorRays) {
  // Base radius 1 at y = 0 narrowing to a point at y = 1.
  const Cylinder cone{{0.f, 0.f, 0.f}, 1.f, {0.f, 1.f, 0.f}, 0.f};
  expect_cylinder_hit(cone, {3.f, 0.5f, 0.f}, {-1.f, 0.f, 0.f}, 2.5f, 0.5f);
  // Parallel to the generator through (1,0,0)-(0,1,0): the quadratic degenerates to a line.
  expect_cylinder_hit(cone, {0.f, 0.f, 0.f}, {-1.f, 1.f, 0.f}, 0.5f, 0.5f);
  // The same direction from outside meets only the mirror nappe above the apex: rejected.
  EXPECT_FALSE(cylinder_hit(cone, {2.f, 0.f, 0.f}, {-1.f, 1.f, 0.f}));
  // Below the base / above the apex.
  EXPECT_FALSE(cylinder_hit(cone, {3.f, -0.5f, 0.f}, {-1.f, 0.f, 0.f}));
  EXPECT_FALSE(cylinder_hit(cone, {3.f, 1.5f, 0.f}, {-1.f, 0.f, 0.f}));
}

TEST(Cylinder, NormalsAndBounds) {
  const Cylinder c{{0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 4.f}, 1.f};
  const Vec3 n = cylinder_normal(c, {0.f, 1.f, 2.f});
  EXPECT_NEAR(n.x, 0.f, 1e-6f);
  EXPECT_NEAR(n.y, 1.f, 1e-6f);
  EXPECT_NEAR(n.z, 0.f, 1e-6f);
  const Vec3 nc = cylinder_normal(Cylinder{{0.f, 0.f, 0.f}, 1.f, {0.f, 1.f, 0.f}, 0.f}, {0.5f, 0.5f, 0.f});
  EXPECT_NEAR(nc.x, std::sqrt(0.5f), 1e-6f);  // the cone's normal tilts up by its 45-degree slope
  EXPECT_NEAR(nc.y, std::sqrt(0.5f), 1e-6f);
  const Box3 b = cylinder_bounds(c);
  EXPECT_EQ(b.lo, (Vec3{-1.f, -1.f, 0.f}));
  EXPECT_EQ(b.hi, (Vec3{1.f, 1.f, 4.f}));
}

// ---------------------------------------------------------------------------------------------
// Disks and quads

TEST(Planar, DiskHitsAndMisses) {
  const Disk d{{0.f, 1.f, 0.f}, {0.f, 1.f, 0.f}, 1.f};
  float t = 0.f;
  ASSERT_TRUE(intersect_disk(d, Ray{{0.5f, 3.f, 0.5f}, 0.f, {0.f, -1.f, 0.f}}, 0.f, kInf, t));
  EXPECT_FLOAT_EQ(t, 2.f);
  ASSERT_TRUE(intersect_disk(d, Ray{{0.5f, -1.f, 0.5f}, 0.f, {0.f, 1.f, 0.f}}, 0.f, kInf, t));  // back side
  EXPECT_FLOAT_EQ(t, 2.f);
  EXPECT_FALSE(intersect_disk(d, Ray{{0.8f, 3.f, 0.8f}, 0.f, {0.f, -1.f, 0.f}}, 0.f, kInf, t));  // |r| > 1
  EXPECT_FALSE(intersect_disk(d, Ray{{0.f, 1.f, -3.f}, 0.f, {0.f, 0.f, 1.f}}, 0.f, kInf, t));    // in the plane
  EXPECT_FALSE(intersect_disk(d, Ray{{0.5f, 3.f, 0.5f}, 0.f, {0.f, 1.f, 0.f}}, 0.f, kInf, t));   // behind
  EXPECT_FALSE(intersect_disk(d, Ray{{0.5f, 3.f, 0.5f}, 0.f, {0.f, -1.f, 0.f}}, 0.f, 2.f, t));   // tmax
}

TEST(Planar, QuadHitsAndMisses) {
  const Quad q{{0.f, 0.f, 0.f}, {2.f, 0.f, 0.f}, {0.f, 0.f, 1.f}};
  float t = 0.f, s = 0.f, u = 0.f;
  ASSERT_TRUE(intersect_quad(q, Ray{{1.f, 3.f, 0.25f}, 0.f, {0.f, -1.f, 0.f}}, 0.f, kInf, t, s, u));
  EXPECT_FLOAT_EQ(t, 3.f);
  EXPECT_FLOAT_EQ(s, 0.5f);
  EXPECT_FLOAT_EQ(u, 0.25f);
  ASSERT_TRUE(intersect_quad(q, Ray{{2.f, 3.f, 1.f}, 0.f, {0.f, -1.f, 0.f}}, 0.f, kInf, t, s, u));  // corner
  EXPECT_FLOAT_EQ(s, 1.f);
  EXPECT_FLOAT_EQ(u, 1.f);
  EXPECT_FALSE(intersect_quad(q, Ray{{2.5f, 3.f, 0.5f}, 0.f, {0.f, -1.f, 0.f}}, 0.f, kInf, t, s, u));
  EXPECT_FALSE(intersect_quad(q, Ray{{1.f, 3.f, -0.1f}, 0.f, {0.f, -1.f, 0.f}}, 0.f, kInf, t, s, u));
  EXPECT_FALSE(intersect_quad(q, Ray{{1.f, 0.f, -1.f}, 0.f, {0.f, 0.f, 1.f}}, 0.f, kInf, t, s, u));  // parallel
}

// ---------------------------------------------------------------------------------------------
// Surface data

// Shoots random rays at each primitive of a mixed Geometry and checks what surface_at reports:
// unit normals facing the ray, the hit point on the surface, the right object.
TEST(SurfaceAt, UnitNormalsFacingTheRayAndPointsOnTheSurface) {
  Geometry g;
  const Triangle tri{{-1.f, 0.f, 0.f}, {1.f, 0.2f, 0.f}, {0.f, 1.5f, 0.5f}};
  g.add(tri, {Vec3{0.f, 0.f, 1.f}, Vec3{0.3f, 0.f, 1.f}, Vec3{}}, 10);
  g.add(Sphere{{4.f, 0.f, 0.f}, 1.5f}, 11);
  g.add(Cylinder{{-4.f, -1.f, 0.f}, 1.f, {-4.f, 1.f, 0.5f}, 1.f}, 12);
  g.add(Cylinder{{0.f, -5.f, 0.f}, 1.f, {0.f, -3.f, 0.f}, 0.25f}, 13);
  g.add(Disk{{0.f, 4.f, 0.f}, normalize(Vec3{0.2f, 1.f, 0.1f}), 1.f}, 14);
  g.add(Quad{{3.f, 3.f, 0.f}, {1.f, 0.5f, 0.f}, {0.f, 0.2f, 1.5f}}, 15);
  auto distance_to_surface = [&](std::uint32_t id, Vec3 p) -> float {
    const ShapeRef r = g.resolve(id);
    switch (r.kind) {
      case ShapeKind::kTriangle:
        return dot(p - tri.p0, normalize(triangle_normal(tri)));
      case ShapeKind::kSphere:
        return length(p - g.spheres[0].center) - g.spheres[0].radius;
      case ShapeKind::kCylinder: {
        const Cylinder& c = g.cylinders[r.index];
        const Vec3 w = normalize(c.apex - c.base);
        const float s = dot(p - c.base, w);
        const float radius = c.base_radius + (c.apex_radius - c.base_radius) * s / length(c.apex - c.base);
        return length(p - c.base - w * s) - radius;
      }
      case ShapeKind::kDisk:
        return dot(p - g.disks[0].center, g.disks[0].normal);
      case ShapeKind::kQuad:
        return dot(p - g.quads[0].corner, normalize(cross(g.quads[0].edge_u, g.quads[0].edge_v)));
    }
    return kInf;
  };
  Pcg32 rng(99, 1);
  for (std::uint32_t id = 0; id < g.size(); ++id) {
    const Box3 b = g.bounds(id);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
      const Vec3 target = b.lo + b.extent() * Vec3{rng.next_float(), rng.next_float(), rng.next_float()};
      const Vec3 o = target + random_unit(rng) * 8.f;
      Ray ray{o, 0.f, (target - o) * 0.125f};
      Hit hit;
      if (!g.intersect(id, WatertightRay(ray), ray, hit)) continue;
      ++hits;
      const SurfaceInteraction si = surface_at(g, ray, hit);
      EXPECT_EQ(si.object_id, 10 + id);
      EXPECT_NEAR(length(si.geometric_normal), 1.f, 1e-5f);
      EXPECT_NEAR(length(si.shading_normal), 1.f, 1e-5f);
      EXPECT_LE(dot(si.geometric_normal, ray.direction), 0.f) << "normal must face the incoming ray, prim " << id;
      EXPECT_GE(dot(si.shading_normal, si.geometric_normal), 0.f);
      EXPECT_NEAR(distance_to_surface(id, si.position), 0.f, 1e-4f) << "prim " << id;
      const Vec3 along = si.position - ray.at(hit.t);
      EXPECT_LT(length(along), 1e-4f) << "prim " << id;
    }
    EXPECT_GT(hits, 100) << "prim " << id;
  }
}

TEST(SurfaceAt, FrontFaceFollowsTheShapesOwnNormal) {
  Geometry g;
  g.add(Triangle{{0.f, 0.f, 0.f}, {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}}, 0);  // normal +z
  Ray from_above{{0.2f, 0.2f, 1.f}, 0.f, {0.f, 0.f, -1.f}};
  Ray from_below{{0.2f, 0.2f, -1.f}, 0.f, {0.f, 0.f, 1.f}};
  Hit h1, h2;
  ASSERT_TRUE(g.intersect(0, WatertightRay(from_above), from_above, h1));
  ASSERT_TRUE(g.intersect(0, WatertightRay(from_below), from_below, h2));
  const SurfaceInteraction a = surface_at(g, from_above, h1), b = surface_at(g, from_below, h2);
  EXPECT_TRUE(a.front_face);
  EXPECT_FALSE(b.front_face);
  EXPECT_EQ(a.geometric_normal, (Vec3{0.f, 0.f, 1.f}));
  EXPECT_EQ(b.geometric_normal, (Vec3{0.f, 0.f, -1.f}));
  EXPECT_NEAR(a.position.x, 0.2f, 1e-6f);
  EXPECT_NEAR(a.position.y, 0.2f, 1e-6f);
}

}  // namespace
}  // namespace raylab
