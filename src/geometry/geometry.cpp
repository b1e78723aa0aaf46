#include "raylab/geometry/geometry.h"

#include <cassert>

namespace raylab {
namespace {

// Texture coordinates of a triangle that has none of its own.
constexpr std::array<Vec2, 3> kBarycentricUvs{Vec2{0.f, 0.f}, Vec2{1.f, 0.f}, Vec2{0.f, 1.f}};

// Appends primitive `shape` of object `object`: a kind's primitives and their objects are
// parallel arrays, and grow together.
template <class Shape>
void append(std::vector<Shape>& shapes, std::vector<std::uint32_t>& objects, const Shape& shape, std::uint32_t object) {
  shapes.push_back(shape);
  objects.push_back(object);
}

}  // namespace

std::uint32_t Geometry::add(const Triangle& t, std::uint32_t object) { return add(t, nullptr, nullptr, object); }

std::uint32_t Geometry::add(const Triangle& t, const std::array<Vec3, 3>& normals, std::uint32_t object) {
  return add(t, &normals, nullptr, object);
}

std::uint32_t Geometry::add(const Triangle& t, const std::array<Vec3, 3>* normals, const std::array<Vec2, 3>* uvs,
                            std::uint32_t object) {
  // Optional arrays are created on first use, back-filled with "absent" for earlier triangles.
  if (normals != nullptr && triangle_normals.size() < triangles.size()) {
    triangle_normals.resize(triangles.size(), {Vec3{}, Vec3{}, Vec3{}});
  }
  if (uvs != nullptr && triangle_uvs.size() < triangles.size()) {
    triangle_uvs.resize(triangles.size(), kBarycentricUvs);
  }
  triangles.push_back(t);
  triangle_objects.push_back(object);
  // The first triangle with normals or uvs starts the array, even on an empty geometry.
  if (normals != nullptr || !triangle_normals.empty()) {
    triangle_normals.push_back(normals ? *normals : std::array<Vec3, 3>{});
  }
  if (uvs != nullptr || !triangle_uvs.empty()) triangle_uvs.push_back(uvs ? *uvs : kBarycentricUvs);
  return static_cast<std::uint32_t>(triangles.size() - 1);
}

void Geometry::add(const Sphere& s, std::uint32_t object) { append(spheres, sphere_objects, s, object); }

void Geometry::add(const Cylinder& c, std::uint32_t object) { append(cylinders, cylinder_objects, c, object); }

void Geometry::add(const Disk& d, std::uint32_t object) { append(disks, disk_objects, d, object); }

void Geometry::add(const Quad& q, std::uint32_t object) { append(quads, quad_objects, q, object); }

std::vector<std::uint32_t> Geometry::primitive_ids() const {
  std::vector<std::uint32_t> ids(size());
  for (std::uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
  return ids;
}

ShapeRef Geometry::resolve(std::uint32_t id) const {
  assert(id < size());
  if (id < triangles.size()) return {ShapeKind::kTriangle, id};
  id -= static_cast<std::uint32_t>(triangles.size());
  if (id < spheres.size()) return {ShapeKind::kSphere, id};
  id -= static_cast<std::uint32_t>(spheres.size());
  if (id < cylinders.size()) return {ShapeKind::kCylinder, id};
  id -= static_cast<std::uint32_t>(cylinders.size());
  if (id < disks.size()) return {ShapeKind::kDisk, id};
  id -= static_cast<std::uint32_t>(disks.size());
  return {ShapeKind::kQuad, id};
}

Box3 Geometry::bounds(std::uint32_t prim_id) const {
  if (prim_id >= kGroupIdBase) return groups[prim_id - kGroupIdBase].box;
  const ShapeRef r = resolve(prim_id);
  switch (r.kind) {
    case ShapeKind::kTriangle: {
      const Triangle& t = triangles[r.index];
      Box3 b;
      b.extend(t.p0);
      b.extend(t.p1);
      b.extend(t.p2);
      return b;
    }
    case ShapeKind::kSphere:
      return sphere_bounds(spheres[r.index]);
    case ShapeKind::kCylinder:
      return cylinder_bounds(cylinders[r.index]);
    case ShapeKind::kDisk:
      return disk_bounds(disks[r.index]);
    case ShapeKind::kQuad:
      return quad_bounds(quads[r.index]);
  }
  return {};
}

Box3 Geometry::bounds() const {
  // Kind by kind rather than through resolve(): this runs over every primitive of a scene after
  // loading, and a million triangles should cost a pass over their vertices, nothing more.
  Box3 b;
  for (const Triangle& t : triangles) {
    b.extend(t.p0);
    b.extend(t.p1);
    b.extend(t.p2);
  }
  for (const Sphere& s : spheres) b.extend(sphere_bounds(s));
  for (const Cylinder& c : cylinders) b.extend(cylinder_bounds(c));
  for (const Disk& d : disks) b.extend(disk_bounds(d));
  for (const Quad& q : quads) b.extend(quad_bounds(q));
  return b;
}

std::uint32_t Geometry::object_of(std::uint32_t prim_id) const {
  const ShapeRef r = resolve(prim_id);
  switch (r.kind) {
    case ShapeKind::kTriangle:
      return triangle_objects[r.index];
    case ShapeKind::kSphere:
      return sphere_objects[r.index];
    case ShapeKind::kCylinder:
      return cylinder_objects[r.index];
    case ShapeKind::kDisk:
      return disk_objects[r.index];
    case ShapeKind::kQuad:
      return quad_objects[r.index];
  }
  return kInvalidId;
}

bool Geometry::intersect(std::uint32_t prim_id, const WatertightRay& wr, Ray& ray, Hit& hit) const {
  if (prim_id >= kGroupIdBase) {
    const GroupShape& g = groups[prim_id - kGroupIdBase];
    return g.intersect(g.context, ray, hit);
  }
  const ShapeRef r = resolve(prim_id);
  float t = 0.f, u = 0.f, v = 0.f;
  bool found = false;
  const float tmax = hit.tie_limit(prim_id, ray.tmax);
  switch (r.kind) {
    case ShapeKind::kTriangle:
      found = intersect_triangle(triangles[r.index], wr, ray.tmin, tmax, t, u, v);
      break;
    case ShapeKind::kSphere:
      found = intersect_sphere(spheres[r.index], ray, ray.tmin, tmax, t);
      break;
    case ShapeKind::kCylinder:
      found = intersect_cylinder(cylinders[r.index], ray, ray.tmin, tmax, t, v);
      break;
    case ShapeKind::kDisk:
      found = intersect_disk(disks[r.index], ray, ray.tmin, tmax, t);
      break;
    case ShapeKind::kQuad:
      found = intersect_quad(quads[r.index], ray, ray.tmin, tmax, t, u, v);
      break;
  }
  if (!found) return false;
  ray.tmax = t;
  hit = Hit{t, prim_id, u, v};
  return true;
}

bool Geometry::occluded(std::uint32_t prim_id, const WatertightRay& wr, const Ray& ray) const {
  if (prim_id >= kGroupIdBase) {
    const GroupShape& g = groups[prim_id - kGroupIdBase];
    return g.occluded(g.context, ray);
  }
  Ray probe = ray;
  Hit scratch;
  return intersect(prim_id, wr, probe, scratch);
}

}  // namespace raylab
