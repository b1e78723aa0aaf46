// The lab's one rule for whether two closest-hit answers agree (see the header for why it has
// a relative tolerance, an origin slack and a tie).

#include "raylab/lab/hit_agreement.h"

#include <algorithm>
#include <cmath>

namespace raylab {

double origin_slack(const Ray& ray) {
  return std::max({std::fabs(ray.origin.x), std::fabs(ray.origin.y), std::fabs(ray.origin.z)}) * std::ldexp(16.0, -24);
}

bool distances_agree(double a, double b, double tolerance, double slack) {
  return std::fabs(a - b) <= std::max(tolerance * std::max(std::fabs(a), std::fabs(b)), slack);
}

HitMatch match_hits(const Hit& a, const Hit& b, double tolerance, double slack) {
  if (a.valid() != b.valid()) return HitMatch::kDifferent;
  if (!a.valid() || a.prim_id == b.prim_id) return HitMatch::kSame;
  return distances_agree(a.t, b.t, tolerance, slack) ? HitMatch::kTie : HitMatch::kDifferent;
}

bool hits_agree(const Hit& a, const Hit& b, float tolerance) {
  return match_hits(a, b, tolerance) != HitMatch::kDifferent;
}

}  // namespace raylab
