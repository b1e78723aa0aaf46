// Up-axis detection: a flat base at one end of the bounds makes its axis up; a mesh without one
// gets no answer (the caller keeps +Y); a box, flat all round, keeps the preferred +Y.

#include <gtest/gtest.h>

#include "raylab/scene/up_axis.h"

namespace raylab {
namespace {

void add_quad(Scene& s, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  s.geometry.triangles.push_back({a, b, c});
  s.geometry.triangles.push_back({a, c, d});
}

// A square pyramid on a 2 x 2 base at the low end of `axis` (0, 1, 2), apex 2 along it;
// `flip` puts the base at the high end.
Scene pyramid(int axis, bool flip) {
  const auto at = [&](float u, float v, float w) {
    Vec3 p;
    p[axis] = flip ? -w : w;
    p[(axis + 1) % 3] = u;
    p[(axis + 2) % 3] = v;
    return p;
  };
  Scene s;
  add_quad(s, at(-1, -1, 0), at(1, -1, 0), at(1, 1, 0), at(-1, 1, 0));
  const Vec3 apex = at(0, 0, 2);
  const Vec3 corners[] = {at(-1, -1, 0), at(1, -1, 0), at(1, 1, 0), at(-1, 1, 0)};
  for (int i = 0; i < 4; ++i) s.geometry.triangles.push_back({corners[i], corners[(i + 1) % 4], apex});
  return s;
}

TEST(UpAxis, AFlatBaseMakesItsAxisUp) {
  for (int axis = 0; axis < 3; ++axis) {
    for (const bool flip : {false, true}) {
      SCOPED_TRACE(std::to_string(axis) + (flip ? " flipped" : ""));
      Vec3 expected;
      expected[axis] = flip ? -1.f : 1.f;
      const std::optional<Vec3> up = detect_up_axis(pyramid(axis, flip));
      ASSERT_TRUE(up.has_value());
      EXPECT_EQ(*up, expected);
    }
  }
}

TEST(UpAxis, ABaseFillingItsSectionCountsOne) {
  const std::array<float, 6> f = flat_base_fractions(pyramid(2, false));
  EXPECT_NEAR(f[1], 1.f, 1e-6f);  // +Z
  for (const int i : {0, 2, 3, 4, 5}) EXPECT_EQ(f[i], 0.f) << i;
}

TEST(UpAxis, ABoxKeepsY) {
  Scene box;
  const Vec3 lo{0.f, 0.f, 0.f}, hi{3.f, 1.f, 2.f};
  for (int axis = 0; axis < 3; ++axis) {
    for (const float w : {lo[axis], hi[axis]}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vec3 a, b, c, d;
      a[axis] = b[axis] = c[axis] = d[axis] = w;
      a[u] = lo[u], a[v] = lo[v];
      b[u] = hi[u], b[v] = lo[v];
      c[u] = hi[u], c[v] = hi[v];
      d[u] = lo[u], d[v] = hi[v];
      add_quad(box, a, b, c, d);
    }
  }
  EXPECT_EQ(detect_up_axis(box), std::optional<Vec3>(Vec3{0.f, 1.f, 0.f}));
}

TEST(UpAxis, NoFlatBaseNoAnswer) {
  Scene tetra;
  const Vec3 a{1.f, 1.f, 1.f}, b{-1.f, -1.f, 1.f}, c{-1.f, 1.f, -1.f}, d{1.f, -1.f, -1.f};
  tetra.geometry.triangles = {{a, b, c}, {a, c, d}, {a, d, b}, {b, d, c}};
  EXPECT_FALSE(detect_up_axis(tetra).has_value());
  EXPECT_FALSE(detect_up_axis(Scene{}).has_value());
}

TEST(UpAxis, NamesReadBack) {
  for (const Vec3 axis : kUpAxes) EXPECT_EQ(parse_up_axis(up_axis_name(axis)), std::optional<Vec3>(axis));
  EXPECT_EQ(parse_up_axis("+Z"), std::optional<Vec3>(Vec3{0.f, 0.f, 1.f}));
  EXPECT_EQ(parse_up_axis("-X"), std::optional<Vec3>(Vec3{-1.f, 0.f, 0.f}));
  for (const char* bad : {"", "w", "zz", "--y", "1"}) EXPECT_FALSE(parse_up_axis(bad).has_value()) << bad;
}

}  // namespace
}  // namespace raylab
