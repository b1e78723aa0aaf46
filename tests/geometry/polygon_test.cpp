// Ear-clipping triangulation of planar polygons (polygon.h): triangle counts, area conservation,
// orientation and containment of every triangle, for convex and non-convex shapes in tilted planes
// and both windings, plus the degenerate and self-intersecting inputs that must not crash.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/geometry/polygon.h"

namespace raylab {
namespace {

using Tris = std::vector<std::array<std::uint32_t, 3>>;

struct P2 {
  double x, y;
};
using Shape = std::vector<P2>;

// Twice the signed area (shoelace): > 0 for counter-clockwise.
double shoelace2(const Shape& s) {
  double a = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const P2 p = s[i], q = s[(i + 1) % s.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

double orient2(P2 a, P2 b, P2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Even-odd rule; a point exactly on the boundary may go either way, so callers use centroids,
// which are strictly inside every non-degenerate triangle.
bool inside(const Shape& s, P2 p) {
  bool in = false;
  for (std::size_t i = 0, j = s.size() - 1; i < s.size(); j = i++) {
    if ((s[i].y > p.y) != (s[j].y > p.y) && p.x < (s[j].x - s[i].x) * (p.y - s[i].y) / (s[j].y - s[i].y) + s[i].x) {
      in = !in;
    }
  }
  return in;
}

Shape reversed(Shape s) { return Shape(s.rbegin(), s.rend()); }

// The 2D shape in the z = 0 plane, exactly.
std::vector<Vec3> flat(const Shape& s) {
  std::vector<Vec3> v;
  for (const P2 p : s) v.push_back({float(p.x), float(p.y), 0.f});
  return v;
}

// The 2D shape placed in a tilted plane through `origin` with orthonormal in-plane axes: the
// triangulation's indices still refer to the 2D points, so everything is checked in 2D.
std::vector<Vec3> tilted(const Shape& s, Vec3 axis_normal, Vec3 origin) {
  Vec3 u, w;
  orthonormal_basis(normalize(axis_normal), u, w);
  std::vector<Vec3> v;
  for (const P2 p : s) v.push_back(origin + u * float(p.x) + w * float(p.y));
  return v;
}

// Checks everything a triangulation of a simple polygon must satisfy, in the shape's own 2D
// coordinates. `sliver` is the area (relative to the polygon's) under which a triangle may be
// considered flat: tilted inputs are rounded to float, so collinear corners there can give
// slivers of either sign along an edge.
void expect_valid(const Shape& shape, const Tris& tris, std::size_t expected_count, double sliver = 0.0) {
  ASSERT_EQ(tris.size(), expected_count);
  const double total2 = shoelace2(shape);
  const double sign = total2 > 0.0 ? 1.0 : -1.0;
  double sum2 = 0.0;
  for (const auto& t : tris) {
    for (const std::uint32_t i : t) ASSERT_LT(i, shape.size());
    const P2 a = shape[t[0]], b = shape[t[1]], c = shape[t[2]];
    const double a2 = orient2(a, b, c);
    sum2 += a2;
    if (std::fabs(a2) <= sliver * std::fabs(total2)) continue;
    EXPECT_GT(a2 * sign, 0.0) << "triangle " << t[0] << " " << t[1] << " " << t[2] << " has the wrong winding";
    const P2 centroid{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
    EXPECT_TRUE(inside(shape, centroid)) << "triangle " << t[0] << " " << t[1] << " " << t[2] << " lies outside";
  }
  EXPECT_NEAR(sum2, total2, 1e-5 * std::fabs(total2));
}

// Runs the shape flat and in several tilted planes, in both windings.
void expect_valid_everywhere(const Shape& shape, std::size_t expected_count, double sliver_when_tilted = 1e-6) {
  const std::array<Vec3, 5> normals{Vec3{0.3f, 0.2f, 1.f}, Vec3{1.f, 0.4f, -0.3f}, Vec3{-0.2f, 1.f, 0.5f},
                                    Vec3{0.577f, -0.577f, 0.577f}, Vec3{0.f, 0.f, -1.f}};
  for (const Shape& s : {shape, reversed(shape)}) {
    SCOPED_TRACE(shoelace2(s) > 0 ? "counter-clockwise" : "clockwise");
    {
      SCOPED_TRACE("z = 0");
      expect_valid(s, triangulate_polygon(flat(s)), expected_count);
    }
    for (const Vec3 n : normals) {
      SCOPED_TRACE(testing::Message() << "plane normal " << n.x << " " << n.y << " " << n.z);
      expect_valid(s, triangulate_polygon(tilted(s, n, {3.f, -2.f, 7.f})), expected_count, sliver_when_tilted);
    }
  }
}

Shape regular(std::size_t n, double r) {
  Shape s;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * double(i) / double(n);
    s.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return s;
}

Shape l_shape() { return {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}; }

Shape u_shape() { return {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}; }

// Five outer points and five reflex inner ones.
Shape star() {
  Shape s;
  for (int i = 0; i < 10; ++i) {
    const double a = std::numbers::pi / 2.0 + std::numbers::pi * i / 5.0;
    const double r = i % 2 == 0 ? 2.0 : 0.7;
    s.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return s;
}

// An "E": the inner corners of the arms are collinear with each other (x = 1) and the arm tips
// with each other (x = 3), so many candidate diagonals pass exactly through other vertices.
Shape e_shape() {
  return {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {3, 2}, {3, 3}, {1, 3}, {1, 4}, {3, 4}, {3, 5}, {0, 5}};
}

// A comb of `teeth` teeth pointing up from a spine.
Shape comb(int teeth) {
  Shape s{{0, 0}, {2.0 * teeth - 1, 0}};
  for (int i = teeth - 1; i >= 0; --i) {
    s.push_back({2.0 * i + 1, 3});
    s.push_back({2.0 * i, 3});
    if (i > 0) {
      s.push_back({2.0 * i, 1});
      s.push_back({2.0 * i - 1, 1});
    }
  }
  return s;
}

// A square spiral corridor of width 1 around a centreline whose parallel runs are 2 apart: most
// vertices see only a few others, and most candidate ears are blocked.
Shape spiral(int segments) {
  Shape centre{{0, 0}};
  const std::array<P2, 4> dirs{P2{1, 0}, P2{0, 1}, P2{-1, 0}, P2{0, -1}};
  for (int i = 0; i < segments; ++i) {
    const double len = 2.0 * (i / 2 + 1);
    centre.push_back({centre.back().x + dirs[i % 4].x * len, centre.back().y + dirs[i % 4].y * len});
  }
  // Walls at +-0.5 with mitred corners: the sum of the half-normals of the two runs at a corner.
  Shape left, right;
  for (std::size_t i = 0; i < centre.size(); ++i) {
    P2 off{0, 0};
    if (i > 0) off = {off.x - 0.5 * dirs[(i - 1) % 4].y, off.y + 0.5 * dirs[(i - 1) % 4].x};
    if (i + 1 < centre.size()) off = {off.x - 0.5 * dirs[i % 4].y, off.y + 0.5 * dirs[i % 4].x};
    left.push_back({centre[i].x + off.x, centre[i].y + off.y});
    right.push_back({centre[i].x - off.x, centre[i].y - off.y});
  }
  Shape s = left;
  s.insert(s.end(), right.rbegin(), right.rend());
  return s;
}

// ---------------------------------------------------------------------------------------------
// Convex

TEST(Polygon, TriangleGivesOneTriangle) {
  const std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Tris t = triangulate_polygon(v);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
}

TEST(Polygon, ConvexQuadGivesTwo) {
  const Shape quad{{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  expect_valid_everywhere(quad, 2);
}

TEST(Polygon, ConvexNGonAreaMatchesShoelace) {
  for (std::size_t n : {5u, 6u, 7u, 12u, 33u, 100u}) {
    SCOPED_TRACE(n);
    expect_valid_everywhere(regular(n, 1.5), n - 2);
  }
}

// Meshes of convex faces must triangulate exactly as the OBJ loader's former fan did.
TEST(Polygon, ConvexPolygonGivesTheFanFromTheFirstVertex) {
  for (const Shape& s : {regular(7, 1.0), reversed(regular(7, 1.0))}) {
    for (const std::vector<Vec3>& v : {flat(s), tilted(s, {0.3f, -1.f, 0.2f}, {1.f, 2.f, 3.f})}) {
      const Tris t = triangulate_polygon(v);
      ASSERT_EQ(t.size(), 5u);
      for (std::uint32_t k = 1; k + 1 < 7; ++k) EXPECT_EQ(t[k - 1], (std::array<std::uint32_t, 3>{0, k, k + 1}));
    }
  }
}

TEST(Polygon, NormalIsTwiceTheAreaAlongTheCounterClockwiseSide) {
  const std::vector<Vec3> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const Vec3 n = polygon_normal(square);
  EXPECT_FLOAT_EQ(n.x, 0.f);
  EXPECT_FLOAT_EQ(n.y, 0.f);
  EXPECT_FLOAT_EQ(n.z, 8.f);
  const std::vector<Vec3> cw(square.rbegin(), square.rend());
  EXPECT_FLOAT_EQ(polygon_normal(cw).z, -8.f);
  // Far from the origin and in another plane.
  const std::vector<Vec3> far{{1000, 5, 1000}, {1000, 5, 1003}, {1004, 5, 1003}, {1004, 5, 1000}};
  const Vec3 nf = polygon_normal(far);
  EXPECT_FLOAT_EQ(nf.y, 24.f);
  EXPECT_FLOAT_EQ(nf.x, 0.f);
  EXPECT_FLOAT_EQ(nf.z, 0.f);
  EXPECT_EQ(polygon_normal(std::vector<Vec3>{{1, 2, 3}, {4, 5, 6}}), Vec3(0.f));
}

// ---------------------------------------------------------------------------------------------
// Non-convex

TEST(Polygon, LShape) { expect_valid_everywhere(l_shape(), 4); }

TEST(Polygon, UShape) { expect_valid_everywhere(u_shape(), 6); }

TEST(Polygon, StarWithFiveReflexVertices) { expect_valid_everywhere(star(), 8); }

TEST(Polygon, EShape) { expect_valid_everywhere(e_shape(), 10); }

TEST(Polygon, Comb) {
  for (int teeth : {2, 5, 40}) {
    SCOPED_TRACE(teeth);
    const Shape s = comb(teeth);
    expect_valid_everywhere(s, s.size() - 2);
  }
}

TEST(Polygon, Spiral) {
  const Shape s = spiral(14);
  expect_valid_everywhere(s, s.size() - 2);
}

// Random star-shaped polygons (sorted angles, random radii): heavily non-convex, all simple.
TEST(Polygon, RandomStarShaped) {
  Pcg32 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 3 + rng.next_u32() % 40;
    Shape s;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = 2.0 * std::numbers::pi * (double(i) + 0.8 * rng.next_float()) / double(n);
      const double r = 0.1 + 2.0 * rng.next_float();
      s.push_back({r * std::cos(a), r * std::sin(a)});
    }
    SCOPED_TRACE(testing::Message() << "trial " << trial << ", " << n << " vertices");
    expect_valid(s, triangulate_polygon(flat(s)), n - 2);
    expect_valid(reversed(s), triangulate_polygon(flat(reversed(s))), n - 2);
  }
}

// ---------------------------------------------------------------------------------------------
// Collinear and repeated vertices

TEST(Polygon, CollinearVerticesStayInProperTriangles) {
  // Square with extra vertices along its edges, and a triangle with midpoints on every edge.
  const Shape square{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}, {1.5, 3}, {0, 3}, {0, 1.5}};
  expect_valid_everywhere(square, square.size() - 2);
  const Shape midpoints{{0, 0}, {2, 0}, {4, 0}, {3, 2}, {2, 4}, {1, 2}};
  expect_valid_everywhere(midpoints, 4);
  // An L whose long side is split, so the inner corner is collinear with several vertices.
  const Shape l{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {1, 3}, {0, 3}, {0, 2}, {0, 1}};
  expect_valid_everywhere(l, l.size() - 2);
}

TEST(Polygon, RepeatedVerticesAreSkipped) {
  // Repeats next to each other and across the wrap-around.
  const Shape s{{0, 0}, {0, 0}, {2, 0}, {2, 1}, {2, 1}, {2, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 0}};
  for (const Shape& w : {s, reversed(s)}) {
    const Tris t = triangulate_polygon(flat(w));
    expect_valid(w, t, 4);  // the distinct L shape
    for (const auto& tri : t) {
      const P2 a = w[tri[0]], b = w[tri[1]], c = w[tri[2]];
      EXPECT_NE(orient2(a, b, c), 0.0);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Degenerate and invalid input

TEST(Polygon, DegenerateGivesNothing) {
  EXPECT_TRUE(triangulate_polygon({}).empty());
  EXPECT_TRUE(triangulate_polygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}}).empty());
  EXPECT_TRUE(triangulate_polygon(std::vector<Vec3>{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}).empty());
  EXPECT_TRUE(triangulate_polygon(std::vector<Vec3>{{0, 0, 0}, {1, 2, 3}, {0, 0, 0}, {1, 2, 3}}).empty());
  // All collinear, in 3D, going back and forth.
  std::vector<Vec3> line;
  for (int t : {0, 1, 2, 5, 3, -1}) line.push_back(Vec3{1, 2, 3} + Vec3{1, 1, 2} * float(t));
  EXPECT_TRUE(triangulate_polygon(line).empty());
  EXPECT_TRUE(triangulate_polygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).empty());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(triangulate_polygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {nan, 1, 0}, {0, 1, 0}}).empty());
}

void expect_indices_valid(const std::vector<Vec3>& v, const Tris& t) {
  EXPECT_LE(t.size(), v.size() - 2);
  for (const auto& tri : t) {
    for (const std::uint32_t i : tri) EXPECT_LT(i, v.size());
    EXPECT_NE(tri[0], tri[1]);
    EXPECT_NE(tri[1], tri[2]);
    EXPECT_NE(tri[0], tri[2]);
  }
}

TEST(Polygon, SelfIntersectingTerminatesWithValidIndices) {
  // Symmetric bow-tie: zero net area.
  const std::vector<Vec3> bowtie{{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}};
  expect_indices_valid(bowtie, triangulate_polygon(bowtie));
  // Lopsided bow-tie: non-zero net area, so the clipper runs.
  const std::vector<Vec3> lopsided{{0, 0, 0}, {3, 3, 0}, {3, 0, 0}, {0, 1, 0}};
  expect_indices_valid(lopsided, triangulate_polygon(lopsided));
  // Pentagram {5/2}, a comb folded over itself, and random point soups in a tilted plane.
  std::vector<Vec3> pentagram;
  for (int i = 0; i < 5; ++i) {
    const float a = 2.f * std::numbers::pi_v<float> * float(2 * i) / 5.f;
    pentagram.push_back({std::cos(a), std::sin(a), 0.f});
  }
  const Tris tp = triangulate_polygon(pentagram);
  expect_indices_valid(pentagram, tp);
  EXPECT_EQ(tp.size(), 3u);
  Pcg32 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 3 + rng.next_u32() % 30;
    Shape s;
    for (std::size_t i = 0; i < n; ++i) s.push_back({double(rng.next_u32() % 5), double(rng.next_u32() % 5)});
    const std::vector<Vec3> v = tilted(s, {0.2f, 0.9f, 0.1f}, {1.f, 1.f, 1.f});
    expect_indices_valid(v, triangulate_polygon(v));
    expect_indices_valid(flat(s), triangulate_polygon(flat(s)));
  }
}

// The grid of corners (detail::kPointGridFrom corners and more) is an index, not a rule: every
// polygon must come out as the scan over all remaining corners gives it, triangle for triangle.
void expect_grid_changes_nothing(const std::vector<Vec3>& v) {
  EXPECT_EQ(detail::triangulate_polygon(v, 3), detail::triangulate_polygon(v, SIZE_MAX));
}

// A gear's outline like SPD's gears.nff: teeth of four corners around a rim, here with a wobble
// so that no two teeth are alike.
Shape gear(int teeth, double wobble, Pcg32& rng) {
  Shape s;
  for (int i = 0; i < teeth; ++i) {
    for (int c = 0; c < 4; ++c) {
      const double a = 2.0 * std::numbers::pi * (i + c / 4.0 + wobble * 0.2 * rng.next_float()) / teeth;
      const double r = (c == 1 || c == 2 ? 1.2 : 1.0) + wobble * 0.05 * rng.next_float();
      s.push_back({r * std::cos(a), r * std::sin(a)});
    }
  }
  return s;
}

TEST(Polygon, GridOfCornersGivesTheTrianglesOfTheFullScan) {
  Pcg32 rng(23);
  std::vector<Shape> shapes{comb(2), comb(40), spiral(14), spiral(30), e_shape(), star(), regular(100, 2.0)};
  for (int i = 0; i < 20; ++i) shapes.push_back(gear(8 + i * 3, i % 2, rng));
  for (int trial = 0; trial < 100; ++trial) {  // star-shaped, as in RandomStarShaped, larger
    const std::size_t n = 3 + rng.next_u32() % 120;
    Shape s;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = 2.0 * std::numbers::pi * (double(i) + 0.8 * rng.next_float()) / double(n);
      s.push_back({(0.1 + 2.0 * rng.next_float()) * std::cos(a), (0.1 + 2.0 * rng.next_float()) * std::sin(a)});
    }
    shapes.push_back(s);
  }
  for (int trial = 0; trial < 100; ++trial) {       // point soups on a small lattice: self-intersecting,
    const std::size_t n = 3 + rng.next_u32() % 60;  // collinear and repeated corners everywhere
    Shape s;
    for (std::size_t i = 0; i < n; ++i) s.push_back({double(rng.next_u32() % 6), double(rng.next_u32() % 6)});
    shapes.push_back(s);
  }
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "shape " << i << ", " << shapes[i].size() << " corners");
    for (const Shape& s : {shapes[i], reversed(shapes[i])}) {
      expect_grid_changes_nothing(flat(s));
      expect_grid_changes_nothing(tilted(s, {0.3f, 0.2f, 1.f}, {3.f, -2.f, 7.f}));
    }
  }
  // And the grid's answers are valid triangulations (not merely the scan's mistakes repeated).
  for (int i = 0; i < 5; ++i) {
    const Shape s = gear(36, i % 2, rng);
    expect_valid(s, detail::triangulate_polygon(flat(s), 3), s.size() - 2);
  }
}

TEST(Polygon, LargeNonConvexPolygonIsFast) {
  // 800 vertices; O(n^3) behaviour would still pass but O(n^2) keeps this well under a second.
  const Shape s = comb(200);
  expect_valid(s, triangulate_polygon(flat(s)), s.size() - 2);
}

}  // namespace
}  // namespace raylab
