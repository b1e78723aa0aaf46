#include "raylab/io/ply_writer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>

#include "raylab/core/error.h"

namespace raylab {
namespace {

// Writes `value` little-endian at `out` and returns the position after it.
template <class T>
char* put(char* out, T value) {
  auto raw = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if constexpr (std::endian::native == std::endian::big) std::reverse(raw.begin(), raw.end());
  std::memcpy(out, raw.data(), sizeof(T));
  return out + sizeof(T);
}

char* put(char* out, Vec3 v) { return put(put(put(out, v.x), v.y), v.z); }
char* put(char* out, Vec2 v) { return put(put(out, v.x), v.y); }

void check_triangles_only(const Geometry& g) {
  if (g.spheres.empty() && g.cylinders.empty() && g.disks.empty() && g.quads.empty()) return;
  throw UsageError("PLY output holds triangles only, but the geometry also has " + std::to_string(g.spheres.size()) +
                   " spheres, " + std::to_string(g.cylinders.size()) + " cylinders, " + std::to_string(g.disks.size()) +
                   " disks and " + std::to_string(g.quads.size()) + " quads (tessellate them first)");
}

std::string header(std::size_t triangles, bool normals, bool uvs) {
  std::string h = "ply\nformat binary_little_endian 1.0\ncomment written by raylab\n";
  h += "element vertex " + std::to_string(3 * triangles) + "\n";
  h += "property float x\nproperty float y\nproperty float z\n";
  if (normals) h += "property float nx\nproperty float ny\nproperty float nz\n";
  if (uvs) h += "property float u\nproperty float v\n";
  h += "element face " + std::to_string(triangles) + "\n";
  h += "property list uchar int vertex_indices\nend_header\n";
  return h;
}

}  // namespace

std::string encode_ply(const Geometry& geometry) {
  check_triangles_only(geometry);
  const std::size_t n = geometry.triangles.size();
  if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()) / 3) {
    throw UsageError("PLY output: " + std::to_string(n) + " triangles are more than int indices can number");
  }
  const bool normals = !geometry.triangle_normals.empty();
  const bool uvs = !geometry.triangle_uvs.empty();
  if ((normals && geometry.triangle_normals.size() != n) || (uvs && geometry.triangle_uvs.size() != n)) {
    throw UsageError("PLY output: the geometry's normal or uv array is not parallel to its triangles");
  }
  const std::string head = header(n, normals, uvs);
  const std::size_t vertex_bytes = sizeof(float) * (3 + (normals ? 3 : 0) + (uvs ? 2 : 0));
  const std::size_t face_bytes = 1 + 3 * sizeof(std::int32_t);
  std::string out(head.size() + n * (3 * vertex_bytes + face_bytes), '\0');
  std::memcpy(out.data(), head.data(), head.size());
  char* p = out.data() + head.size();
  for (std::size_t t = 0; t < n; ++t) {
    const Triangle& tri = geometry.triangles[t];
    const std::array<Vec3, 3> corners{tri.p0, tri.p1, tri.p2};
    for (int k = 0; k < 3; ++k) {
      p = put(p, corners[k]);
      if (normals) p = put(p, geometry.triangle_normals[t][k]);
      if (uvs) p = put(p, geometry.triangle_uvs[t][k]);
    }
  }
  for (std::size_t t = 0; t < n; ++t) {
    *p++ = 3;
    for (int k = 0; k < 3; ++k) p = put(p, static_cast<std::int32_t>(3 * t + k));
  }
  return out;
}

}  // namespace raylab
