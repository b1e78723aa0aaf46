// Shape-box overlap tests (overlap.h) against references: points sampled on each surface (every
// box around a sample must be accepted), polygon clipping for triangles and quads (exact both
// ways, up to a margin), inscribed and circumscribed polygons for disks, a Lipschitz bound for
// cones (boxes it proves empty must be rejected), and analytic cases (touching faces, edges and
// corners, flat boxes, degenerate triangles, boxes inside spheres and cones).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "../accel/test_scenes.h"
#include "raylab/geometry/overlap.h"

namespace raylab {
namespace {

using test_scenes::Sampler;

constexpr double kPi = 3.14159265358979323846;

Box3 box(Vec3 lo, Vec3 hi) { return {lo, hi}; }

// A random box holding `p` with a margin of at least 1% of `size` on every side, so that a sample
// rounded to float by an ulp is still inside it.
Box3 box_around(Vec3 p, float size, Sampler& s) {
  Box3 b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = p[k] - size * s.uni(0.01f, 1.f);
    b.hi[k] = p[k] + size * s.uni(0.01f, 1.f);
  }
  return b;
}

// A random box near a shape of extent `scale` around `c`: sizes over two decades.
Box3 random_box(Vec3 c, float scale, Sampler& s) {
  const Vec3 centre = c + s.in_box(Vec3(-scale), Vec3(scale));
  Vec3 half;
  for (int k = 0; k < 3; ++k) half[k] = s.log_uniform(1e-2f, 1.f) * scale;
  return {centre - half, centre + half};
}

// ---------------------------------------------------------------------------------------------
// Reference: convex polygon clipping in double (Sutherland-Hodgman against the six box planes).

using P3 = std::array<double, 3>;
using Polygon = std::vector<P3>;

P3 p3(Vec3 v) { return {v.x, v.y, v.z}; }

// True when the convex polygon (any number of vertices >= 1, degenerate allowed) has a point in
// the box [lo - grow, hi + grow] (grow < 0 shrinks it).
bool clip_reference(Polygon poly, const Box3& b, double grow) {
  for (int k = 0; k < 3; ++k) {
    const double lo = double(b.lo[k]) - grow, hi = double(b.hi[k]) + grow;
    if (lo > hi) return false;
    for (int side = 0; side < 2; ++side) {
      auto dist = [&](const P3& p) { return side == 0 ? p[k] - lo : hi - p[k]; };  // >= 0 inside
      Polygon out;
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const P3& cur = poly[i];
        const P3& prev = poly[(i + poly.size() - 1) % poly.size()];
        const double dc = dist(cur), dp = dist(prev);
        if ((dc >= 0.0) != (dp >= 0.0)) {
          const double t = dp / (dp - dc);
          out.push_back(
              {prev[0] + t * (cur[0] - prev[0]), prev[1] + t * (cur[1] - prev[1]), prev[2] + t * (cur[2] - prev[2])});
        }
        if (dc >= 0.0) out.push_back(cur);
      }
      if (out.empty()) return false;
      poly = std::move(out);
    }
  }
  return true;
}

// Checks `test` against the clipping reference on `boxes`: a box the reference finds overlapping
// even when shrunk by `margin` must be accepted; one it finds disjoint even when grown must be
// rejected. Returns {accepted, rejected} counts of the decided boxes.
template <class Test>
std::pair<int, int> check_against_clipping(const Polygon& poly, const std::vector<Box3>& boxes, double margin,
                                           Test test) {
  int accepted = 0, rejected = 0;
  for (const Box3& b : boxes) {
    if (clip_reference(poly, b, -margin)) {
      ++accepted;
      EXPECT_TRUE(test(b)) << "missed an overlap: box (" << b.lo.x << ", " << b.lo.y << ", " << b.lo.z << ") - ("
                           << b.hi.x << ", " << b.hi.y << ", " << b.hi.z << ")";
    } else if (!clip_reference(poly, b, margin)) {
      ++rejected;
      EXPECT_FALSE(test(b)) << "accepted a disjoint box (" << b.lo.x << ", " << b.lo.y << ", " << b.lo.z << ") - ("
                            << b.hi.x << ", " << b.hi.y << ", " << b.hi.z << ")";
    }
  }
  return {accepted, rejected};
}

// ---------------------------------------------------------------------------------------------
// Triangles

