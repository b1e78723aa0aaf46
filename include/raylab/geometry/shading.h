#pragma once
/// \file
/// Surface data at a hit, computed once the closest hit is known (never during traversal).

#include <algorithm>
#include <cstdint>
#include <optional>

#include "raylab/core/ray.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// What shading needs to know about a hit point.
struct SurfaceInteraction {
  Vec3 position;                         ///< hit point
  Vec3 geometric_normal;                 ///< unit normal of the surface, facing the incoming ray
  Vec3 shading_normal;                   ///< unit interpolated normal, on the same side as geometric_normal
  float u = 0.f;                         ///< surface coordinate (texture space), shape-dependent
  float v = 0.f;                         ///< surface coordinate (texture space), shape-dependent
  bool front_face = true;                ///< true when the ray hit the side the shape's own normal points to
  std::uint32_t object_id = kInvalidId;  ///< object the primitive belongs to
};

/// How a surface's position changes with its surface coordinates (u, v) of SurfaceInteraction:
/// the frame in which normal and bump maps are written.
struct SurfaceTangents {
  Vec3 dpdu;  ///< dp/du, in scene units per unit of u
  Vec3 dpdv;  ///< dp/dv, in scene units per unit of v
};

/// The tangents of primitive `prim_id` (a triangle's or a quad's are constant over it), or
/// nullopt for the shapes whose surface coordinates are not meant for image maps (spheres,
/// cylinders, disks) and for triangles whose texture coordinates have no area.
std::optional<SurfaceTangents> surface_tangents(const Geometry& geometry, std::uint32_t prim_id);

/// Whether surface_at computes a hit's surface coordinates (SurfaceInteraction::u and v).
enum class SurfaceCoordinates : std::uint8_t {
  kCompute,  ///< u and v as each shape defines them
  /// For a caller that will not read them: u = v = 0 where they cost more than the rest of the
  /// hit, which is on spheres (an arc tangent and an arc cosine); the other shapes' cost a few
  /// products and are computed all the same.
  kSkip,
};

/// Computes position, normals and surface coordinates (as `coordinates` says) for `hit` on
/// `ray`. The position and normals do not depend on `coordinates`.
SurfaceInteraction surface_at(const Geometry& geometry, const Ray& ray, const Hit& hit,
                              SurfaceCoordinates coordinates = SurfaceCoordinates::kCompute);

/// Offset along the normal that moves a spawned ray's origin off the surface: relative to the
/// magnitude of the position so that scenes at any scale are handled (float ulp ~ 1.2e-7).
inline float surface_offset(Vec3 position) { return 1e-4f * std::max(1.f, max_component(abs(position))); }

/// The two origins of the rays leaving a surface point: moved off it along its normal `n`, to
/// `n`'s side and to the other. Made once per hit when it spawns several rays (shading).
struct OffsetOrigins {
  Vec3 above;  ///< for directions on n's side (dot(dir, n) >= 0)
  Vec3 below;  ///< for the others

  /// The origin of a ray leaving in direction `dir`; `n` is the normal these were made with.
  Vec3 toward(Vec3 dir, Vec3 n) const { return dot(dir, n) >= 0.f ? above : below; }
};

/// The two origins of rays leaving the surface at `p` with normal `n`.
inline OffsetOrigins offset_origins(Vec3 p, Vec3 n) {
  const float eps = surface_offset(p);
  return {p + n * eps, p - n * eps};
}

/// Origin for a ray leaving the surface at `p` towards the side of `n` that `dir` points to.
Vec3 offset_origin(Vec3 p, Vec3 n, Vec3 dir);

}  // namespace raylab
