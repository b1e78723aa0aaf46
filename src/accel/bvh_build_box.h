#pragma once
/// \file
/// Internal to the BVH builder: the 4-wide box it accumulates bounds in, shared by the binning,
/// the partition and the relayout.

#include <cmath>

#include "bvh_build_ref.h"
#include "raylab/core/box.h"
#include "raylab/simd/float4.h"

namespace raylab::bvh_build {

/// A box as two 4-wide vectors (the fourth lane is ignored), 32 bytes; empty when default-made.
struct Box4 {
  simd::Float4 lo = simd::Float4::broadcast(INFINITY);
  simd::Float4 hi = simd::Float4::broadcast(-INFINITY);

  /// Grows the box to contain the box [l, h].
  void extend(simd::Float4 l, simd::Float4 h) {
    lo = min(l, lo);
    hi = max(h, hi);
  }
  /// Grows the box to contain `b`.
  void extend(const Box4& b) { extend(b.lo, b.hi); }
  /// The box as a Box3.
  Box3 box3() const {
    float l[4], h[4];
    lo.store(l);
    hi.store(h);
    return {{l[0], l[1], l[2]}, {h[0], h[1], h[2]}};
  }
};

/// Surface area of a 4-wide box; 0 when empty.
inline float area(const Box4& b) {
  float e[4];
  (b.hi - b.lo).store(e);  // one subtraction and one store instead of three and two
  // Without a branch: the split search sweeps over bins, empty or not in no predictable order,
  // and a branch here mispredicted about once in forty calls.
  const int nonempty = int(e[0] >= 0.f) & int(e[1] >= 0.f) & int(e[2] >= 0.f);
  const float a = 2.f * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
  return nonempty != 0 ? a : 0.f;
}

/// A reference's box minimum as four floats (the fourth is its id's bits, ignored).
inline simd::Float4 load_lo(const BuildRef& r) { return simd::Float4::load(r.lo); }
/// A reference's box maximum as four floats (the fourth is the splittable flag's bits, ignored).
inline simd::Float4 load_hi(const BuildRef& r) { return simd::Float4::load(r.hi); }

}  // namespace raylab::bvh_build
