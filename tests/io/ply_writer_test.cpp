// encode_ply: the exact bytes of a small file, and round trips through parse_ply that give back
// every triangle, normal and uv bit for bit.

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstring>
#include <string>

#include "../test_util.h"
#include "raylab/core/error.h"
#include "raylab/core/rng.h"
#include "raylab/io/ply_loader.h"
#include "raylab/io/ply_writer.h"

namespace raylab {
namespace {

// A float with random sign, exponent and mantissa bits (finite, and not so small that a
// triangle of three of them risks a zero area from underflow).
float random_float(Pcg32& rng) {
  for (;;) {
    const float f = std::bit_cast<float>(rng.next_u32());
    if (std::isfinite(f) && std::fabs(f) > 1e-10f && std::fabs(f) < 1e10f) return f;
  }
}

Vec3 random_vec(Pcg32& rng) { return {random_float(rng), random_float(rng), random_float(rng)}; }

// A geometry of `n` random triangles, with normals and uvs as asked.
Geometry random_mesh(std::size_t n, bool normals, bool uvs, std::uint64_t seed) {
  Pcg32 rng(seed);
  Geometry g;
  while (g.triangles.size() < n) {
    const Triangle t{random_vec(rng), random_vec(rng), random_vec(rng)};
    const Vec3 normal = triangle_normal(t);
    if (!(dot(normal, normal) > 0.f) || !is_finite(normal)) continue;  // the loader would drop it
    const std::array<Vec3, 3> nrm{random_vec(rng), random_vec(rng), Vec3{}};
    const std::array<Vec2, 3> uv{Vec2{random_float(rng), random_float(rng)}, Vec2{rng.next_float(), -0.f},
                                 Vec2{1.f, rng.next_float()}};
    g.add(t, normals ? &nrm : nullptr, uvs ? &uv : nullptr, 0);
  }
  return g;
}

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool same_bits(Vec3 a, Vec3 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }
bool same_bits(Vec2 a, Vec2 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y); }

void expect_round_trip(const Geometry& g) {
  const std::string bytes = encode_ply(g);
  Geometry back;
  const MeshLoadReport r = parse_ply(bytes, "round-trip.ply", back, 5);
  EXPECT_EQ(r.triangles, g.triangles.size());
  EXPECT_EQ(r.vertices, 3 * g.triangles.size());
  EXPECT_EQ(r.degenerate_dropped, 0u);
  ASSERT_EQ(back.triangles.size(), g.triangles.size());
  ASSERT_EQ(back.triangle_normals.size(), g.triangle_normals.size());
  ASSERT_EQ(back.triangle_uvs.size(), g.triangle_uvs.size());
  for (std::size_t t = 0; t < g.triangles.size(); ++t) {
    ASSERT_TRUE(same_bits(back.triangles[t].p0, g.triangles[t].p0)) << t;
    ASSERT_TRUE(same_bits(back.triangles[t].p1, g.triangles[t].p1)) << t;
    ASSERT_TRUE(same_bits(back.triangles[t].p2, g.triangles[t].p2)) << t;
    ASSERT_EQ(back.triangle_objects[t], 5u);
    for (int k = 0; k < 3; ++k) {
      if (!g.triangle_normals.empty()) {
        ASSERT_TRUE(same_bits(back.triangle_normals[t][k], g.triangle_normals[t][k])) << t;
      }
      if (!g.triangle_uvs.empty()) {
        ASSERT_TRUE(same_bits(back.triangle_uvs[t][k], g.triangle_uvs[t][k])) << t;
      }
    }
  }
}

TEST(PlyWriter, RoundTripIsBitExact) {
  for (const bool normals : {false, true}) {
    for (const bool uvs : {false, true}) {
      SCOPED_TRACE(std::string(normals ? "normals " : "") + (uvs ? "uvs" : ""));
      expect_round_trip(random_mesh(500, normals, uvs, 11 + 2 * normals + uvs));
    }
  }
}

TEST(PlyWriter, EmptyGeometryGivesAnEmptyMesh) {
  const std::string bytes = encode_ply(Geometry{});
  EXPECT_NE(bytes.find("element vertex 0\n"), std::string::npos);
  EXPECT_NE(bytes.find("element face 0\n"), std::string::npos);
  Geometry back;
  EXPECT_EQ(parse_ply(bytes, "empty.ply", back, 0).triangles, 0u);
  EXPECT_TRUE(back.triangles.empty());
}

TEST(PlyWriter, ExactBytesOfOneTriangle) {
  Geometry g;
  const std::array<Vec2, 3> uv{Vec2{0.f, 0.f}, Vec2{1.f, 0.f}, Vec2{0.f, -2.f}};
  g.add(Triangle{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, nullptr, &uv, 0);
  const std::string bytes = encode_ply(g);
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment written by raylab\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nproperty float u\nproperty float v\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  ASSERT_EQ(bytes.size(), header.size() + 3 * 20 + 13);
  const unsigned char* body = reinterpret_cast<const unsigned char*>(bytes.data() + header.size());
  // 1.0f is 00 00 80 3f little-endian; -2.0f is 00 00 00 c0.
  const unsigned char first_x[4] = {0x00, 0x00, 0x80, 0x3f};
  EXPECT_EQ(std::memcmp(body, first_x, 4), 0);
  const unsigned char third_v[4] = {0x00, 0x00, 0x00, 0xc0};
  EXPECT_EQ(std::memcmp(body + 2 * 20 + 16, third_v, 4), 0);
  const unsigned char face[13] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
  EXPECT_EQ(std::memcmp(body + 60, face, 13), 0);
}

TEST(PlyWriter, RefusesPrimitivesOtherThanTriangles) {
  Geometry g = random_mesh(3, false, false, 1);
  g.add(Sphere{}, 0);
  test::expect_contains_all(test::thrown_message<UsageError>([&] { encode_ply(g); }), {"1 spheres", "tessellate"});
}

}  // namespace
}  // namespace raylab