// Random triangles of every shape, degenerate ones included.
Triangle random_triangle(Sampler& s, int kind) {
  const Vec3 p0 = s.in_box(Vec3(-2.f), Vec3(2.f));
  const Vec3 p1 = p0 + s.unit() * s.uni(0.2f, 3.f);
  switch (kind % 6) {
    case 0:  // general
      return {p0, p1, p0 + s.unit() * s.uni(0.2f, 3.f)};
    case 1:  // sliver: the third vertex almost on the opposite edge
      return {p0, p1, p0 + (p1 - p0) * s.uni(0.f, 1.f) + s.unit() * 1e-3f};
    case 2:  // collinear (up to the rounding of the third vertex)
      return {p0, p1, p0 + (p1 - p0) * s.uni(-1.f, 2.f)};
    case 3:  // two equal vertices: a segment
      return {p0, p1, p1};
    case 4:  // a point
      return {p0, p0, p0};
    default:  // axis-aligned: flat bounding box
      return {p0, {p1.x, p1.y, p0.z}, {p0.x + s.uni(-2.f, 2.f), p0.y + s.uni(-2.f, 2.f), p0.z}};
  }
}

TEST(TriangleBoxOverlap, EveryBoxAroundASurfacePointIsAccepted) {
  Sampler s(101);
  for (int i = 0; i < 300; ++i) {
    const Triangle t = random_triangle(s, i);
    for (int j = 0; j < 20; ++j) {
      // Barycentric sample; one in four on an edge or a vertex, where boxes only just touch.
      double a = s.rng.next_float(), b = s.rng.next_float();
      if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
      if (j % 4 == 0) a = 0.0;
      if (j % 8 == 0) b = 0.0;
      const P3 p0 = p3(t.p0), p1 = p3(t.p1), p2 = p3(t.p2);
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = float(p0[k] + a * (p1[k] - p0[k]) + b * (p2[k] - p0[k]));
      const Box3 b3 = box_around(p, s.log_uniform(1e-3f, 2.f), s);
      ASSERT_TRUE(triangle_overlaps_box(t, b3)) << "triangle " << i << " sample " << j;
    }
  }
}

TEST(TriangleBoxOverlap, AgreesWithPolygonClippingBothWays) {
  Sampler s(102);
  int accepted = 0, rejected = 0, edge_axis_only = 0;
  for (int i = 0; i < 300; ++i) {
    const Triangle t = random_triangle(s, i);
    std::vector<Box3> boxes;
    for (int j = 0; j < 60; ++j) boxes.push_back(random_box((t.p0 + t.p1 + t.p2) / 3.f, 1.f, s));
    const auto [acc, rej] = check_against_clipping({p3(t.p0), p3(t.p1), p3(t.p2)}, boxes, 1e-5,
                                                   [&](const Box3& b) { return triangle_overlaps_box(t, b); });
    accepted += acc;
    rejected += rej;
    // Count the rejections no box normal and no triangle normal explains: only the edge axes can.
    for (const Box3& b : boxes) {
      Box3 tb;
      tb.extend(t.p0), tb.extend(t.p1), tb.extend(t.p2);
      const bool boxes_meet = tb.lo.x <= b.hi.x && b.lo.x <= tb.hi.x && tb.lo.y <= b.hi.y && b.lo.y <= tb.hi.y &&
                              tb.lo.z <= b.hi.z && b.lo.z <= tb.hi.z;
      const Vec3 n = triangle_normal(t);
      const Vec3 c = b.center(), h = b.extent() * 0.5f;
      const float r = h.x * std::fabs(n.x) + h.y * std::fabs(n.y) + h.z * std::fabs(n.z);
      const bool plane_meets = std::fabs(dot(n, c - t.p0)) <= r;
      if (boxes_meet && plane_meets && !clip_reference({p3(t.p0), p3(t.p1), p3(t.p2)}, b, 1e-5)) ++edge_axis_only;
    }
  }
  // Both outcomes must be well represented for the comparison to mean anything.
  EXPECT_GT(accepted, 600);
  EXPECT_GT(rejected, 8000);
  EXPECT_GT(edge_axis_only, 500);
}

TEST(TriangleBoxOverlap, TouchingFaceEdgeAndCornerCount) {
  const Box3 unit = box({0.f, 0.f, 0.f}, {1.f, 1.f, 1.f});
  // A big triangle in the plane of the bottom face: touches the whole face.
  EXPECT_TRUE(triangle_overlaps_box({{-5.f, -5.f, 0.f}, {10.f, -5.f, 0.f}, {-5.f, 10.f, 0.f}}, unit));
  EXPECT_FALSE(triangle_overlaps_box({{-5.f, -5.f, -1e-3f}, {10.f, -5.f, -1e-3f}, {-5.f, 10.f, -1e-3f}}, unit));
  // In the plane x + y = 2, which meets the box only along its edge x = y = 1.
  EXPECT_TRUE(triangle_overlaps_box({{2.f, 0.f, -5.f}, {0.f, 2.f, -5.f}, {1.f, 1.f, 10.f}}, unit));
  EXPECT_FALSE(triangle_overlaps_box({{2.001f, 0.f, -5.f}, {0.f, 2.001f, -5.f}, {1.0005f, 1.0005f, 10.f}}, unit));
  // In the plane x + y + z = 3, which meets the box only at its corner (1, 1, 1), the centroid.
  EXPECT_TRUE(triangle_overlaps_box({{3.f, 0.f, 0.f}, {0.f, 3.f, 0.f}, {0.f, 0.f, 3.f}}, unit));
  EXPECT_FALSE(triangle_overlaps_box({{3.001f, 0.f, 0.f}, {0.f, 3.001f, 0.f}, {0.f, 0.f, 3.001f}}, unit));
  // A vertex exactly on a face, the triangle pointing away.
  EXPECT_TRUE(triangle_overlaps_box({{1.f, 0.5f, 0.5f}, {3.f, 0.f, 0.f}, {3.f, 1.f, 1.f}}, unit));
  EXPECT_FALSE(triangle_overlaps_box({{1.0001f, 0.5f, 0.5f}, {3.f, 0.f, 0.f}, {3.f, 1.f, 1.f}}, unit));
}

