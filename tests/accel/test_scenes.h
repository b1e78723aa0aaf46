#pragma once
// Scenes and rays shared by the accelerator tests (bvh_vs_brute_test, bvh_tree_test, wide_bvh_test):
// overlap, slivers, sizes over eight orders of magnitude, dense soups, every shape kind, and closed
// meshes with axis-aligned (zero-thickness box) faces. All from fixed seeds.

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/geometry/geometry.h"

namespace raylab::test_scenes {

inline constexpr float kInf = std::numeric_limits<float>::infinity();

struct Sampler {
  Pcg32 rng;
  explicit Sampler(std::uint64_t seed) : rng(seed, 17) {}
  float uni(float lo, float hi) { return lo + (hi - lo) * rng.next_float(); }
  Vec3 in_box(Vec3 lo, Vec3 hi) { return lo + (hi - lo) * Vec3{rng.next_float(), rng.next_float(), rng.next_float()}; }
  Vec3 unit() {
    for (;;) {
      const Vec3 p = in_box(Vec3(-1.f), Vec3(1.f));
      const float l2 = dot(p, p);
      if (l2 > 1e-4f && l2 <= 1.f) return p / std::sqrt(l2);
    }
  }
  float log_uniform(float lo, float hi) { return lo * std::pow(hi / lo, rng.next_float()); }
};

inline Triangle random_triangle(Sampler& s, Vec3 center, float size) {
  return {center + s.unit() * size, center + s.unit() * size, center + s.unit() * size};
}

// ---------------------------------------------------------------------------------------------
// Scenes

inline Geometry spheres_and_triangles(Sampler& s) {
  Geometry g;
  for (int i = 0; i < 700; ++i) g.add(random_triangle(s, s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.3f, 3.f)), 0);
  for (int i = 0; i < 400; ++i) g.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.2f, 2.f)}, 1);
  return g;
}

inline Geometry slivers(Sampler& s) {
  Geometry g;
  for (int i = 0; i < 1200; ++i) {
    const Vec3 p0 = s.in_box(Vec3(-10.f), Vec3(10.f));
    const Vec3 along = s.unit() * s.uni(5.f, 20.f);
    Vec3 side = cross(along, s.unit());
    side = side / length(side) * s.uni(1e-4f, 1e-2f);
    g.add(Triangle{p0, p0 + along, p0 + along * s.uni(0.f, 1.f) + side}, 0);
  }
  return g;
}

inline Geometry sizes_over_eight_decades(Sampler& s) {
  Geometry g;
  for (int i = 0; i < 1200; ++i) {
    const Vec3 c = s.in_box(Vec3(-1e4f), Vec3(1e4f));
    const float size = s.log_uniform(1e-4f, 1e4f);
    if (i % 3 == 0) {
      g.add(Sphere{c, size}, 0);
    } else if (i % 3 == 1) {
      g.add(random_triangle(s, c, size), 0);
    } else {
      g.add(Quad{c, s.unit() * size, s.unit() * size}, 0);
    }
  }
  return g;
}

inline Geometry dense_soup(Sampler& s) {
  Geometry g;
  for (int i = 0; i < 1500; ++i) g.add(random_triangle(s, s.in_box(Vec3(0.f), Vec3(1.f)), s.uni(0.05f, 0.2f)), 0);
  return g;
}

inline Geometry every_shape_kind(Sampler& s) {
  Geometry g;
  auto p = [&] { return s.in_box(Vec3(-10.f), Vec3(10.f)); };
  for (int i = 0; i < 300; ++i) g.add(random_triangle(s, p(), s.uni(0.3f, 2.f)), 0);
  for (int i = 0; i < 200; ++i) g.add(Sphere{p(), s.uni(0.2f, 1.5f)}, 1);
  for (int i = 0; i < 250; ++i) {
    const Vec3 base = p();
    const float r = s.uni(0.1f, 1.f);
    g.add(Cylinder{base, r, base + s.unit() * s.uni(0.5f, 4.f), i % 2 ? r : s.uni(0.f, 1.f)}, 2);
  }
  for (int i = 0; i < 150; ++i) g.add(Disk{p(), s.unit(), s.uni(0.2f, 2.f)}, 3);
  for (int i = 0; i < 150; ++i) g.add(Quad{p(), s.unit() * s.uni(0.3f, 3.f), s.unit() * s.uni(0.3f, 3.f)}, 4);
  // A few axis-aligned ones, whose bounding boxes are flat.
  g.add(Quad{{-10.f, -10.5f, -10.f}, {20.f, 0.f, 0.f}, {0.f, 0.f, 20.f}}, 4);
  g.add(Disk{{0.f, 0.f, 10.5f}, {0.f, 0.f, 1.f}, 5.f}, 3);
  return g;
}

