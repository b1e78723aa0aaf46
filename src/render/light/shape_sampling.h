#pragma once
// Internal to the render module: points spread uniformly over the area of the shapes that can
// emit light, for light sampling. One rule per shape, called by the path integrator's emitters
// and by Whitted's sphere and quad lights alike.

#include "raylab/core/vec3.h"
#include "raylab/geometry/cylinder.h"
#include "raylab/geometry/planar.h"
#include "raylab/geometry/sphere.h"
#include "raylab/geometry/triangle.h"
#include "raylab/sampling/pixel_sampler.h"

namespace raylab::detail {

/// A point on a surface and the surface's unit normal there (the shape's own orientation).
struct SurfacePoint {
  Vec3 position;
  Vec3 normal;
};

/// The point at (u, v) in [0, 1)^2 of the uniform parametrisation of the sphere's surface:
/// z = 1 - 2u, azimuth 2 pi v (Whitted's sphere lights have always used this one).
Vec3 point_on_sphere(Vec3 center, float radius, float u, float v);

/// Uniform points by area (pdf 1 / area), from `u`.
SurfacePoint sample_triangle(const Triangle& t, Sample2 u);
/// See sample_triangle.
SurfacePoint sample_sphere(const Sphere& s, Sample2 u);
/// See sample_triangle.
SurfacePoint sample_disk(const Disk& d, Sample2 u);
/// See sample_triangle.
SurfacePoint sample_quad(const Quad& q, Sample2 u);
/// See sample_triangle: a point of the lateral surface of a cylinder or cone frustum, with its
/// outward normal. Uniform in area: the height follows the radius (a linear density, inverted
/// in closed form), the angle is uniform.
SurfacePoint sample_cylinder(const Cylinder& c, Sample2 u);

/// Surface areas.
float triangle_area(const Triangle& t);
/// See triangle_area.
float sphere_area(const Sphere& s);
/// See triangle_area.
float disk_area(const Disk& d);
/// See triangle_area.
float quad_area(const Quad& q);
/// See triangle_area: the lateral surface, pi (r0 + r1) times the slant height.
float cylinder_area(const Cylinder& c);

}  // namespace raylab::detail
