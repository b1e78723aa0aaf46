#include "raylab/scene/tessellate.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace raylab {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Two unit vectors perpendicular to unit `n` and to each other.
void frame(Vec3 n, Vec3& t, Vec3& b) {
  t = std::abs(n.x) > 0.9f ? Vec3{0.f, 1.f, 0.f} : Vec3{1.f, 0.f, 0.f};
  t = normalize(cross(n, t));
  b = cross(n, t);
}

void add_smooth(Geometry& out, Vec3 a, Vec3 b, Vec3 c, Vec3 na, Vec3 nb, Vec3 nc, std::uint32_t object) {
  const Triangle tri{a, b, c};
  const Vec3 n = triangle_normal(tri);
  if (!(dot(n, n) > 0.f)) return;  // pole slivers of zero area
  const std::array<Vec3, 3> normals{na, nb, nc};
  out.add(tri, &normals, nullptr, object);
}

void tessellate_sphere(Geometry& out, const Sphere& s, std::uint32_t object, const TessellationOptions& o) {
  auto direction = [&](int ring, int seg) {
    const double theta = std::numbers::pi * ring / o.rings;
    const double phi = kTwoPi * seg / o.segments;
    return Vec3{static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
                static_cast<float>(std::sin(theta) * std::sin(phi))};
  };
  for (int r = 0; r < o.rings; ++r) {
    for (int k = 0; k < o.segments; ++k) {
      const Vec3 d00 = direction(r, k), d01 = direction(r, k + 1);
      const Vec3 d10 = direction(r + 1, k), d11 = direction(r + 1, k + 1);
      auto p = [&](Vec3 d) { return s.center + d * s.radius; };
      // Counter-clockwise seen from outside.
      add_smooth(out, p(d00), p(d01), p(d11), d00, d01, d11, object);
      add_smooth(out, p(d00), p(d11), p(d10), d00, d11, d10, object);
    }
  }
}

void tessellate_cylinder(Geometry& out, const Cylinder& c, std::uint32_t object, const TessellationOptions& o) {
  const Vec3 axis = c.apex - c.base;
  const float height = length(axis);
  if (!(height > 0.f)) return;
  const Vec3 a = axis / height;
  Vec3 t, b;
  frame(a, t, b);
  // The lateral normal of a cone leans toward the apex by the slope of its side.
  const float slope = (c.base_radius - c.apex_radius) / height;
  for (int k = 0; k < o.segments; ++k) {
    const double p0 = kTwoPi * k / o.segments, p1 = kTwoPi * (k + 1) / o.segments;
    const Vec3 r0 = t * static_cast<float>(std::cos(p0)) + b * static_cast<float>(std::sin(p0));
    const Vec3 r1 = t * static_cast<float>(std::cos(p1)) + b * static_cast<float>(std::sin(p1));
    const Vec3 n0 = normalize(r0 + a * slope), n1 = normalize(r1 + a * slope);
    const Vec3 b0 = c.base + r0 * c.base_radius, b1 = c.base + r1 * c.base_radius;
    const Vec3 a0 = c.apex + r0 * c.apex_radius, a1 = c.apex + r1 * c.apex_radius;
    // Counter-clockwise seen from outside: (t, b, axis) is right-handed and the angle turns t to b.
    add_smooth(out, b0, b1, a1, n0, n1, n1, object);
    add_smooth(out, b0, a1, a0, n0, n1, n0, object);
  }
}

void tessellate_disk(Geometry& out, const Disk& d, std::uint32_t object, const TessellationOptions& o) {
  Vec3 t, b;
  frame(d.normal, t, b);
  for (int k = 0; k < o.segments; ++k) {
    const double p0 = kTwoPi * k / o.segments, p1 = kTwoPi * (k + 1) / o.segments;
    const Vec3 e0 = d.center + (t * static_cast<float>(std::cos(p0)) + b * static_cast<float>(std::sin(p0))) * d.radius;
    const Vec3 e1 = d.center + (t * static_cast<float>(std::cos(p1)) + b * static_cast<float>(std::sin(p1))) * d.radius;
    // Wind so the triangle's normal is the disk's.
    Triangle tri{d.center, e0, e1};
    if (dot(triangle_normal(tri), d.normal) < 0.f) std::swap(tri.p1, tri.p2);
    out.add(tri, object);
  }
}

}  // namespace

Geometry tessellate(const Geometry& g, const TessellationOptions& options) {
  TessellationOptions o = options;
  o.segments = std::max(3, o.segments);
  o.rings = std::max(2, o.rings);
  Geometry out;
  for (std::size_t i = 0; i < g.triangles.size(); ++i) {
    const std::array<Vec3, 3>* n = g.triangle_normals.empty() ? nullptr : &g.triangle_normals[i];
    const std::array<Vec2, 3>* uv = g.triangle_uvs.empty() ? nullptr : &g.triangle_uvs[i];
    out.add(g.triangles[i], n, uv, g.triangle_objects[i]);
  }
  for (std::size_t i = 0; i < g.spheres.size(); ++i) tessellate_sphere(out, g.spheres[i], g.sphere_objects[i], o);
  for (std::size_t i = 0; i < g.cylinders.size(); ++i) {
    tessellate_cylinder(out, g.cylinders[i], g.cylinder_objects[i], o);
  }
  for (std::size_t i = 0; i < g.disks.size(); ++i) tessellate_disk(out, g.disks[i], g.disk_objects[i], o);
  for (std::size_t i = 0; i < g.quads.size(); ++i) {
    const Quad& q = g.quads[i];
    const Vec3 p1 = q.corner + q.edge_u, p2 = q.corner + q.edge_u + q.edge_v, p3 = q.corner + q.edge_v;
    out.add(Triangle{q.corner, p1, p2}, g.quad_objects[i]);
    out.add(Triangle{q.corner, p2, p3}, g.quad_objects[i]);
  }
  return out;
}

}  // namespace raylab
