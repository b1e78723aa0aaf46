#pragma once
/// \file
/// One sphere against N rays at once (N = 4, 8 or 16): the ray-parallel form of the sphere test
/// of sphere.h, for packets, as triangle_rays.h is for triangles. Each lane does
/// `intersect_sphere`'s float operations in the same order, so lane i gives bit for bit what
/// `intersect_sphere` gives for ray i.

#include "raylab/geometry/ray_lanes.h"
#include "raylab/geometry/sphere.h"
#include "raylab/geometry/sphere_lanes.h"
#include "raylab/simd/isa_namespace.h"
#include "raylab/simd/wide_float.h"

namespace raylab {
RAYLAB_ISA_BEGIN

/// `intersect_sphere(sphere, ray_i, tmin_i, tmax_i, t)` for each lane i of `lanes`: the mask of
/// the lanes hit, and in t_out[i] each such lane's distance (rays_hitting_spheres). As with
/// intersect_sphere_lanes, a caller with a tie rule may pass any limit at least the one the rule
/// applies and check `t < limit` lane by lane: the answer is the same.
template <int N>
[[gnu::always_inline]] inline unsigned intersect_sphere_rays(const Sphere& sphere, const RayLanes<N>& rays,
                                                             unsigned lanes, const simd::WideFloat<N>& tmin,
                                                             const simd::WideFloat<N>& tmax, float* t_out) {
  using F = simd::WideFloat<N>;
  const float r2 = sphere.radius * sphere.radius;
  // A radius whose square is not positive: no hit for any ray (intersect_sphere's first test).
  if (!(r2 > 0.f)) return 0;
  const SphereTestLanes<N> one{F::broadcast(sphere.center.x), F::broadcast(sphere.center.y),
                               F::broadcast(sphere.center.z), F::broadcast(r2)};
  const auto fallback = [&](int i, float& t) {
    alignas(N * sizeof(float)) float lo[N], hi[N];
    tmin.store(lo);
    tmax.store(hi);
    return intersect_sphere(sphere, rays.ray(i), lo[i], hi[i], t);
  };
  const F a = rays.dx * rays.dx + rays.dy * rays.dy + rays.dz * rays.dz;
  return rays_hitting_spheres<N>(rays, a, one, lanes, tmin, tmax, t_out, fallback);
}

RAYLAB_ISA_END
}  // namespace raylab