TEST(TriangleBoxOverlap, TriangleCoveringTheCrossSection) {
  // Every box corner lies outside the triangle's extent in x and y, and the triangle's bounding
  // box holds the whole box: only the plane decides.
  const Box3 unit = box({0.f, 0.f, 0.f}, {1.f, 1.f, 1.f});
  EXPECT_TRUE(triangle_overlaps_box({{-10.f, -10.f, 0.5f}, {30.f, -10.f, 0.5f}, {-10.f, 30.f, 0.5f}}, unit));
  // Tilted through the box: still crosses it.
  EXPECT_TRUE(triangle_overlaps_box({{-10.f, -10.f, -2.f}, {30.f, -10.f, 3.f}, {-10.f, 30.f, 3.f}}, unit));
  // Tilted so that the plane passes just above the corner (1, 1, 1).
  EXPECT_FALSE(triangle_overlaps_box({{-10.f, -10.f, 23.01f}, {30.f, -10.f, -16.99f}, {-10.f, 30.f, -16.99f}}, unit));
}

TEST(TriangleBoxOverlap, FlatBoxInTheTrianglePlane) {
  const Triangle t{{0.f, 0.f, 2.f}, {4.f, 0.f, 2.f}, {0.f, 4.f, 2.f}};
  EXPECT_TRUE(triangle_overlaps_box(t, box({1.f, 1.f, 2.f}, {1.5f, 1.5f, 2.f})));   // inside
  EXPECT_TRUE(triangle_overlaps_box(t, box({1.f, 1.f, 2.f}, {3.f, 3.f, 2.f})));     // across the hypotenuse
  EXPECT_TRUE(triangle_overlaps_box(t, box({2.f, 2.f, 2.f}, {3.f, 3.f, 2.f})));     // touches it at (2, 2)
  EXPECT_FALSE(triangle_overlaps_box(t, box({2.01f, 2.f, 2.f}, {3.f, 3.f, 2.f})));  // just beyond
  EXPECT_FALSE(triangle_overlaps_box(t, box({1.f, 1.f, 2.01f}, {1.5f, 1.5f, 2.01f})));
  // A point box on the triangle's edge, and one on its vertex.
  EXPECT_TRUE(triangle_overlaps_box(t, box({2.f, 0.f, 2.f}, {2.f, 0.f, 2.f})));
  EXPECT_TRUE(triangle_overlaps_box(t, box({4.f, 0.f, 2.f}, {4.f, 0.f, 2.f})));
}

TEST(TriangleBoxOverlap, DegenerateTriangles) {
  const Box3 unit = box({0.f, 0.f, 0.f}, {1.f, 1.f, 1.f});
  // Points: inside, on a corner, outside.
  EXPECT_TRUE(triangle_overlaps_box({Vec3(0.5f), Vec3(0.5f), Vec3(0.5f)}, unit));
  EXPECT_TRUE(triangle_overlaps_box({Vec3(1.f), Vec3(1.f), Vec3(1.f)}, unit));
  EXPECT_FALSE(triangle_overlaps_box({Vec3(1.01f), Vec3(1.01f), Vec3(1.01f)}, unit));
  // A segment through the box, both ends outside.
  EXPECT_TRUE(triangle_overlaps_box({{-1.f, 0.5f, 0.5f}, {2.f, 0.5f, 0.5f}, {2.f, 0.5f, 0.5f}}, unit));
  // Collinear vertices along x + y = 2 at z = 0.5: touches the edge x = y = 1; shifted, it
  // misses, which only the cross product of its direction with the z axis shows.
  EXPECT_TRUE(triangle_overlaps_box({{2.f, 0.f, 0.5f}, {0.f, 2.f, 0.5f}, {1.5f, 0.5f, 0.5f}}, unit));
  EXPECT_FALSE(triangle_overlaps_box({{2.05f, 0.f, 0.5f}, {0.f, 2.05f, 0.5f}, {1.55f, 0.5f, 0.5f}}, unit));
  // An empty box holds nothing.
  EXPECT_FALSE(triangle_overlaps_box({Vec3(0.5f), Vec3(0.6f), Vec3(0.7f)}, Box3{}));
}

