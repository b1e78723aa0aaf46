#include "raylab/scene/mesh_builder.h"

#include <vector>

#include "raylab/geometry/polygon.h"

namespace raylab {

bool add_triangle(Geometry& geometry, const Triangle& triangle, const std::array<Vec3, 3>* normals,
                  const std::array<Vec2, 3>* uvs, std::uint32_t object, MeshLoadReport& report) {
  const Vec3 n = triangle_normal(triangle);
  if (!(dot(n, n) > 0.f)) {
    ++report.degenerate_dropped;
    return false;
  }
  geometry.add(triangle, normals, uvs, object);
  ++report.triangles;
  return true;
}

void add_polygon(Geometry& geometry, std::span<const Vec3> corners, std::span<const Vec3> normals,
                 std::span<const Vec2> uvs, std::uint32_t object, MeshLoadReport& report) {
  if (corners.size() < 3) {
    ++report.degenerate_dropped;
    return;
  }
  const bool has_normals = normals.size() == corners.size();
  const bool has_uvs = uvs.size() == corners.size();
  auto add_corners = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const Triangle tri{corners[a], corners[b], corners[c]};
    const std::array<Vec3, 3> n =
        has_normals ? std::array<Vec3, 3>{normals[a], normals[b], normals[c]} : std::array<Vec3, 3>{};
    const std::array<Vec2, 3> t = has_uvs ? std::array<Vec2, 3>{uvs[a], uvs[b], uvs[c]} : std::array<Vec2, 3>{};
    add_triangle(geometry, tri, has_normals ? &n : nullptr, has_uvs ? &t : nullptr, object, report);
  };
  if (corners.size() == 3) {
    add_corners(0, 1, 2);
    return;
  }
  // Ear clipping rather than a fan: a fan is wrong for non-convex faces (SPD's gears, exporters'
  // n-gons). Triangles the triangulation leaves out count as dropped, as the n - 2 fan
  // triangles over repeated or collinear corners would have been.
  const std::vector<std::array<std::uint32_t, 3>> triangles = triangulate_polygon(corners);
  report.degenerate_dropped += corners.size() - 2 - triangles.size();
  for (const auto& t : triangles) add_corners(t[0], t[1], t[2]);
}

}  // namespace raylab
