// Box3 basics and the ray-box slab test, including the IEEE corner cases (+-0 directions,
// origins on face planes) that the BVH relies on.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "raylab/core/box.h"
#include "raylab/core/rng.h"

namespace raylab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

const Box3 kUnit{{0.f, 0.f, 0.f}, {1.f, 1.f, 1.f}};

// Runs the slab test with a direction (not its reciprocal), as a caller would.
bool hits(const Box3& box, Vec3 o, Vec3 d, float tmin = 0.f, float tmax = kInf, float* t_out = nullptr) {
  float t = -1.f;
  const bool h = intersect_box(box, o, safe_reciprocal(d), tmin, tmax, t);
  if (t_out) *t_out = t;
  return h;
}

TEST(Box3, DefaultIsEmptyWithZeroArea) {
  const Box3 b;
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(b.area(), 0.f);
  EXPECT_FALSE(b.contains({0.f, 0.f, 0.f}));
}

TEST(Box3, ExtendFromEmpty) {
  Box3 b;
  b.extend(Vec3{1.f, 2.f, 3.f});
  // A single point is a valid (degenerate) box: not empty, zero area.
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.area(), 0.f);
  EXPECT_TRUE(b.contains({1.f, 2.f, 3.f}));
  b.extend(Vec3{-1.f, 4.f, 3.f});
  EXPECT_EQ(b.lo, (Vec3{-1.f, 2.f, 3.f}));
  EXPECT_EQ(b.hi, (Vec3{1.f, 4.f, 3.f}));
  EXPECT_EQ(b.area(), 2.f * (2.f * 2.f));  // a flat 2 x 2 rectangle: both faces count
  EXPECT_EQ(b.center(), (Vec3{0.f, 3.f, 3.f}));
  EXPECT_EQ(b.extent(), (Vec3{2.f, 2.f, 0.f}));
}

TEST(Box3, AreaOfCuboid) {
  const Box3 b{{0.f, 0.f, 0.f}, {1.f, 2.f, 3.f}};
  EXPECT_EQ(b.area(), 2.f * (1.f * 2.f + 2.f * 3.f + 3.f * 1.f));
}

TEST(Box3, ExtendByBoxAndMerge) {
  Box3 a{{0.f, 0.f, 0.f}, {1.f, 1.f, 1.f}};
  const Box3 b{{-1.f, 0.5f, 0.5f}, {0.5f, 3.f, 0.75f}};
  const Box3 m = merge(a, b);
  a.extend(b);
  EXPECT_EQ(a.lo, m.lo);
  EXPECT_EQ(a.hi, m.hi);
  EXPECT_EQ(m.lo, (Vec3{-1.f, 0.f, 0.f}));
  EXPECT_EQ(m.hi, (Vec3{1.f, 3.f, 1.f}));
  // Merging with an empty box changes nothing.
  const Box3 e = merge(m, Box3{});
  EXPECT_EQ(e.lo, m.lo);
  EXPECT_EQ(e.hi, m.hi);
}

TEST(Box3, ContainsIsClosed) {
  EXPECT_TRUE(kUnit.contains({0.f, 0.f, 0.f}));
  EXPECT_TRUE(kUnit.contains({1.f, 1.f, 1.f}));
  EXPECT_TRUE(kUnit.contains({0.5f, 1.f, 0.f}));
  EXPECT_FALSE(kUnit.contains({0.5f, 1.0001f, 0.f}));
}

TEST(IntersectBox, AxisParallelDirections) {
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {1.f, -1.f}) {
      Vec3 o{0.5f, 0.5f, 0.5f};
      o[axis] = sign > 0.f ? -2.f : 3.f;
      Vec3 d{0.f, 0.f, 0.f};
      d[axis] = sign;
      float t = 0.f;
      ASSERT_TRUE(hits(kUnit, o, d, 0.f, kInf, &t)) << "axis " << axis << " sign " << sign;
      EXPECT_EQ(t, 2.f);
      // Shifted outside the box on another axis: miss.
      Vec3 off = o;
      off[(axis + 1) % 3] = 1.5f;
      EXPECT_FALSE(hits(kUnit, off, d));
    }
  }
}

TEST(IntersectBox, SignedZeroComponents) {
  // 1/+0 = +inf and 1/-0 = -inf: both must behave as "parallel to that slab".
  for (float zy : {0.f, -0.f}) {
    for (float zz : {0.f, -0.f}) {
      const Vec3 d{1.f, zy, zz};
      float t = 0.f;
      EXPECT_TRUE(hits(kUnit, {-1.f, 0.5f, 0.5f}, d, 0.f, kInf, &t));
      EXPECT_EQ(t, 1.f);
      // Outside the y slab on either side: the parallel slab rejects for both zero signs.
      EXPECT_FALSE(hits(kUnit, {-1.f, 1.5f, 0.5f}, d));
      EXPECT_FALSE(hits(kUnit, {-1.f, -0.5f, 0.5f}, d));
      EXPECT_FALSE(hits(kUnit, {-1.f, 0.5f, 2.f}, d));
      EXPECT_FALSE(hits(kUnit, {-1.f, 0.5f, -2.f}, d));
    }
  }
}