// ---------------------------------------------------------------------------------------------
// Quads

Quad random_quad(Sampler& s, int kind) {
  const Vec3 c = s.in_box(Vec3(-2.f), Vec3(2.f));
  const Vec3 u = s.unit() * s.uni(0.2f, 3.f);
  if (kind % 4 == 1) return {c, u, u * s.uni(-1.f, 1.f)};                        // degenerate: parallel edges
  if (kind % 4 == 2) return {c, {u.x, u.y, 0.f}, {0.f, s.uni(0.2f, 3.f), 0.f}};  // axis-aligned normal
  return {c, u, s.unit() * s.uni(0.2f, 3.f)};
}

TEST(QuadBoxOverlap, EveryBoxAroundASurfacePointIsAccepted) {
  Sampler s(201);
  for (int i = 0; i < 300; ++i) {
    const Quad q = random_quad(s, i);
    for (int j = 0; j < 20; ++j) {
      double a = s.rng.next_float(), b = s.rng.next_float();
      if (j % 4 == 0) a = j % 8 == 0 ? 0.0 : 1.0;  // on an edge
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = float(double(q.corner[k]) + a * q.edge_u[k] + b * q.edge_v[k]);
      ASSERT_TRUE(quad_overlaps_box(q, box_around(p, s.log_uniform(1e-3f, 2.f), s))) << "quad " << i;
    }
  }
}

TEST(QuadBoxOverlap, AgreesWithPolygonClippingBothWays) {
  Sampler s(202);
  int accepted = 0, rejected = 0;
  for (int i = 0; i < 200; ++i) {
    const Quad q = random_quad(s, i);
    const P3 c = p3(q.corner), u = p3(q.edge_u), v = p3(q.edge_v);
    const Polygon poly = {c,
                          {c[0] + u[0], c[1] + u[1], c[2] + u[2]},
                          {c[0] + u[0] + v[0], c[1] + u[1] + v[1], c[2] + u[2] + v[2]},
                          {c[0] + v[0], c[1] + v[1], c[2] + v[2]}};
    std::vector<Box3> boxes;
    for (int j = 0; j < 60; ++j) boxes.push_back(random_box(q.corner + (q.edge_u + q.edge_v) * 0.5f, 1.5f, s));
    const auto [acc, rej] =
        check_against_clipping(poly, boxes, 1e-5, [&](const Box3& b) { return quad_overlaps_box(q, b); });
    accepted += acc;
    rejected += rej;
  }
  EXPECT_GT(accepted, 500);
  EXPECT_GT(rejected, 5000);
}

// ---------------------------------------------------------------------------------------------
// Spheres and balls

TEST(SphereBoxOverlap, EveryBoxAroundASurfacePointIsAccepted) {
  Sampler s(301);
  for (int i = 0; i < 200; ++i) {
    const Sphere sp{s.in_box(Vec3(-5.f), Vec3(5.f)), s.log_uniform(0.1f, 10.f)};
    for (int j = 0; j < 20; ++j) {
      const Vec3 d = s.unit();
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = float(double(sp.center[k]) + double(sp.radius) * d[k]);
      ASSERT_TRUE(sphere_overlaps_box(sp, box_around(p, sp.radius * s.log_uniform(1e-2f, 2.f), s)));
    }
  }
}

TEST(SphereBoxOverlap, TouchingFromOutsideAndFromInside) {
  const Sphere s3{{0.f, 0.f, 0.f}, 3.f};
  // From outside: nearest point on a face, on an edge ((3, 4, 0) at distance 5), at a corner
  // ((1, 2, 2) at distance 3).
  EXPECT_TRUE(sphere_overlaps_box(s3, box({3.f, -1.f, -1.f}, {4.f, 1.f, 1.f})));
  EXPECT_FALSE(sphere_overlaps_box(s3, box({3.001f, -1.f, -1.f}, {4.f, 1.f, 1.f})));
  EXPECT_TRUE(sphere_overlaps_box({{0.f, 0.f, 0.f}, 5.f}, box({3.f, 4.f, -1.f}, {4.f, 5.f, 1.f})));
  EXPECT_FALSE(sphere_overlaps_box({{0.f, 0.f, 0.f}, 5.f}, box({3.f, 4.001f, -1.f}, {4.f, 5.f, 1.f})));
  EXPECT_TRUE(sphere_overlaps_box(s3, box({1.f, 2.f, 2.f}, {2.f, 3.f, 3.f})));
  EXPECT_FALSE(sphere_overlaps_box(s3, box({1.001f, 2.f, 2.f}, {2.f, 3.f, 3.f})));
  // From inside: the farthest corner (1, 2, 2) on the surface touches it; a box strictly inside
  // the ball holds no surface.
  EXPECT_TRUE(sphere_overlaps_box(s3, box({0.f, 0.f, 0.f}, {1.f, 2.f, 2.f})));
  EXPECT_FALSE(sphere_overlaps_box(s3, box({0.f, 0.f, 0.f}, {0.999f, 2.f, 2.f})));
  EXPECT_FALSE(sphere_overlaps_box(s3, box(Vec3(-1.f), Vec3(1.f))));
  // A box holding the whole sphere, and a flat box through the centre.
  EXPECT_TRUE(sphere_overlaps_box(s3, box(Vec3(-4.f), Vec3(4.f))));
  EXPECT_TRUE(sphere_overlaps_box(s3, box({-4.f, -4.f, 0.f}, {4.f, 4.f, 0.f})));
}

