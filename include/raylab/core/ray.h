#pragma once
/// \file
/// Rays and hit records shared by every accelerator.

#include <cmath>
#include <cstdint>
#include <limits>

#include "raylab/core/vec3.h"

namespace raylab {

/// Sentinel for "no primitive".
inline constexpr std::uint32_t kInvalidId = 0xffffffffu;

/// A ray `origin + t * direction` restricted to `t` in [tmin, tmax]. 32 bytes, laid out exactly
/// as one record of a `.rays` file (origin xyz, tmin, direction xyz, tmax). The direction need not
/// be unit length; `t` is measured in units of it. `intersect` shrinks `tmax` to the closest hit.
struct Ray {
  Vec3 origin;
  float tmin = 0.f;
  Vec3 direction;
  float tmax = std::numeric_limits<float>::infinity();

  /// The point at parameter `t`.
  constexpr Vec3 at(float t) const { return origin + direction * t; }
};
static_assert(sizeof(Ray) == 32, "Ray must match the .rays record layout");

/// The ray's direction octant: bit a is set when direction component a is negative (-0
/// included: its reciprocal is -inf). It decides which of a box's two planes is met first, and
/// which rays can share a packet.
inline int direction_octant(Vec3 d) {
  return (std::signbit(d.x) ? 1 : 0) | (std::signbit(d.y) ? 2 : 0) | (std::signbit(d.z) ? 4 : 0);
}

/// The closest (or any) hit found by an accelerator: what traversal knows, nothing more. Shading
/// data (normal, uv, material) is computed afterwards from `prim_id` (see geometry/shading.h).
struct Hit {
  float t = std::numeric_limits<float>::infinity();  ///< ray parameter of the hit
  std::uint32_t prim_id = kInvalidId;                ///< global primitive index (see Geometry)
  float u = 0.f;                                     ///< first barycentric / surface coordinate
  float v = 0.f;                                     ///< second barycentric / surface coordinate

  /// True when a primitive was hit.
  constexpr bool valid() const { return prim_id != kInvalidId; }

  /// The far limit to test primitive `candidate` against, given that this is the closest hit so
  /// far and `tmax` its distance. Exactly equal distances are resolved toward the lower
  /// primitive id, so the closest hit (and everything shading derives from it, such as the
  /// SPD ray counts) does not depend on the order in which a structure visits primitives: a
  /// candidate with a lower id is tested against the next float above `tmax`, so that a hit at
  /// exactly `tmax` is taken.
  float tie_limit(std::uint32_t candidate, float tmax) const {
    return valid() && candidate < prim_id ? std::nextafter(tmax, std::numeric_limits<float>::infinity()) : tmax;
  }
};

}  // namespace raylab
