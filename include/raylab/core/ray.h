#pragma once
/// \file
/// Rays and hit records shared by every accelerator.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "raylab/core/float_neighbour.h"
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

/// Whether a ray can be traced along `d`: every component finite and not all zero. A ray whose
/// direction is not (a NaN, an infinite component, or zero) is no ray: every accelerator answers
/// it with a miss, closest-hit, any-hit, packet and all-hits queries alike. An infinite component
/// has no useful limit (every distance along it rounds to t = +-0, behind the origin as well as
/// ahead), and Embree takes such rays as invalid (its `EMBREE_IGNORE_INVALID_RAYS` build misses
/// them too).
inline bool traceable_direction(Vec3 d) {
  // On the magnitudes' bit patterns, which order as the magnitudes do and put inf and every NaN
  // above the finite floats: the largest must be neither zero nor inf or NaN. Integer work only,
  // no branch: this runs once per ray on every query.
  constexpr std::uint32_t kMagnitude = 0x7fffffffu, kInfinity = 0x7f800000u;
  const std::uint32_t x = std::bit_cast<std::uint32_t>(d.x) & kMagnitude;
  const std::uint32_t y = std::bit_cast<std::uint32_t>(d.y) & kMagnitude;
  const std::uint32_t z = std::bit_cast<std::uint32_t>(d.z) & kMagnitude;
  const std::uint32_t largest = std::max(x, std::max(y, z));
  return largest - 1u < kInfinity - 1u;  // 0 wraps round to the top
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
    return valid() && candidate < prim_id ? next_float_up(tmax) : tmax;
  }
};

}  // namespace raylab