TEST(SphereBoxOverlap, MatchesDistanceReferenceOnRandomBoxes) {
  // Reference: the nearest and farthest box points by dense corner/face sampling would be loose;
  // instead check the two analytic conditions separately with a margin.
  Sampler s(303);
  int accepted = 0, inside = 0, outside = 0;
  for (int i = 0; i < 5000; ++i) {
    const Sphere sp{s.in_box(Vec3(-1.f), Vec3(1.f)), s.uni(0.5f, 2.f)};
    const Box3 b = random_box(sp.center, 2.f, s);
    double near2 = 0.0, far2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double lo = double(b.lo[k]) - sp.center[k], hi = double(b.hi[k]) - sp.center[k];
      const double near = std::max({0.0, lo, -hi}), far = std::max(-lo, hi);
      near2 += near * near, far2 += far * far;
    }
    const double r = sp.radius, m = 1e-5;
    const bool result = sphere_overlaps_box(sp, b);
    if (std::sqrt(near2) > r + m) {
      ++outside;
      EXPECT_FALSE(result) << "box outside the sphere";
    } else if (std::sqrt(far2) < r - m) {
      ++inside;
      EXPECT_FALSE(result) << "box inside the sphere";
    } else if (std::sqrt(near2) < r - m && std::sqrt(far2) > r + m) {
      ++accepted;
      EXPECT_TRUE(result) << "box across the surface";
    }
    EXPECT_EQ(ball_overlaps_box(sp, b), std::sqrt(near2) <= r) << "ball";
  }
  EXPECT_GT(accepted, 800);
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 1500);
}

TEST(BallBoxOverlap, CountsBoxesInsideTheBall) {
  const Sphere s3{{0.f, 0.f, 0.f}, 3.f};
  EXPECT_TRUE(ball_overlaps_box(s3, box(Vec3(-1.f), Vec3(1.f))));
  EXPECT_TRUE(ball_overlaps_box(s3, box({1.f, 2.f, 2.f}, {2.f, 3.f, 3.f})));  // touching corner
  EXPECT_FALSE(ball_overlaps_box(s3, box({1.001f, 2.f, 2.f}, {2.f, 3.f, 3.f})));
}

// ---------------------------------------------------------------------------------------------
// Disks

Disk random_disk(Sampler& s, int kind) {
  Vec3 n = s.unit();
  if (kind % 3 == 1) n = {0.f, 0.f, 1.f};  // axis-aligned: flat bounding box
  return {s.in_box(Vec3(-2.f), Vec3(2.f)), n, s.uni(0.2f, 3.f)};
}

// An orthonormal pair spanning the plane of unit normal `n`, in double.
void plane_basis(const P3& n, P3& u, P3& v) {
  const P3 a = std::fabs(n[0]) < 0.6 ? P3{1.0, 0.0, 0.0} : P3{0.0, 1.0, 0.0};
  u = {n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0]};
  const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& x : u) x /= lu;
  v = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
}

// The disk's boundary as a regular polygon of `sides` vertices at distance `radius`.
Polygon disk_polygon(const Disk& d, double radius, int sides) {
  const double ln = std::sqrt(double(dot(d.normal, d.normal)));
  const P3 n = {d.normal.x / ln, d.normal.y / ln, d.normal.z / ln};
  P3 u, v;
  plane_basis(n, u, v);
  Polygon poly;
  for (int i = 0; i < sides; ++i) {
    const double a = 2.0 * kPi * i / sides;
    P3 p;
    for (int k = 0; k < 3; ++k) p[k] = d.center[k] + radius * (std::cos(a) * u[k] + std::sin(a) * v[k]);
    poly.push_back(p);
  }
  return poly;
}