// A cube surface [c - h, c + h] split into n x n cells per face, two triangles per cell, rotated by
// `rot` (columns of an orthonormal matrix). Each lattice point is transformed once and reused, so
// faces meeting at an edge share vertices bit for bit (recomputing them could round differently
// where the compiler contracts to FMA in one copy of the code and not another).
inline void add_cube_mesh(Geometry& g, Vec3 c, float h, int n, const Vec3 rot[3], std::uint32_t object) {
  std::map<std::array<int, 3>, Vec3> lattice;
  auto vertex = [&](std::array<int, 3> idx) {
    auto [it, fresh] = lattice.try_emplace(idx);
    if (fresh) {
      Vec3 local;
      for (int k = 0; k < 3; ++k) local[k] = -h + 2.f * h * float(idx[k]) / float(n);
      it->second = c + rot[0] * local.x + rot[1] * local.y + rot[2] * local.z;
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {0, n})
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          auto vert = [&](int a, int b) {
            std::array<int, 3> idx;
            idx[axis] = side;
            idx[(axis + 1) % 3] = a;
            idx[(axis + 2) % 3] = b;
            return vertex(idx);
          };
          g.add(Triangle{vert(i, j), vert(i + 1, j), vert(i + 1, j + 1)}, object);
          g.add(Triangle{vert(i, j), vert(i + 1, j + 1), vert(i, j + 1)}, object);
        }
}

inline Geometry closed_meshes(Sampler&) {
  Geometry g;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(g, {0.f, 0.f, 0.f}, 2.f, 10, identity, 0);
  const Vec3 ex = normalize(Vec3{1.f, 0.4f, -0.3f});
  const Vec3 ey = normalize(cross(Vec3{0.1f, 0.2f, 1.f}, ex));
  const Vec3 rotated[3] = {ex, ey, cross(ex, ey)};
  add_cube_mesh(g, {7.f, 1.f, -1.f}, 1.5f, 8, rotated, 1);
  return g;
}

struct NamedScene {
  const char* name;
  Geometry (*make)(Sampler&);
  std::uint64_t seed;  ///< the seed bvh_vs_brute_test uses for it
};

/// The six scenes with their seeds, for tests that loop over all of them.
inline const std::array<NamedScene, 6> kScenes = {{{"OverlappingSpheresAndTriangles", spheres_and_triangles, 1},
                                                   {"Slivers", slivers, 2},
                                                   {"SizesFrom1em4To1e4", sizes_over_eight_decades, 3},
                                                   {"DenseTriangleSoup", dense_soup, 4},
                                                   {"EveryShapeKind", every_shape_kind, 5},
                                                   {"ClosedMeshes", closed_meshes, 6}}};

// ---------------------------------------------------------------------------------------------
// Rays

// A point on (or, for spheres, inside) primitive `id`: a ray aimed at it almost surely hits it.
inline Vec3 point_on(const Geometry& g, std::uint32_t id, Sampler& s) {
  const ShapeRef ref = g.resolve(id);
  if (ref.kind == ShapeKind::kTriangle) {
    const Triangle& t = g.triangles[ref.index];
    float a = s.rng.next_float(), b = s.rng.next_float();
    if (a + b > 1.f) a = 1.f - a, b = 1.f - b;
    return t.p0 + (t.p1 - t.p0) * a + (t.p2 - t.p0) * b;
  }
  if (ref.kind == ShapeKind::kSphere)
    return g.spheres[ref.index].center + s.unit() * (0.9f * g.spheres[ref.index].radius);
  const Box3 box = g.bounds(id);
  return s.in_box(box.lo, box.hi);
}

