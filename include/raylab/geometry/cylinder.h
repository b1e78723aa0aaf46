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
/// height. A structure keeps these beside its leaves, so that each test saves a square root and
/// four divisions; the test gives bit for bit what it gives from the Cylinder. 56 bytes.
struct CylinderFrame {
  Vec3 base;                            ///< the base point
  float base_radius = 1.f;              ///< the radius at the base
  double wx = 0.0, wy = 0.0, wz = 0.0;  ///< the unit axis, base to apex
  double h = 0.0;                       ///< the axis length (0: degenerate, never hit)
  double k = 0.0;                       ///< radius change per unit height
};

/// The frame of `cyl`.
CylinderFrame cylinder_frame(const Cylinder& cyl);

/// Closest hit of `ray` with the lateral surface of `cyl` in [tmin, tmax). The quadratic is
/// solved in double precision: cones are few, and grazing rays need the accuracy.
/// On a hit, `t` is set and `height` is the fraction 0..1 from base to apex.
bool intersect_cylinder(const Cylinder& cyl, const Ray& ray, float tmin, float tmax, float& t, float& height);

/// The same test from the cylinder's precomputed frame (cylinder_frame): the same answers.
bool intersect_cylinder(const CylinderFrame& frame, const Ray& ray, float tmin, float tmax, float& t, float& height);

/// Outward unit normal of the lateral surface at point `p`.
Vec3 cylinder_normal(const Cylinder& cyl, Vec3 p);

/// Bounding box of a cone frustum (exact: the extent of each end disk, per axis).
Box3 cylinder_bounds(const Cylinder& cyl);

}  // namespace raylab