TEST(DiskBoxOverlap, EveryBoxAroundASurfacePointIsAccepted) {
  Sampler s(401);
  for (int i = 0; i < 300; ++i) {
    const Disk d = random_disk(s, i);
    const Polygon rim = disk_polygon(d, d.radius, 64);
    for (int j = 0; j < 20; ++j) {
      // A point of the disk: a rim point (one in four exactly on the rim) scaled towards the centre.
      const P3& r = rim[s.rng.next_u32() % rim.size()];
      const double f = j % 4 == 0 ? 1.0 : std::sqrt(double(s.rng.next_float()));
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = float(d.center[k] + f * (r[k] - d.center[k]));
      ASSERT_TRUE(disk_overlaps_box(d, box_around(p, d.radius * s.log_uniform(1e-2f, 2.f), s))) << "disk " << i;
    }
  }
}

TEST(DiskBoxOverlap, BetweenInscribedAndCircumscribedPolygons) {
  // The disk lies between its inscribed 256-gon and the circumscribed one: a box the inner polygon
  // reaches must be accepted, a box the outer polygon misses must be rejected.
  Sampler s(402);
  constexpr int kSides = 256;
  int accepted = 0, rejected = 0;
  for (int i = 0; i < 120; ++i) {
    const Disk d = random_disk(s, i);
    const Polygon inner = disk_polygon(d, d.radius, kSides);
    const Polygon outer = disk_polygon(d, d.radius / std::cos(kPi / kSides), kSides);
    for (int j = 0; j < 60; ++j) {
      const Box3 b = random_box(d.center, d.radius, s);
      const bool result = disk_overlaps_box(d, b);
      if (clip_reference(inner, b, -1e-5)) {
        ++accepted;
        EXPECT_TRUE(result) << "disk " << i << " box " << j;
      } else if (!clip_reference(outer, b, 1e-5)) {
        ++rejected;
        EXPECT_FALSE(result) << "disk " << i << " box " << j;
      }
    }
  }
  EXPECT_GT(accepted, 900);
  EXPECT_GT(rejected, 2500);
}

TEST(DiskBoxOverlap, AnalyticCases) {
  const Disk d{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, 1.f};
  EXPECT_TRUE(disk_overlaps_box(d, box({1.f, -0.1f, -0.1f}, {2.f, 0.1f, 0.1f})));  // touches the rim
  EXPECT_FALSE(disk_overlaps_box(d, box({1.001f, -0.1f, -0.1f}, {2.f, 0.1f, 0.1f})));
  EXPECT_TRUE(disk_overlaps_box(d, box({0.7f, 0.7f, -1.f}, {1.f, 1.f, 1.f})));         // corner at 0.99
  EXPECT_FALSE(disk_overlaps_box(d, box({0.8f, 0.8f, -1.f}, {1.f, 1.f, 1.f})));        // corner at 1.13
  EXPECT_TRUE(disk_overlaps_box(d, box({-0.5f, -0.5f, 0.f}, {0.5f, 0.5f, 1.f})));      // face on the plane
  EXPECT_FALSE(disk_overlaps_box(d, box({-0.5f, -0.5f, 0.001f}, {0.5f, 0.5f, 1.f})));  // just above
  EXPECT_TRUE(disk_overlaps_box(d, box(Vec3(-5.f), Vec3(5.f))));                       // holds it all
  // Tilted 45 degrees about y: a box whose 3D distance to the centre is under the radius while its
  // section by the plane (x = -z) stays farther: (0.75, 0, -0.75) is at 1.06.
  const float h = std::sqrt(0.5f);
  const Disk tilted{{0.f, 0.f, 0.f}, {h, 0.f, h}, 1.f};
  EXPECT_FALSE(disk_overlaps_box(tilted, box({0.75f, -0.1f, -0.8f}, {0.9f, 0.1f, -0.6f})));
  EXPECT_TRUE(disk_overlaps_box(tilted, box({0.65f, -0.1f, -0.8f}, {0.9f, 0.1f, -0.6f})));
}

// ---------------------------------------------------------------------------------------------
// Cone frustums

Cylinder random_cone(Sampler& s, int kind) {
  const Vec3 base = s.in_box(Vec3(-2.f), Vec3(2.f));
  const Vec3 apex = base + s.unit() * s.log_uniform(0.1f, 5.f);
  const float r = s.log_uniform(0.05f, 2.f);
  switch (kind % 4) {
    case 0:
      return {base, r, apex, r};  // cylinder
    case 1:
      return {base, r, apex, 0.f};  // cone to a point
    case 2:
      return {base, r, apex, s.log_uniform(0.05f, 2.f)};  // frustum
    default:
      return {base, r, {apex.x, base.y, base.z}, r};  // axis-aligned cylinder
  }
}

// The point at height fraction `h` and angle `a` on the lateral surface, computed in double.
Vec3 cone_point(const Cylinder& c, double h, double a) {
  P3 w = p3(c.apex - c.base);
  const double len = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  for (double& x : w) x /= len;
  P3 u, v;
  plane_basis(w, u, v);
  const double r = c.base_radius + h * (double(c.apex_radius) - c.base_radius);
  Vec3 p;
  for (int k = 0; k < 3; ++k) {
    p[k] = float(c.base[k] + h * (double(c.apex[k]) - c.base[k]) + r * (std::cos(a) * u[k] + std::sin(a) * v[k]));
  }
  return p;
}

