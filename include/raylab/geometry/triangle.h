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
/// rejects, the exact test rejects too. That stays true with the tie rule of `edge_with_tie_broken`,
/// which gives a sign only to edge functions that are exactly zero, and this filter never claims
/// a sign for those. Products are compared, not subtracted, so that no FMA contraction can round
/// one of them and not the other.
inline bool beside_in_float(float p0, float q0, float p1, float q1, float p2, float q2) {
  return (p0 < q0 || p1 < q1 || p2 < q2) && (p0 > q0 || p1 > q1 || p2 > q2);
}

/// The edge function e = px * qy - py * qx of the edge from p to q (two sheared vertices,
/// relative to the ray, which sits at the origin of the sheared plane), as the kernels computed
/// it (exact products, rounded once to float), with a tie broken: never zero for an edge whose
/// ends differ. A ray exactly on the line of an edge would otherwise be accepted by both
/// triangles that share the edge, so a closed mesh could count one crossing twice.
///
/// The rule is "simulation of simplicity": the ray is taken as moved by an infinitesimal
/// (eps, eps^2), which turns e into e + eps * (py - qy) + eps^2 * (qx - px) (to first order in
/// each). So a non-zero e keeps its sign, and a zero one takes the sign of py - qy, or where
/// that is zero of qx - px. The neighbour that shares the edge has it from q to p, and float
/// subtraction is exactly antisymmetric, so it gets the opposite sign: exactly one of the two
/// accepts the ray. One perturbation for all edges tested against one ray also makes a ray
/// through a vertex hit exactly one triangle of a fan that covers the vertex once in the sheared
/// plane (a flat enough fan), and a ray grazing a silhouette hit 0 or 2 triangles.
///
/// A float e of zero is not always an exact zero: an exact value under the float range rounds to
/// (signed) zero. There the exact sign is recomputed, so that only exact zeros get the tie rule
/// and the float filter (`beside_in_float`), which decides from exact signs, stays valid. Only
/// the sign of the result means anything; returns `e` itself when it is not zero (NaN included).
inline float edge_with_tie_broken(float e, float px, float py, float qx, float qy) {
  if (e != 0.f) return e;
  const double exact = double(px) * double(qy) - double(py) * double(qx);
  if (exact != 0.0) return exact < 0.0 ? -1.f : 1.f;
  const float dy = py - qy;
  return dy != 0.f ? dy : qx - px;
}

/// A triangle as the watertight test sees it: its vertices relative to the ray's origin on the
/// permuted axes, sheared so that the ray runs along z through the origin of the (x, y) plane.
struct ShearedTriangle {
  float ax, ay, bx, by, cx, cy;  ///< sheared x and y of p0, p1, p2
  float akz, bkz, ckz;           ///< (p - origin)[kz] of p0, p1, p2 (z before the scale sz)
};

/// `tri` sheared for the ray `wr`. The SIMD kernels do these operations lane by lane, in this
/// order, so each lane gets these values bit for bit.
inline ShearedTriangle shear_triangle(const Triangle& tri, const WatertightRay& wr) {
  const Vec3 a = tri.p0 - wr.origin;
  const Vec3 b = tri.p1 - wr.origin;
  const Vec3 c = tri.p2 - wr.origin;
  return {a[wr.kx] - wr.sx * a[wr.kz],
          a[wr.ky] - wr.sy * a[wr.kz],
          b[wr.kx] - wr.sx * b[wr.kz],
          b[wr.ky] - wr.sy * b[wr.kz],
          c[wr.kx] - wr.sx * c[wr.kz],
          c[wr.ky] - wr.sy * c[wr.kz],
          a[wr.kz],
          b[wr.kz],
          c[wr.kz]};
}

/// The edge function px * qy - py * qx of the edge from p to q, with exact products (a product of
/// two floats fits in a double) rounded once to float: its sign is exact, and the edge from q to
/// p gets exactly the opposite value. In float, `px * qy - py * qx` is contracted to
/// fma(px, qy, -(py * qx)) where FMA is available (GCC's default for C++ with
/// -march=x86-64-v3); that is not the negation of the neighbour's fma(qx, py, -(qy * px)), and
/// both triangles could reject a ray through their shared edge.
inline float exact_edge_function(float px, float py, float qx, float qy) {
  return static_cast<float>(double(px) * double(qy) - double(py) * double(qx));
}

