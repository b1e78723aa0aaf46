#pragma once
/// \file
/// Open cylinders and truncated cones, as NFF's `c` primitive defines them.

#include "raylab/core/box.h"
#include "raylab/core/ray.h"

namespace raylab {

/// An open (capless) cone frustum from `base` with `base_radius` to `apex` with `apex_radius`;
/// a cylinder when the radii are equal (32 bytes).
struct Cylinder {
  Vec3 base;
  float base_radius = 1.f;
  Vec3 apex;
  float apex_radius = 1.f;
};

/// What the intersection test of a cylinder needs that does not depend on the ray, computed once:
/// the unit axis and the length of the axis in double precision, and the radius change per unit
/// height; and, for the float test that rejects the rays that surely miss, the unit axis in float
/// and the radius beyond which a line surely misses. A structure keeps these beside its leaves, so that each test saves
/// a square root and four divisions; the test gives bit for bit what it gives from the Cylinder. 72 bytes.
struct CylinderFrame {
  Vec3 base;                            ///< the base point
  float base_radius = 1.f;              ///< the radius at the base
  double wx = 0.0, wy = 0.0, wz = 0.0;  ///< the unit axis, base to apex
  double h = 0.0;                       ///< the axis length (0: degenerate, never hit)
  double k = 0.0;                       ///< radius change per unit height
  Vec3 axis{0.f, 0.f, 0.f};             ///< the unit axis rounded to float
  /// The larger end radius (by magnitude); infinity, which turns the float rejection off, for a
  /// cone whose radius changes faster than its height (see cylinder.cpp).
  float reject_radius = 0.f;
};

/// The frame of `cyl`.
CylinderFrame cylinder_frame(const Cylinder& cyl);

/// Closest hit of `ray` with the lateral surface of `cyl` in [tmin, tmax). The quadratic is
/// solved in double precision: cones are few, and grazing rays need the accuracy.
/// On a hit, `t` is set and `height` is the fraction 0..1 from base to apex.
bool intersect_cylinder(const Cylinder& cyl, const Ray& ray, float tmin, float tmax, float& t, float& height);

/// The same test from the cylinder's precomputed frame (cylinder_frame): the same answers. Most
/// rays that reach a cylinder in a structure's leaf pass beside it; a float test of the distance
/// between the ray's line and the axis rejects those that surely miss (with a margin far above
/// float's rounding, see cylinder.cpp), and the rest go to intersect_cylinder_exact.
bool intersect_cylinder(const CylinderFrame& frame, const Ray& ray, float tmin, float tmax, float& t, float& height);

/// The double-precision test alone, without the float rejection (the reference the tests hold
/// intersect_cylinder to).
bool intersect_cylinder_exact(const CylinderFrame& frame, const Ray& ray, float tmin, float tmax, float& t,
                              float& height);

/// Whether the line of `ray` surely passes farther from the axis of `frame` than its larger end
/// radius, so that the exact test misses; false when float cannot tell (the line nearly parallel
/// to the axis, the distance within the margin of the radius, magnitudes far from 1).
bool cylinder_surely_missed(const CylinderFrame& frame, const Ray& ray);

namespace detail {
/// The float rejection judges only lines at least this sine off the axis (cylinder.cpp says why).
inline constexpr float kCylinderRejectMinSine = 0.1f;
/// Its margin over the radius, per unit of |origin - base|_1 + radius (cylinder.cpp says why).
inline constexpr float kCylinderRejectMargin = 4e-5f;
}  // namespace detail

/// Outward unit normal of the lateral surface at point `p`.
Vec3 cylinder_normal(const Cylinder& cyl, Vec3 p);

/// Bounding box of a cone frustum (exact: the extent of each end disk, per axis).
Box3 cylinder_bounds(const Cylinder& cyl);

}  // namespace raylab
