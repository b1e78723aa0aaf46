#pragma once
/// \file
/// Four spheres stored lane by lane, tested against one ray with SIMD: how the wide BVH tests the
/// spheres of a leaf. The test is the one of sphere.h done four lanes at a time with the same
/// float operations in the same order, so each lane gives bit for bit what `intersect_sphere`
/// gives for that sphere.

#include <bit>
#include <cmath>

#include "raylab/core/ray.h"
#include "raylab/geometry/sphere.h"
#include "raylab/simd/float4.h"
#include "raylab/simd/isa_namespace.h"

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

/// `intersect_sphere` on the lanes `lanes` of `spheres`: the mask of the lanes hit within
/// [tmin, tmax), and in t_out[i] each such lane's distance (the nearer root when it lies in the
/// interval, else the farther). Lanes whose discriminant overflows float go to intersect_sphere
/// itself (its fallback for them is not worth a vector path). A caller with a tie rule passes
/// the largest limit it may apply (the float above its tmax) and checks `t < limit` lane by lane:
/// a root rejected that way would have been rejected by intersect_sphere at that limit too,
/// since the other root is not nearer.
[[gnu::always_inline]] inline int intersect_sphere_lanes(const SphereLanes& spheres, int lanes, const Ray& ray,
                                                         float tmin, float tmax, float t_out[4]) {
  using simd::Float4;
  const Float4 zero = Float4::broadcast(0.f);
  const Float4 r = Float4::load(spheres.radius);
  const Float4 r2 = r * r;
  const Float4 dx = Float4::broadcast(ray.direction.x), dy = Float4::broadcast(ray.direction.y),
               dz = Float4::broadcast(ray.direction.z);
  const Float4 a = Float4::broadcast(dot(ray.direction, ray.direction));
  const Float4 fx = Float4::broadcast(ray.origin.x) - Float4::load(spheres.cx);
  const Float4 fy = Float4::broadcast(ray.origin.y) - Float4::load(spheres.cy);
  const Float4 fz = Float4::broadcast(ray.origin.z) - Float4::load(spheres.cz);
  const Float4 b = fx * dx + fy * dy + fz * dz;
  const Float4 c = (fx * fx + fy * fy + fz * fz) - r2;
  const Float4 b_over_a = b / a;
  const Float4 lx = fx - dx * b_over_a, ly = fy - dy * b_over_a, lz = fz - dz * b_over_a;
  const Float4 disc = a * (r2 - (lx * lx + ly * ly + lz * lz));
  // A radius whose square is not positive, and a negative (or NaN) discriminant: no hit.
  int live = lanes & less_mask(zero, r2) & less_equal_mask(zero, disc);
  if (live == 0) return 0;
  const int overflow = live & equal_mask(disc, Float4::broadcast(INFINITY));
  // -b as b * -1, which flips the sign of a zero as negation does (0 - b would not).
  const Float4 q = b * Float4::broadcast(-1.f) - copysign(sqrt(disc), b);
  const Float4 t0 = c / q, t1 = q / a;
  // intersect_sphere's `if (t0 > t1) swap`: min and max take their second operand on NaN.
  const Float4 near = min(t1, t0), far = max(t0, t1);
  const Float4 lo = Float4::broadcast(tmin), hi = Float4::broadcast(tmax);
  const int near_in = less_equal_mask(lo, near) & less_mask(near, hi);
  const int far_in = less_equal_mask(lo, far) & less_mask(far, hi);
  alignas(16) float near_t[4], far_t[4];
  near.store(near_t);
  far.store(far_t);
  int hit = live & ~overflow & (near_in | far_in);
  for (unsigned m = static_cast<unsigned>(hit); m != 0; m &= m - 1) {
    const int i = std::countr_zero(m);
    t_out[i] = (near_in >> i) & 1 ? near_t[i] : far_t[i];
  }
  if (overflow != 0) [[unlikely]] {
    for (unsigned m = static_cast<unsigned>(overflow); m != 0; m &= m - 1) {
      const int i = std::countr_zero(m);
      if (intersect_sphere(spheres.sphere(i), ray, tmin, tmax, t_out[i])) hit |= 1 << i;
    }
  }
  return hit;
}

RAYLAB_ISA_END
}  // namespace raylab