TEST(CylinderBoxOverlap, EveryBoxAroundASurfacePointIsAccepted) {
  Sampler s(501);
  for (int i = 0; i < 300; ++i) {
    const Cylinder c = random_cone(s, i);
    const float scale = std::max(length(c.apex - c.base), c.base_radius);
    for (int j = 0; j < 30; ++j) {
      const double h = j % 5 == 0 ? (j % 10 == 0 ? 0.0 : 1.0) : s.rng.next_float();  // some on the rims
      const Vec3 p = cone_point(c, h, 2.0 * kPi * s.rng.next_float());
      ASSERT_TRUE(cylinder_overlaps_box(c, box_around(p, scale * s.log_uniform(1e-2f, 2.f), s)))
          << "cone " << i << " sample " << j;
    }
  }
}

TEST(CylinderBoxOverlap, RejectsEveryBoxALipschitzBoundProvesEmpty) {
  // f(p) = (distance to the axis) - (radius at p's height) vanishes on the surface and changes by
  // at most sqrt(1 + slope^2) per unit of distance, so a box whose centre has |f| above that times
  // its half diagonal holds no surface point; nor does a box wholly beyond an end plane. The test
  // is conservative, but it must be at least this tight.
  Sampler s(502);
  int provably_empty = 0, accepted = 0;
  for (int i = 0; i < 200; ++i) {
    const Cylinder c = random_cone(s, i);
    const P3 base = p3(c.base);
    P3 w = p3(c.apex - c.base);
    const double len = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (double& x : w) x /= len;
    const double slope = (double(c.apex_radius) - c.base_radius) / len;
    const float scale = std::max(float(len), c.base_radius);
    for (int j = 0; j < 100; ++j) {
      const Box3 b = random_box(c.base, scale, s);
      auto height = [&](const P3& p) {
        return (p[0] - base[0]) * w[0] + (p[1] - base[1]) * w[1] + (p[2] - base[2]) * w[2];
      };
      const P3 ctr = p3(b.center());
      const double z = height(ctr);
      P3 q;
      for (int k = 0; k < 3; ++k) q[k] = ctr[k] - base[k] - z * w[k];
      const double f = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) - (c.base_radius + slope * z);
      const Vec3 e = b.extent() * 0.5f;
      const double half_diagonal = std::sqrt(double(dot(e, e)));
      double zmin = 1e300, zmax = -1e300;
      for (int k = 0; k < 8; ++k) {
        const double hz = height({(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z});
        zmin = std::min(zmin, hz), zmax = std::max(zmax, hz);
      }
      const double margin = 1e-4 * scale;
      const bool empty = std::fabs(f) > 1.01 * std::sqrt(1.0 + slope * slope) * half_diagonal + margin ||
                         zmin > len + margin || zmax < -margin;
      const bool result = cylinder_overlaps_box(c, b);
      if (empty) {
        ++provably_empty;
        EXPECT_FALSE(result) << "cone " << i << " box " << j << " f " << f;
      }
      accepted += result;
    }
  }
  EXPECT_GT(provably_empty, 6000);
  EXPECT_GT(accepted, 1800);
}

