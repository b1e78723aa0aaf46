#include "raylab/scene/mesh_generators.h"

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace raylab {

void add_torus(Geometry& g, std::uint32_t object, Vec3 center, float major, float minor, int rings, int sides) {
  const float two_pi = 2.f * std::numbers::pi_v<float>;
  auto vertex = [&](int i, int j, Vec3& p, Vec3& n) {
    const float a = two_pi * static_cast<float>(i % rings) / static_cast<float>(rings);
    const float b = two_pi * static_cast<float>(j % sides) / static_cast<float>(sides);
    const Vec3 ring_dir{std::cos(a), 0.f, std::sin(a)};
    n = ring_dir * std::cos(b) + Vec3{0.f, std::sin(b), 0.f};
    p = center + ring_dir * major + n * minor;
  };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < sides; ++j) {
      Vec3 p00, p10, p01, p11, n00, n10, n01, n11;
      vertex(i, j, p00, n00);
      vertex(i + 1, j, p10, n10);
      vertex(i, j + 1, p01, n01);
      vertex(i + 1, j + 1, p11, n11);
      // Indices wrap with `% rings` / `% sides`, so shared vertices are bit-identical: closed mesh.
      g.add(Triangle{p00, p01, p11}, {n00, n01, n11}, object);
      g.add(Triangle{p00, p11, p10}, {n00, n11, n10}, object);
    }
  }
}

void add_icosphere(Geometry& g, std::uint32_t object, Vec3 center, float radius, int level) {
  const float t = (1.f + std::sqrt(5.f)) / 2.f;
  std::vector<Vec3> verts = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                             {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& v : verts) v = normalize(v);
  std::vector<std::array<int, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                           {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                           {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                           {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    // Midpoints are shared through the edge map, so neighbouring faces share exact vertices.
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      verts.push_back(normalize(verts[a] + verts[b]));
      const int idx = static_cast<int>(verts.size() - 1);
      midpoint.emplace(key, idx);
      return idx;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(faces.size() * 4);
    for (const auto& f : faces) {
      const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      next.push_back({f[0], ab, ca});
      next.push_back({f[1], bc, ab});
      next.push_back({f[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    faces = std::move(next);
  }
  for (const auto& f : faces) {
    g.add(Triangle{center + verts[f[0]] * radius, center + verts[f[1]] * radius, center + verts[f[2]] * radius},
          {verts[f[0]], verts[f[1]], verts[f[2]]}, object);
  }
}

}  // namespace raylab
