#pragma once
/// \file
/// Bounding volumes around complex objects: the box or sphere a ray is tested against before it
/// may enter a mesh's or an instance's own structure. A cheap test that rejects most rays spares
/// them the structure's traversal; the sphere is the cheaper test, the box the tighter fit.

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "raylab/core/box.h"
#include "raylab/core/ray.h"
#include "raylab/geometry/geometry.h"
#include "raylab/geometry/sphere.h"

namespace raylab {

/// What wraps each mesh or instance (`--wrap`).
enum class WrapMode : std::uint8_t {
  kNone,    ///< meshes go into the top level primitive by primitive; instances are entered directly
  kBox,     ///< each mesh and instance is one top-level item behind its bounding box
  kSphere,  ///< each mesh and instance is one top-level item behind a bounding sphere
};

/// Parses "none", "box" or "sphere"; throws UsageError listing them otherwise.
WrapMode parse_wrap_mode(std::string_view name);
/// The name of a wrap mode ("none", "box", "sphere").
std::string_view wrap_mode_name(WrapMode mode);

/// The volume around one mesh or instance (world space) and the test a ray pays before entering.
struct BoundingWrapper {
  WrapMode mode = WrapMode::kNone;  ///< which of the volumes the test uses
  Box3 box;                         ///< the bounding box
  Sphere sphere;                    ///< the bounding sphere (enlarged a little: see sphere_around)

  /// True when the segment [ray.tmin, ray.tmax] meets the volume (always for kNone). Never
  /// rejects a ray that meets the object inside: the box test is widened as the traversals'
  /// slab tests are, the sphere enlarged at construction.
  bool admits(const Ray& ray) const;
};

/// A sphere around `points`: the centre of their box, the radius to the farthest one, enlarged a
/// little so that rounding in the ray-ball test never rejects a ray that grazes it.
Sphere sphere_around(std::span<const Vec3> points);

/// Appends points whose convex hull contains primitive `id` of `geometry`: a triangle's corners,
/// the box corners of any other shape.
void append_hull_points(const Geometry& geometry, std::uint32_t id, std::vector<Vec3>& out);

/// True when the segment [ray.tmin, ray.tmax] of `ray` meets the solid ball `s`.
bool ray_meets_ball(const Sphere& s, const Ray& ray);

}  // namespace raylab
