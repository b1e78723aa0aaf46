#pragma once
/// \file
/// All primitives of a scene in flat arrays, with one global primitive index space.

#include <array>
#include <cstdint>
#include <vector>

#include "raylab/core/box.h"
#include "raylab/core/ray.h"
#include "raylab/geometry/cylinder.h"
#include "raylab/geometry/planar.h"
#include "raylab/geometry/sphere.h"
#include "raylab/geometry/triangle.h"

namespace raylab {

/// The kinds of primitive, in the order their ranges appear in the global index space.
enum class ShapeKind : std::uint8_t { kTriangle = 0, kSphere, kCylinder, kDisk, kQuad };

/// A global primitive index resolved to its kind and its index within that kind's array.
struct ShapeRef {
  ShapeKind kind;
  std::uint32_t index;
};

/// First id of the group range: ids at or above it name `Geometry::groups[id - kGroupIdBase]`.
inline constexpr std::uint32_t kGroupIdBase = 0x80000000u;

/// A whole sub-structure (a wrapped mesh, or a placed instance) seen as one primitive by the top
/// level of a two-level structure. Type-erased, so that geometry knows nothing of accelerators:
/// the callbacks receive `context` back. Both answer in global primitive ids and honour the
/// current closest hit passed in (its `t` in `ray.tmax`, its id for equal-distance ties).
struct GroupShape {
  Box3 box;                     ///< bounds of everything in the group (world space)
  Sphere sphere{Vec3{}, -1.f};  ///< bounding sphere, when the group is wrapped in one (radius < 0: none)
  const void* context = nullptr;
  /// Closest hit in [ray.tmin, ray.tmax): on a hit shrinks ray.tmax, fills hit, returns true.
  bool (*intersect)(const void* context, Ray& ray, Hit& hit) = nullptr;
  /// Any hit in [ray.tmin, ray.tmax).
  bool (*occluded)(const void* context, const Ray& ray) = nullptr;
};

/// Plain data: the scene's primitives, one array per kind, each primitive tagged with the object
/// it belongs to. Global primitive ids number triangles first, then spheres, cylinders, disks and
/// quads, so that for a scene of one mesh the id is the triangle's index in file order.
/// Arrays may be appended to freely until an accelerator is built over the geometry; after that
/// the accelerator refers to it and it must not change.
struct Geometry {
  std::vector<Triangle> triangles;
  std::vector<Sphere> spheres;
  std::vector<Cylinder> cylinders;
  std::vector<Disk> disks;
  std::vector<Quad> quads;

  /// Object id of each primitive, one array per kind, parallel to the shape arrays.
  std::vector<std::uint32_t> triangle_objects, sphere_objects, cylinder_objects, disk_objects, quad_objects;

  /// Per-vertex shading normals of each triangle; empty, or parallel to `triangles`. A zero
  /// normal means "use the geometric normal" for that triangle.
  std::vector<std::array<Vec3, 3>> triangle_normals;

  /// Per-vertex texture coordinates of each triangle; empty, or parallel to `triangles`.
  /// Triangles without them get (0,0), (1,0), (0,1), i.e. their barycentric coordinates.
  std::vector<std::array<Vec2, 3>> triangle_uvs;

  /// Sub-structures standing as single items (ids kGroupIdBase + index; not counted by size()).
  /// Only two-level structures fill this, in their own copy of the shapes; scenes never do.
  std::vector<GroupShape> groups;

  /// Appends a triangle of object `object`; returns its global id.
  std::uint32_t add(const Triangle& t, std::uint32_t object);
  /// Appends a triangle with per-vertex shading normals.
  std::uint32_t add(const Triangle& t, const std::array<Vec3, 3>& normals, std::uint32_t object);
  /// Appends a triangle with optional per-vertex shading normals and texture coordinates (each
  /// nullptr when absent). The one entry point that keeps all parallel arrays in step.
  std::uint32_t add(const Triangle& t, const std::array<Vec3, 3>* normals, const std::array<Vec2, 3>* uvs,
                    std::uint32_t object);
  /// Appends a sphere.
  void add(const Sphere& s, std::uint32_t object);
  /// Appends a cylinder or cone.
  void add(const Cylinder& c, std::uint32_t object);
  /// Appends a disk.
  void add(const Disk& d, std::uint32_t object);
  /// Appends a quad.
  void add(const Quad& q, std::uint32_t object);

  /// Total number of primitives.
  std::uint32_t size() const {
    return static_cast<std::uint32_t>(triangles.size() + spheres.size() + cylinders.size() + disks.size() +
                                      quads.size());
  }
  /// The ids 0 .. size() - 1: every primitive, for building a structure over all of them.
  std::vector<std::uint32_t> primitive_ids() const;
  /// Resolves a global id (must be < size()) to kind and local index.
  ShapeRef resolve(std::uint32_t prim_id) const;
  /// Bounding box of primitive `prim_id` (or of group `prim_id`).
  Box3 bounds(std::uint32_t prim_id) const;
  /// Bounding box of all primitives.
  Box3 bounds() const;
  /// Object id of primitive `prim_id`.
  std::uint32_t object_of(std::uint32_t prim_id) const;

  /// Tests primitive `prim_id` against `ray` in [ray.tmin, ray.tmax). On a hit, shrinks
  /// `ray.tmax`, fills `hit` and returns true. `wr` must be WatertightRay(ray).
  /// A group id calls the group's own `intersect`.
  bool intersect(std::uint32_t prim_id, const WatertightRay& wr, Ray& ray, Hit& hit) const;

  /// True when primitive (or group) `prim_id` is hit anywhere in [ray.tmin, ray.tmax): the
  /// any-hit test of shadow rays, which lets a group stop at its first hit.
  bool occluded(std::uint32_t prim_id, const WatertightRay& wr, const Ray& ray) const;
};

}  // namespace raylab
