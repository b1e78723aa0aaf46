#pragma once
/// \file
/// Four spheres stored lane by lane, tested against one ray with SIMD: how the wide BVH tests the
/// spheres of a leaf. The test is the one of sphere.h done four lanes at a time with the same
/// float operations in the same order, so each lane gives bit for bit what `intersect_sphere`
/// gives for that sphere.

#include <bit>
#include <cmath>

#include "raylab/core/ray.h"
#include "raylab/geometry/ray_lanes.h"
#include "raylab/geometry/sphere.h"
#include "raylab/simd/float4.h"
#include "raylab/simd/isa_namespace.h"
#include "raylab/simd/wide_float.h"

namespace raylab {

/// Where four spheres lie lane by lane: four floats from each pointer, structure of arrays.
/// Lanes that hold no sphere are left out by the caller's lane mask, or hold radius 0 (never
/// hit, as in intersect_sphere).
struct SphereLanes {
  const float* cx;      ///< the centres' x
  const float* cy;      ///< the centres' y
  const float* cz;      ///< the centres' z
  const float* radius;  ///< the radii

  /// The sphere of lane `lane`.
  Sphere sphere(int lane) const { return Sphere{{cx[lane], cy[lane], cz[lane]}, radius[lane]}; }
};

RAYLAB_ISA_BEGIN

/// What the sphere test needs of spheres, lane by lane (broadcast where the lanes share one).
template <int N>
struct SphereTestLanes {
  simd::WideFloat<N> cx, cy, cz;  ///< the centres
  simd::WideFloat<N> radius_sq;   ///< the squared radii, as intersect_sphere computes them
};

/// `intersect_sphere`'s rule lane by lane, each lane a (ray, sphere) pair, within each lane's
/// [tmin, tmax); `a` is each lane's dot(d, d) (a caller whose lanes share one ray computes it
/// once, in scalar). The mask of the lanes of `lanes` hit, and in t_out[i] each such lane's
/// distance (the nearer root when it lies in the interval, else the farther). The float
/// operations and their order are the scalar test's (dot products summed x, y, then z; `-b` as
/// `b * -1`, which flips a zero's sign as negation does; the swap of the roots as
/// `min(t1, t0)` and `max(t0, t1)`, whose NaN rule keeps the scalar order), so each lane is bit
/// for bit the scalar answer. Lanes whose discriminant overflows float go to
/// `fallback(i, t_out[i])` (intersect_sphere itself for that pair: its fallback is not worth a
/// vector path). The one rule of both forms: four spheres against one ray
/// (intersect_sphere_lanes), one sphere against N rays (sphere_rays.h).
template <int N, class Fallback>
[[gnu::always_inline]] inline unsigned rays_hitting_spheres(const RayLanes<N>& rays, const simd::WideFloat<N>& a,
                                                            const SphereTestLanes<N>& spheres, unsigned lanes,
                                                            const simd::WideFloat<N>& tmin,
                                                            const simd::WideFloat<N>& tmax, float* t_out,
                                                            const Fallback& fallback) {
  using F = simd::WideFloat<N>;
  const F zero = F::broadcast(0.f);
  const F& r2 = spheres.radius_sq;
  const F &dx = rays.dx, &dy = rays.dy, &dz = rays.dz;
  const F fx = rays.ox - spheres.cx;
  const F fy = rays.oy - spheres.cy;
  const F fz = rays.oz - spheres.cz;
  const F b = fx * dx + fy * dy + fz * dz;
  const F c = (fx * fx + fy * fy + fz * fz) - r2;
  const F b_over_a = b / a;
  const F lx = fx - dx * b_over_a, ly = fy - dy * b_over_a, lz = fz - dz * b_over_a;
  const F disc = a * (r2 - (lx * lx + ly * ly + lz * lz));
  // A radius whose square is not positive, and a negative (or NaN) discriminant: no hit.
  const unsigned live = lanes & less_mask(zero, r2) & less_equal_mask(zero, disc);
  if (live == 0) return 0;
  const unsigned overflow = live & equal_mask(disc, F::broadcast(INFINITY));
  // -b as b * -1, which flips the sign of a zero as negation does (0 - b would not).
  const F q = b * F::broadcast(-1.f) - copysign(sqrt(disc), b);
  const F t0 = c / q, t1 = q / a;
  // intersect_sphere's `if (t0 > t1) swap`: min and max take their second operand on NaN.
  const F near = min(t1, t0), far = max(t0, t1);
  const unsigned near_in = less_equal_mask(tmin, near) & less_mask(near, tmax);
  const unsigned far_in = less_equal_mask(tmin, far) & less_mask(far, tmax);
  unsigned hit = live & ~overflow & (near_in | far_in);
  if (hit != 0) {
    // Aligned to the vector, no more: 64 would make every caller of the four-lane form realign
    // its stack frame.
    alignas(N * sizeof(float)) float near_t[N], far_t[N];
    near.store(near_t);
    far.store(far_t);
    for (unsigned m = hit; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      t_out[i] = (near_in >> i) & 1u ? near_t[i] : far_t[i];
    }
  }
  if (overflow != 0) [[unlikely]] {
    for (unsigned m = overflow; m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (fallback(i, t_out[i])) hit |= 1u << i;
    }
  }
  return hit;
}

/// `intersect_sphere` on the lanes `lanes` of `spheres`: the mask of the lanes hit within
/// [tmin, tmax), and in t_out[i] each such lane's distance (rays_hitting_spheres). A caller with
/// a tie rule passes the largest limit it may apply (the float above its tmax) and checks
/// `t < limit` lane by lane: a root rejected that way would have been rejected by
/// intersect_sphere at that limit too, since the other root is not nearer.
[[gnu::always_inline]] inline int intersect_sphere_lanes(const SphereLanes& spheres, int lanes, const Ray& ray,
                                                         float tmin, float tmax, float t_out[4]) {
  using simd::Float4;
  const RayLanes<4> line{Float4::broadcast(ray.origin.x),    Float4::broadcast(ray.origin.y),
                         Float4::broadcast(ray.origin.z),    Float4::broadcast(ray.direction.x),
                         Float4::broadcast(ray.direction.y), Float4::broadcast(ray.direction.z)};
  const Float4 r = Float4::load(spheres.radius);
  const SphereTestLanes<4> four{Float4::load(spheres.cx), Float4::load(spheres.cy), Float4::load(spheres.cz), r * r};
  const auto fallback = [&](int i, float& t) { return intersect_sphere(spheres.sphere(i), ray, tmin, tmax, t); };
  const Float4 a = Float4::broadcast(dot(ray.direction, ray.direction));
  return static_cast<int>(rays_hitting_spheres<4>(line, a, four, static_cast<unsigned>(lanes), Float4::broadcast(tmin),
                                                  Float4::broadcast(tmax), t_out, fallback));
}

RAYLAB_ISA_END
}  // namespace raylab
