#pragma once
/// \file
/// The one rule by which the lab decides whether two tracers answered a ray alike: `raylab
/// compare` holds every structure to its reference with it, `raylab bench` holds ours to Embree.
/// One rule, so that "agrees" means the same in both reports.

#include "raylab/core/ray.h"

namespace raylab {

/// Relative tolerance on the distances of two hits that the lab's checks use unless told
/// otherwise: two correct tracers that round differently land well within it.
inline constexpr double kHitDistanceTolerance = 1e-4;

/// How two closest-hit answers to one ray compare.
enum class HitMatch {
  kSame,       ///< both miss, or both hit the same primitive
  kTie,        ///< different primitives at distances that agree (shared edges, coplanar faces)
  kDifferent,  ///< one hits and the other misses, or different primitives at different distances
};

/// Absolute distance slack near a ray's origin: 16 float ulps of its largest coordinate. A ray
/// leaving a surface can meet its own or a neighbouring triangle at t ~ 1e-6, where two correct
/// float tests differ by far more than a relative tolerance of t, but by less than this.
double origin_slack(const Ray& ray);

/// True when distances `a` and `b` agree: they differ by at most `tolerance` times the larger
/// magnitude, or by at most `slack`.
bool distances_agree(double a, double b, double tolerance, double slack = 0.0);

/// The rule. Both miss, or both hit the same primitive: kSame (the distances are not compared:
/// two tracers may round the same surface point differently). Different primitives whose
/// distances agree (distances_agree with `tolerance` and `slack`): kTie, which a caller able to
/// test the primitives may confirm further. Anything else: kDifferent.
HitMatch match_hits(const Hit& a, const Hit& b, double tolerance, double slack = 0.0);

/// True when two closest-hit answers agree: match_hits(a, b, tolerance) is not kDifferent.
bool hits_agree(const Hit& a, const Hit& b, float tolerance);

}  // namespace raylab