/// +0 or -0 at even odds.
inline float signed_zero(Sampler& s) { return s.rng.next_float() < 0.5f ? 0.f : -0.f; }

// Origins inside and outside the scene box; directions uniform, axis-parallel (with +0 and -0 in
// the other components), or aimed at a random primitive so that a good share of rays hit.
inline std::vector<Ray> random_rays(const Geometry& g, Sampler& s, int count) {
  const Box3 box = g.bounds();
  const Vec3 margin = box.extent();
  std::vector<Ray> rays(count);
  for (Ray& r : rays) {
    r.origin = s.rng.next_float() < 0.5f ? s.in_box(box.lo, box.hi) : s.in_box(box.lo - margin, box.hi + margin);
    const float kind = s.rng.next_float();
    if (kind < 0.15f) {
      Vec3 d{signed_zero(s), signed_zero(s), signed_zero(s)};
      d[static_cast<int>(s.rng.next_u32() % 3)] = s.rng.next_float() < 0.5f ? 1.f : -1.f;
      r.direction = d;
    } else if (kind < 0.5f) {
      r.direction = point_on(g, s.rng.next_u32() % g.size(), s) - r.origin;
    } else {
      r.direction = s.unit() * s.uni(0.5f, 2.f);
    }
    if (s.rng.next_float() < 0.1f) r.tmin = s.uni(0.f, 0.3f) * length(box.extent()) / length(r.direction);
  }
  return rays;
}

/// Rays at a structure's weak points around the lattice points `point_of()` returns (cell
/// corners): in a plane through the point and parallel to it (+0 or -0 across it), along a line
/// of two such planes, starting at the point, aimed through it, and starting in one of its planes
/// in any direction. Origins elsewhere are drawn from `box` grown by a fifth on every side.
template <class PointOf>
std::vector<Ray> rays_at_lattice_points(const Box3& box, Sampler& s, int count, PointOf point_of) {
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const Vec3 c = point_of();
    const int axis = static_cast<int>(s.rng.next_u32() % 3);
    Ray r;
    r.origin = s.in_box(box.lo - box.extent() * 0.2f, box.hi + box.extent() * 0.2f);
    r.direction = s.unit();
    switch (i % 5) {
      case 0:  // in a plane, parallel to it
        r.origin[axis] = c[axis];
        r.direction[axis] = signed_zero(s);
        break;
      case 1:  // along a line where two planes meet (a cell edge)
        r.origin[axis] = c[axis];
        r.origin[(axis + 1) % 3] = c[(axis + 1) % 3];
        r.direction = {signed_zero(s), signed_zero(s), signed_zero(s)};
        r.direction[(axis + 2) % 3] = s.rng.next_float() < 0.5f ? 1.f : -1.f;
        break;
      case 2:  // from the point
        r.origin = c;
        break;
      case 3:  // through the point
        r.direction = c - r.origin;
        break;
      default:  // from a point of a plane, in any direction
        r.origin[axis] = c[axis];
        break;
    }
    rays.push_back(r);
  }
  return rays;
}

/// Axis-parallel rays (+0 and -0 in the other components) from inside and around the box
/// [-1, 5]^3, every fourth starting in one of the planes 1 or 3: for the cube meshes centred at
/// (2, 2, 2) with half-edges 2 and 1, whose faces lie on cell planes.
inline std::vector<Ray> axis_rays_in_cube_faces(Sampler& s, int count) {
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    Ray r;
    r.origin = s.in_box(Vec3(-1.f), Vec3(5.f));
    r.direction = {signed_zero(s), signed_zero(s), signed_zero(s)};
    r.direction[i % 3] = s.rng.next_float() < 0.5f ? 1.f : -1.f;
    if (i % 4 == 0) r.origin[(i + 1) % 3] = 1.f + 2.f * float(s.rng.next_u32() % 2);  // in a face plane
    rays.push_back(r);
  }
  return rays;
}

}  // namespace raylab::test_scenes