/// Whether the tie rule (`edge_with_tie_broken`) rejects `tri` for the ray `wr`: whether, once
/// the edge functions that are exactly zero have a sign, some edge function is negative and some
/// positive. Every kernel calls this, only for a hit with an edge function exactly zero (rare;
/// or with a product of the three that underflows), so that all break ties identically. It
/// computes the sheared vertices again (bit for bit the same), so that the SIMD kernels need not
/// keep them in registers for this rare case; not inlined, so that it costs the kernels nothing
/// where it is not called.
[[gnu::noinline]] inline bool tie_rule_rejects(const Triangle& tri, const WatertightRay& wr) {
  const ShearedTriangle s = shear_triangle(tri, wr);
  const float e0 = exact_edge_function(s.cx, s.cy, s.bx, s.by);
  const float e1 = exact_edge_function(s.ax, s.ay, s.cx, s.cy);
  const float e2 = exact_edge_function(s.bx, s.by, s.ax, s.ay);
  return edge_signs_differ(edge_with_tie_broken(e0, s.cx, s.cy, s.bx, s.by),
                           edge_with_tie_broken(e1, s.ax, s.ay, s.cx, s.cy),
                           edge_with_tie_broken(e2, s.bx, s.by, s.ax, s.ay));
}

/// Tests `tri` against the ray described by `wr`, accepting hits with tmin <= t < tmax.
/// Watertight, and each crossing counted once: a ray through an edge shared by two consistently
/// wound triangles hits exactly one of them, and a ray through a vertex exactly one triangle of a
/// flat enough fan around it (edge functions are evaluated with exact products, so their signs
/// are exact, and exact zeros get a sign by the tie rule of `edge_with_tie_broken`). On a hit
/// writes `t` and the barycentric weights `u` (of p1) and `v` (of p2).
inline bool intersect_triangle(const Triangle& tri, const WatertightRay& wr, float tmin, float tmax, float& t, float& u,
                               float& v) {
  const ShearedTriangle s = shear_triangle(tri, wr);
  // A filter in float first: most triangles a ray is tested against lie beside it, and the
  // products of the edge functions in float show that, exactly (see beside_in_float).
  if (beside_in_float(s.cx * s.by, s.cy * s.bx, s.ax * s.cy, s.ay * s.cx, s.bx * s.ay, s.by * s.ax)) return false;
  // Edge functions with exact signs, so a shared edge gets exactly opposite values in its two
  // triangles (see exact_edge_function).
  const float e0 = exact_edge_function(s.cx, s.cy, s.bx, s.by);  // weight of p0
  const float e1 = exact_edge_function(s.ax, s.ay, s.cx, s.cy);  // weight of p1
  const float e2 = exact_edge_function(s.bx, s.by, s.ax, s.ay);  // weight of p2
  if (edge_signs_differ(e0, e1, e2)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.f) return false;
  const float az = wr.sz * s.akz;
  const float bz = wr.sz * s.bkz;
  const float cz = wr.sz * s.ckz;
  const float rcp = 1.f / det;
  const float th = (e0 * az + e1 * bz + e2 * cz) * rcp;
  if (!(th >= tmin && th < tmax)) return false;  // also rejects NaN
  // The tie rule, last because it is rarely needed: it only gives zeros a sign, so it can turn a
  // hit into a miss but never the reverse; det, t, u and v keep the unperturbed values. Where an
  // edge function is zero so is the product of the three, which cannot be NaN here (an infinite
  // edge function makes th NaN, rejected above); a product that underflows to zero only sends a
  // hit without zeros to the tie rule, which then changes nothing. One compare instead of three:
  // this runs for every hit.
  if (e0 * e1 * e2 == 0.f && tie_rule_rejects(tri, wr)) [[unlikely]]
    return false;
  t = th;
  u = e1 * rcp;
  v = e2 * rcp;
  return true;
}

/// Unnormalised geometric normal of `tri` (its length is twice the area).
inline Vec3 triangle_normal(const Triangle& tri) { return cross(tri.p1 - tri.p0, tri.p2 - tri.p0); }

}  // namespace raylab