TEST(CylinderBoxOverlap, AnalyticCases) {
  const Cylinder cyl{{0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 4.f}, 1.f};
  EXPECT_FALSE(cylinder_overlaps_box(cyl, box({-0.5f, -0.5f, 1.f}, {0.5f, 0.5f, 3.f})));    // inside
  EXPECT_FALSE(cylinder_overlaps_box(cyl, box({0.5f, 0.5f, 1.f}, {0.6f, 0.6f, 2.f})));      // inside, 0.85
  EXPECT_TRUE(cylinder_overlaps_box(cyl, box({0.5f, 0.5f, 1.f}, {0.75f, 0.75f, 2.f})));     // corner at 1.06
  EXPECT_TRUE(cylinder_overlaps_box(cyl, box({1.f, -0.1f, 1.f}, {2.f, 0.1f, 2.f})));        // touches
  EXPECT_FALSE(cylinder_overlaps_box(cyl, box({1.01f, -0.1f, 1.f}, {2.f, 0.1f, 2.f})));     // beside
  EXPECT_FALSE(cylinder_overlaps_box(cyl, box({0.8f, 0.8f, 1.f}, {2.f, 2.f, 2.f})));        // beside, diagonally
  EXPECT_FALSE(cylinder_overlaps_box(cyl, box({-0.1f, -0.1f, 4.01f}, {0.1f, 0.1f, 5.f})));  // past the open end
  EXPECT_TRUE(cylinder_overlaps_box(cyl, box({-0.1f, -1.1f, 3.99f}, {0.1f, 1.1f, 5.f})));   // across the rim
  EXPECT_TRUE(cylinder_overlaps_box(cyl, box({-2.f, -2.f, -1.f}, {2.f, 2.f, 5.f})));        // holds it all
  EXPECT_TRUE(cylinder_overlaps_box(cyl, box({-2.f, -2.f, 2.f}, {2.f, 2.f, 2.f})));         // a flat section
  EXPECT_TRUE(cylinder_overlaps_box(cyl, box({-2.f, -0.1f, 1.f}, {2.f, 0.1f, 2.f})));       // pierced sideways
  // A cone from radius 2 at z = 0 to a point at z = 2: at height z the radius is 2 - z.
  const Cylinder cone{{0.f, 0.f, 0.f}, 2.f, {0.f, 0.f, 2.f}, 0.f};
  EXPECT_FALSE(cylinder_overlaps_box(cone, box({0.5f, 0.5f, 0.f}, {1.f, 1.f, 0.1f})));     // inside
  EXPECT_FALSE(cylinder_overlaps_box(cone, box({1.5f, -0.1f, 1.5f}, {2.f, 0.1f, 2.f})));   // beside the slope
  EXPECT_TRUE(cylinder_overlaps_box(cone, box({0.4f, -0.1f, 1.5f}, {2.f, 0.1f, 2.f})));    // across the slope
  EXPECT_TRUE(cylinder_overlaps_box(cone, box({-0.1f, -0.1f, 1.9f}, {0.1f, 0.1f, 3.f})));  // holds the tip
  // Zero length: never hit, so never in a cell.
  EXPECT_FALSE(cylinder_overlaps_box({Vec3(1.f), 1.f, Vec3(1.f), 1.f}, box(Vec3(0.f), Vec3(2.f))));
}

// ---------------------------------------------------------------------------------------------
// Dispatch and groups

TEST(OverlapsBox, DispatchesOnTheKind) {
  Sampler s(601);
  Geometry g;
  g.add(random_triangle(s, 0), 0);
  g.add(Sphere{{0.5f, 0.f, 0.f}, 1.f}, 0);
  g.add(random_cone(s, 0), 0);
  g.add(random_disk(s, 0), 0);
  g.add(random_quad(s, 0), 0);
  int accepted = 0;
  for (int i = 0; i < 2000; ++i) {
    const Box3 b = random_box(Vec3(0.f), 2.f, s);
    EXPECT_EQ(overlaps_box(g, 0, b), triangle_overlaps_box(g.triangles[0], b));
    EXPECT_EQ(overlaps_box(g, 1, b), sphere_overlaps_box(g.spheres[0], b));
    EXPECT_EQ(overlaps_box(g, 2, b), cylinder_overlaps_box(g.cylinders[0], b));
    EXPECT_EQ(overlaps_box(g, 3, b), disk_overlaps_box(g.disks[0], b));
    EXPECT_EQ(overlaps_box(g, 4, b), quad_overlaps_box(g.quads[0], b));
    for (std::uint32_t id = 0; id < 5; ++id) accepted += overlaps_box(g, id, b);
  }
  EXPECT_GT(accepted, 300);
}

TEST(OverlapsBox, GroupsAreSolidVolumes) {
  Geometry g;
  GroupShape boxed;
  boxed.box = box(Vec3(0.f), Vec3(10.f));
  GroupShape balled = boxed;
  balled.sphere = {Vec3(5.f), 5.f};
  g.groups = {boxed, balled};
  const std::uint32_t box_id = kGroupIdBase, ball_id = kGroupIdBase + 1;
  // Inside counts for both wrappers (unlike a sphere primitive).
  EXPECT_TRUE(overlaps_box(g, box_id, box(Vec3(4.f), Vec3(6.f))));
  EXPECT_TRUE(overlaps_box(g, ball_id, box(Vec3(4.f), Vec3(6.f))));
  // In the box's corner but outside the ball (distance sqrt(48) > 5).
  EXPECT_TRUE(overlaps_box(g, box_id, box(Vec3(0.f), Vec3(1.f))));
  EXPECT_FALSE(overlaps_box(g, ball_id, box(Vec3(0.f), Vec3(1.f))));
  // Touching the box's face.
  EXPECT_TRUE(overlaps_box(g, box_id, box({10.f, 4.f, 4.f}, {11.f, 6.f, 6.f})));
  EXPECT_TRUE(overlaps_box(g, ball_id, box({10.f, 4.f, 4.f}, {11.f, 6.f, 6.f})));
  EXPECT_FALSE(overlaps_box(g, box_id, box({10.01f, 4.f, 4.f}, {11.f, 6.f, 6.f})));
}

}  // namespace
}  // namespace raylab
