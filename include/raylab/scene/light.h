#pragma once
/// \file
/// Light sources: point, spot, directional, and spherical and quad area lights.

#include <cstdint>

#include "raylab/core/vec3.h"

namespace raylab {

/// A light. Point and spherical lights fall off with the inverse square of distance only when
/// `falloff` is set (NFF lights do not fall off); area lights are sampled with `samples`
/// stratified shadow rays, which gives soft shadows. Every member has a default, so that a
/// designated initialiser names only what differs from it.
struct Light {
  /// kSpot is a point light limited to a cone (last, so that the other kinds keep their values,
  /// which scene fingerprints hash).
  enum class Kind { kPoint, kDirectional, kSphere, kQuad, kSpot } kind = Kind::kPoint;
  Vec3 position{};                 ///< point / sphere centre / quad corner
  Vec3 direction{0.f, -1.f, 0.f};  ///< directional: direction the light travels; spot: the cone's axis
  Vec3 edge_u{1.f, 0.f, 0.f};      ///< quad: first edge
  Vec3 edge_v{0.f, 0.f, 1.f};      ///< quad: second edge
  float radius = 0.f;              ///< sphere radius
  Color intensity{1.f, 1.f, 1.f};  ///< colour times strength
  bool falloff = false;            ///< divide by squared distance
  int samples = 16;                ///< shadow rays per shading point for area lights (a square is used)
  float spot_angle = 30.f;         ///< spot: half-angle of the cone, in degrees (0 to 90]
  float spot_blend = 0.15f;        ///< spot: the outer fraction of the angle over which the light fades out
  /// The scene object that draws this light's surface (an emissive quad where a quad light is),
  /// or -1. The path integrator, for which an emitter is geometry, lights the scene from that
  /// object and skips this entry; Whitted samples this entry and shows the object.
  std::int32_t object = -1;
};

}  // namespace raylab
