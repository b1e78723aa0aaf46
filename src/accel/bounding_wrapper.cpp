// Bounding volumes around meshes and instances (bounding_wrapper.h).

#include "raylab/accel/bounding_wrapper.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "raylab/core/error.h"
#include "traversal_common.h"

namespace raylab {

WrapMode parse_wrap_mode(std::string_view name) {
  if (name == "none") return WrapMode::kNone;
  if (name == "box") return WrapMode::kBox;
  if (name == "sphere") return WrapMode::kSphere;
  throw UsageError("unknown wrap mode '" + std::string(name) + "' (valid: none, box, sphere)");
}

std::string_view wrap_mode_name(WrapMode mode) {
  switch (mode) {
    case WrapMode::kNone:
      return "none";
    case WrapMode::kBox:
      return "box";
    case WrapMode::kSphere:
      return "sphere";
  }
  return "none";
}

bool ray_meets_ball(const Sphere& s, const Ray& ray) {
  const Vec3 f = ray.origin - s.center;
  const float a = dot(ray.direction, ray.direction);
  const float b = dot(f, ray.direction);
  const Vec3 l = f - ray.direction * (b / a);  // centre to its foot on the ray line
  const float r2 = s.radius * s.radius;
  const float d2 = dot(l, l);
  if (!(d2 <= r2)) return false;
  const float half = std::sqrt((r2 - d2) / a);
  const float t_mid = -b / a;
  return t_mid - half <= ray.tmax && t_mid + half >= ray.tmin;
}

bool BoundingWrapper::admits(const Ray& ray) const {
  switch (mode) {
    case WrapMode::kSphere:
      return ray_meets_ball(sphere, ray);
    case WrapMode::kBox: {
      float t_enter;
      return intersect_box(box, ray.origin, safe_reciprocal(ray.direction), ray.tmin, widen_exit(ray.tmax), t_enter);
    }
    case WrapMode::kNone:
      break;
  }
  return true;
}

Sphere sphere_around(std::span<const Vec3> points) {
  Box3 box;
  for (Vec3 p : points) box.extend(p);
  const Vec3 c = box.center();
  float r2 = 0.f;
  for (Vec3 p : points) r2 = std::max(r2, dot(p - c, p - c));
  return {c, std::sqrt(r2) * (1.f + 1e-5f) + 1e-30f};
}

void append_hull_points(const Geometry& geometry, std::uint32_t id, std::vector<Vec3>& out) {
  const ShapeRef r = geometry.resolve(id);
  if (r.kind == ShapeKind::kTriangle) {
    const Triangle& t = geometry.triangles[r.index];
    out.insert(out.end(), {t.p0, t.p1, t.p2});
    return;
  }
  const Box3 b = geometry.bounds(id);
  for (int c = 0; c < 8; ++c)
    out.push_back({c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z});
}

}  // namespace raylab
