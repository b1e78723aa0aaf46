#pragma once
/// \file
/// Watertight ray-triangle intersection (Woop, Benthin & Wald, JCGT 2013).

#include <cmath>
#include <utility>

#include "raylab/core/ray.h"

namespace raylab {

/// A triangle by its three vertices (36 bytes). Winding p0 -> p1 -> p2 gives the geometric
/// normal cross(p1 - p0, p2 - p0); both sides are hit (no culling).
struct Triangle {
  Vec3 p0, p1, p2;
};

/// Per-ray constants of the watertight test, computed once per ray and reused for every
/// triangle: the axis permutation that makes the dominant direction component z, and the shear
/// that maps the ray onto the +z axis.
struct WatertightRay {
  Vec3 origin;
  int kx = 0, ky = 1, kz = 2;
  float sx = 0.f, sy = 0.f, sz = 1.f;

  WatertightRay() = default;
  /// Prepares the constants for `ray`.
  explicit WatertightRay(const Ray& ray) : origin(ray.origin) {
    const Vec3 d = ray.direction;
    const Vec3 ad = abs(d);
    kz = max_axis(ad);
    kx = kz == 2 ? 0 : kz + 1;
    ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0.f) std::swap(kx, ky);  // keeps the winding, so the sign of det is meaningful
    sz = 1.f / d[kz];
    sx = d[kx] * sz;
    sy = d[ky] * sz;
  }
};

/// Whether some of three edge functions is negative and some positive: the ray passes beside the
/// triangle (NaN is neither).
inline bool edge_signs_differ(float e0, float e1, float e2) {
  return (e0 < 0.f || e1 < 0.f || e2 < 0.f) && (e0 > 0.f || e1 > 0.f || e2 > 0.f);
}

/// Whether the edge functions p0 - q0, p1 - q1, p2 - q2, given by their products rounded to
/// float, surely have both signs. Rounding is monotone, so fl(p) < fl(q) implies p < q exactly
/// and fl(p) > fl(q) implies p > q (where float cannot tell, neither holds): a triangle this
/// rejects, the exact test rejects too. Products are compared, not subtracted, so that no FMA
/// contraction can round one of them and not the other.
inline bool beside_in_float(float p0, float q0, float p1, float q1, float p2, float q2) {
  return (p0 < q0 || p1 < q1 || p2 < q2) && (p0 > q0 || p1 > q1 || p2 > q2);
}

/// Tests `tri` against the ray described by `wr`, accepting hits with tmin <= t < tmax.
/// Watertight: a ray through an edge or vertex shared by two triangles hits at least one of them
/// (edge functions are evaluated with exact products, so their signs are exact). On a hit writes `t`
/// and the barycentric weights `u` (of p1) and `v` (of p2).
inline bool intersect_triangle(const Triangle& tri, const WatertightRay& wr, float tmin, float tmax, float& t, float& u,
                               float& v) {
  const Vec3 a = tri.p0 - wr.origin;
  const Vec3 b = tri.p1 - wr.origin;
  const Vec3 c = tri.p2 - wr.origin;
  const float ax = a[wr.kx] - wr.sx * a[wr.kz];
  const float ay = a[wr.ky] - wr.sy * a[wr.kz];
  const float bx = b[wr.kx] - wr.sx * b[wr.kz];
  const float by = b[wr.ky] - wr.sy * b[wr.kz];
  const float cx = c[wr.kx] - wr.sx * c[wr.kz];
  const float cy = c[wr.ky] - wr.sy * c[wr.kz];
  // A filter in float first: most triangles a ray is tested against lie beside it, and the
  // products of the edge functions in float show that, exactly (see beside_in_float).
  if (beside_in_float(cx * by, cy * bx, ax * cy, ay * cx, bx * ay, by * ax)) return false;
  // Edge functions with exact products (a product of two floats fits in a double), so each sign
  // is exact and a shared edge gets exactly opposite values in its two triangles. In float,
  // `cx * by - cy * bx` is contracted to fma(cx, by, -(cy * bx)) where FMA is available (GCC's
  // default for C++ with -march=x86-64-v3); that is not the negation of the neighbour's
  // fma(bx, cy, -(by * cx)), and both triangles could reject a ray through their shared edge.
  const float e0 = static_cast<float>(double(cx) * double(by) - double(cy) * double(bx));  // weight of p0
  const float e1 = static_cast<float>(double(ax) * double(cy) - double(ay) * double(cx));  // weight of p1
  const float e2 = static_cast<float>(double(bx) * double(ay) - double(by) * double(ax));  // weight of p2
  if (edge_signs_differ(e0, e1, e2)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.f) return false;
  const float az = wr.sz * a[wr.kz];
  const float bz = wr.sz * b[wr.kz];
  const float cz = wr.sz * c[wr.kz];
  const float rcp = 1.f / det;
  const float th = (e0 * az + e1 * bz + e2 * cz) * rcp;
  if (!(th >= tmin && th < tmax)) return false;  // also rejects NaN
  t = th;
  u = e1 * rcp;
  v = e2 * rcp;
  return true;
}

/// Unnormalised geometric normal of `tri` (its length is twice the area).
inline Vec3 triangle_normal(const Triangle& tri) { return cross(tri.p1 - tri.p0, tri.p2 - tri.p0); }

}  // namespace raylab
