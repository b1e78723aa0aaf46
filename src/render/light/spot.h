#pragma once
// Internal to the render module: how much of a spot light's intensity leaves toward a
// direction. One rule for the Whitted and the path integrators.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "raylab/scene/light.h"

namespace raylab::detail {

/// The fraction of spot light `light`'s intensity sent along unit direction `out` (from the
/// light): 1 inside the inner cone, 0 outside the cone of half-angle spot_angle, and a smooth
/// step between, over the outer spot_blend of the angle (in cosine, as Blender's spot lights).
inline float spot_factor(const Light& light, Vec3 out) {
  constexpr float kDegree = std::numbers::pi_v<float> / 180.f;
  const float angle = std::clamp(light.spot_angle, 0.f, 90.f) * kDegree;
  const float cos_outer = std::cos(angle);
  const float cos_inner = std::cos(angle * (1.f - std::clamp(light.spot_blend, 0.f, 1.f)));
  const float c = dot(normalize(light.direction), out);
  if (c <= cos_outer) return 0.f;
  if (c >= cos_inner) return 1.f;
  const float t = (c - cos_outer) / (cos_inner - cos_outer);
  return t * t * (3.f - 2.f * t);
}

}  // namespace raylab::detail