TEST(IntersectBox, OriginOnFacePlaneParallelDirectionHits) {
  // (plane - origin) * inf = 0 * inf = NaN; the boxes are closed, so this is a hit as long as
  // the ray is inside the other slabs.
  for (float zy : {0.f, -0.f}) {
    for (float face : {0.f, 1.f}) {
      const Vec3 d{1.f, zy, 0.f};
      float t = 0.f;
      EXPECT_TRUE(hits(kUnit, {-1.f, face, 0.5f}, d, 0.f, kInf, &t)) << "face y=" << face;
      EXPECT_EQ(t, 1.f);
      // Along an edge (on two face planes at once).
      EXPECT_TRUE(hits(kUnit, {-1.f, face, face}, Vec3{1.f, zy, -0.f}, 0.f, kInf, &t));
      EXPECT_EQ(t, 1.f);
      // On the face plane but outside another slab: miss.
      EXPECT_FALSE(hits(kUnit, {-1.f, face, 1.5f}, d));
    }
  }
  // On a face plane, moving along the face (from inside the box).
  float t = -1.f;
  EXPECT_TRUE(hits(kUnit, {0.5f, 0.f, 0.5f}, {0.f, 0.f, 1.f}, 0.f, kInf, &t));
  EXPECT_EQ(t, 0.f);
}

TEST(IntersectBox, OriginInsideEntersAtTmin) {
  float t = -1.f;
  EXPECT_TRUE(hits(kUnit, {0.25f, 0.5f, 0.75f}, {0.3f, -0.4f, 0.5f}, 0.f, kInf, &t));
  EXPECT_EQ(t, 0.f);
  EXPECT_TRUE(hits(kUnit, {0.25f, 0.5f, 0.75f}, {0.3f, -0.4f, 0.5f}, 0.125f, kInf, &t));
  EXPECT_EQ(t, 0.125f);
}

TEST(IntersectBox, BoxBehindRayMisses) {
  EXPECT_FALSE(hits(kUnit, {2.f, 0.5f, 0.5f}, {1.f, 0.f, 0.f}));
  EXPECT_FALSE(hits(kUnit, {2.f, 2.f, 2.f}, {1.f, 1.f, 1.f}));
  EXPECT_FALSE(hits(kUnit, {-1.f, -1.f, -1.f}, {-1.f, -0.5f, -0.25f}));
  // ... but the same lines point the other way hit.
  EXPECT_TRUE(hits(kUnit, {2.f, 0.5f, 0.5f}, {-1.f, 0.f, 0.f}));
  EXPECT_TRUE(hits(kUnit, {2.f, 2.f, 2.f}, {-1.f, -1.f, -1.f}));
}

TEST(IntersectBox, TminTmaxClipping) {
  // The ray spends t in [1, 2] inside the box.
  const Vec3 o{-1.f, 0.5f, 0.5f}, d{1.f, 0.f, 0.f};
  float t = 0.f;
  EXPECT_FALSE(hits(kUnit, o, d, 0.f, 0.5f));
  EXPECT_TRUE(hits(kUnit, o, d, 0.f, 1.f, &t));  // closed interval: touching counts
  EXPECT_EQ(t, 1.f);
  EXPECT_TRUE(hits(kUnit, o, d, 1.5f, kInf, &t));
  EXPECT_EQ(t, 1.5f);
  EXPECT_TRUE(hits(kUnit, o, d, 2.f, kInf, &t));
  EXPECT_FALSE(hits(kUnit, o, d, 2.5f, kInf));
  EXPECT_FALSE(hits(kUnit, o, d, 1.25f, 1.125f));  // empty query interval
}

TEST(IntersectBox, DiagonalAndFlatBoxes) {
  float t = 0.f;
  EXPECT_TRUE(hits(kUnit, {-1.f, -1.f, -1.f}, {1.f, 1.f, 1.f}, 0.f, kInf, &t));
  EXPECT_EQ(t, 1.f);
  // A zero-thickness box (a rectangle) is still hit by a ray crossing it.
  const Box3 flat{{0.f, 0.f, 0.5f}, {1.f, 1.f, 0.5f}};
  EXPECT_TRUE(hits(flat, {0.5f, 0.5f, 2.f}, {0.1f, 0.f, -1.f}, 0.f, kInf, &t));
  EXPECT_FLOAT_EQ(t, 1.5f);
  EXPECT_FALSE(hits(flat, {0.5f, 0.5f, 2.f}, {0.1f, 0.f, 1.f}));
}

// Property test against a simple reference: a ray aimed at a point inside the box must hit it no
// later than that point, and whenever the test reports a hit the entry point lies on the box.
TEST(IntersectBox, RandomRaysAgreeWithGeometry) {
  Pcg32 rng(7, 1);
  auto uni = [&](float lo, float hi) { return lo + (hi - lo) * rng.next_float(); };
  for (int i = 0; i < 20000; ++i) {
    Box3 box;
    box.extend(Vec3{uni(-5.f, 5.f), uni(-5.f, 5.f), uni(-5.f, 5.f)});
    box.extend(Vec3{uni(-5.f, 5.f), uni(-5.f, 5.f), uni(-5.f, 5.f)});
    const Vec3 o{uni(-10.f, 10.f), uni(-10.f, 10.f), uni(-10.f, 10.f)};
    const Vec3 target = box.lo + box.extent() * Vec3{rng.next_float(), rng.next_float(), rng.next_float()};
    const Vec3 d = target - o;
    float t = -1.f;
    ASSERT_TRUE(hits(box, o, d, 0.f, kInf, &t)) << "ray aimed into the box missed it";
    EXPECT_LE(t, 1.f + 1e-5f);
    const Vec3 p = o + d * t;
    const float eps = 1e-4f * (1.f + max_component(abs(o)) + max_component(abs(d)));
    EXPECT_TRUE(p.x >= box.lo.x - eps && p.x <= box.hi.x + eps && p.y >= box.lo.y - eps && p.y <= box.hi.y + eps &&
                p.z >= box.lo.z - eps && p.z <= box.hi.z + eps);
    // The reversed ray from the same origin hits only when the origin is inside.
    if (!box.contains(o)) {
      EXPECT_FALSE(hits(box, o, -d)) << "the box is on one side of an outside origin";
    }
  }
}

}  // namespace
}  // namespace raylab
