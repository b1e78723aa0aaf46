#include "raylab/geometry/shading.h"

#include <cmath>
#include <numbers>

namespace raylab {
namespace {

// Spherical coordinates of a unit direction mapped to [0, 1]^2.
void spherical_uv(Vec3 n, float& u, float& v) {
  u = 0.5f + std::atan2(n.z, n.x) / (2.f * std::numbers::pi_v<float>);
  v = std::acos(std::clamp(n.y, -1.f, 1.f)) / std::numbers::pi_v<float>;
}

}  // namespace

SurfaceInteraction surface_at(const Geometry& geometry, const Ray& ray, const Hit& hit,
                              SurfaceCoordinates coordinates) {
  SurfaceInteraction si;
  si.object_id = geometry.object_of(hit.prim_id);
  const ShapeRef ref = geometry.resolve(hit.prim_id);
  Vec3 n_shape;                  // the shape's own outward normal (unit)
  Vec3 n_smooth{0.f, 0.f, 0.f};  // interpolated normal, when the shape has one
  switch (ref.kind) {
    case ShapeKind::kTriangle: {
      const Triangle& tri = geometry.triangles[ref.index];
      const float w = 1.f - hit.u - hit.v;
      // Barycentric reconstruction is more accurate than origin + t * direction.
      si.position = tri.p0 * w + tri.p1 * hit.u + tri.p2 * hit.v;
      n_shape = normalize(triangle_normal(tri));
      if (!geometry.triangle_normals.empty()) {
        const auto& vn = geometry.triangle_normals[ref.index];
        const Vec3 s = vn[0] * w + vn[1] * hit.u + vn[2] * hit.v;
        if (dot(s, s) > 0.f) n_smooth = normalize(s);
      }
      si.u = hit.u;
      si.v = hit.v;
      if (!geometry.triangle_uvs.empty()) {
        const auto& uv = geometry.triangle_uvs[ref.index];
        si.u = uv[0].x * w + uv[1].x * hit.u + uv[2].x * hit.v;
        si.v = uv[0].y * w + uv[1].y * hit.u + uv[2].y * hit.v;
      }
      break;
    }
    case ShapeKind::kSphere: {
      const Sphere& s = geometry.spheres[ref.index];
      si.position = ray.at(hit.t);
      n_shape = normalize(si.position - s.center);
      // Project back onto the sphere: removes the error of t along the normal.
      si.position = s.center + n_shape * s.radius;
      if (coordinates == SurfaceCoordinates::kCompute) spherical_uv(n_shape, si.u, si.v);
      break;
    }
    case ShapeKind::kCylinder: {
      const Cylinder& c = geometry.cylinders[ref.index];
      si.position = ray.at(hit.t);
      n_shape = cylinder_normal(c, si.position);
      si.u = 0.f;
      si.v = hit.v;
      break;
    }
    case ShapeKind::kDisk: {
      const Disk& d = geometry.disks[ref.index];
      si.position = ray.at(hit.t);
      n_shape = d.normal;
      Vec3 t, b;
      orthonormal_basis(d.normal, t, b);
      si.u = dot(si.position - d.center, t);
      si.v = dot(si.position - d.center, b);
      break;
    }
    case ShapeKind::kQuad: {
      const Quad& q = geometry.quads[ref.index];
      si.position = q.corner + q.edge_u * hit.u + q.edge_v * hit.v;
      n_shape = normalize(cross(q.edge_u, q.edge_v));
      // Texture coordinates in world units along the edges, so checkers keep square cells.
      si.u = hit.u * length(q.edge_u);
      si.v = hit.v * length(q.edge_v);
      break;
    }
  }
  si.front_face = dot(ray.direction, n_shape) < 0.f;
  si.geometric_normal = si.front_face ? n_shape : -n_shape;
  si.shading_normal = si.geometric_normal;
  if (dot(n_smooth, n_smooth) > 0.f) {
    si.shading_normal = dot(n_smooth, si.geometric_normal) < 0.f ? -n_smooth : n_smooth;
  }
  return si;
}

std::optional<SurfaceTangents> surface_tangents(const Geometry& geometry, std::uint32_t prim_id) {
  const ShapeRef ref = geometry.resolve(prim_id);
  if (ref.kind == ShapeKind::kQuad) {
    // surface_at measures a quad's coordinates in scene units along its edges.
    const Quad& q = geometry.quads[ref.index];
    const float lu = length(q.edge_u), lv = length(q.edge_v);
    if (!(lu > 0.f) || !(lv > 0.f)) return std::nullopt;
    return SurfaceTangents{q.edge_u / lu, q.edge_v / lv};
  }
  if (ref.kind != ShapeKind::kTriangle) return std::nullopt;
  const Triangle& tri = geometry.triangles[ref.index];
  const Vec3 e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
  // Without texture coordinates a triangle's are its barycentrics: (0,0), (1,0), (0,1).
  if (geometry.triangle_uvs.empty()) return SurfaceTangents{e1, e2};
  // e1 = du1 dp/du + dv1 dp/dv and e2 likewise: solve the 2x2 system for the two tangents.
  const auto& uv = geometry.triangle_uvs[ref.index];
  const float du1 = uv[1].x - uv[0].x, dv1 = uv[1].y - uv[0].y;
  const float du2 = uv[2].x - uv[0].x, dv2 = uv[2].y - uv[0].y;
  const float det = du1 * dv2 - du2 * dv1;
  if (!(std::fabs(det) > 1e-12f) || !std::isfinite(det)) return std::nullopt;
  const float inv = 1.f / det;
  return SurfaceTangents{(e1 * dv2 - e2 * dv1) * inv, (e2 * du1 - e1 * du2) * inv};
}

Vec3 offset_origin(Vec3 p, Vec3 n, Vec3 dir) { return offset_origins(p, n).toward(dir, n); }

}  // namespace raylab
