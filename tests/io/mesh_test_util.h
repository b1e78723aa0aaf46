#pragma once
// Shared by the mesh loader tests: points and triangles read back exactly as the text wrote them,
// and the small hand-written mesh that several formats spell out.

#include <gtest/gtest.h>

#include <cstdint>

#include "raylab/core/vec3.h"
#include "raylab/geometry/geometry.h"
#include "raylab/geometry/triangle.h"
#include "raylab/scene/mesh_builder.h"

namespace raylab::test {

/// Expects `got` to equal `want` exactly, coordinate by coordinate (a failure names the axis).
inline void expect_vec(Vec3 got, Vec3 want) {
  EXPECT_EQ(got.x, want.x);
  EXPECT_EQ(got.y, want.y);
  EXPECT_EQ(got.z, want.z);
}

/// Expects the corners of `t` to be `p0`, `p1` and `p2` exactly, in that order.
inline void expect_triangle(const Triangle& t, Vec3 p0, Vec3 p1, Vec3 p2) {
  expect_vec(t.p0, p0);
  expect_vec(t.p1, p1);
  expect_vec(t.p2, p2);
}

/// Expects what the loader tests' hand-written mesh reads as: four vertices (0 0 0) (1 0 0)
/// (1 1 0.5) (0 1 0.5), the triangle (0 1 2) and the convex quad (0 1 2 3) as its fan (0 1 2)
/// (0 2 3), all of object `object`, with no normals and no texture coordinates.
inline void expect_triangle_and_quad(const MeshLoadReport& r, const Geometry& g, std::uint32_t object) {
  EXPECT_EQ(r.vertices, 4u);
  EXPECT_EQ(r.triangles, 3u);
  EXPECT_EQ(r.degenerate_dropped, 0u);
  ASSERT_EQ(g.triangles.size(), 3u);
  const Vec3 v[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5f}, {0, 1, 0.5f}};
  expect_triangle(g.triangles[0], v[0], v[1], v[2]);
  expect_triangle(g.triangles[1], v[0], v[1], v[2]);
  expect_triangle(g.triangles[2], v[0], v[2], v[3]);
  for (std::uint32_t id : g.triangle_objects) EXPECT_EQ(id, object);
  EXPECT_TRUE(g.triangle_normals.empty());
  EXPECT_TRUE(g.triangle_uvs.empty());
}

}  // namespace raylab::test
