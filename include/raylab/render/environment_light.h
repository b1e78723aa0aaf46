#pragma once
/// \file
/// The environment as a light of the path integrator: the radiance a direction sees, and
/// directions drawn in proportion to it for next-event estimation.
///
/// A constant environment is sampled uniformly over the sphere. An image is sampled by a
/// Distribution2D over its texels in (u, v) (scene/environment.h gives the mapping), each
/// texel weighted by its luminance times the solid angle of its row, so that bright texels and
/// texels of large solid angle are drawn most; a density p(u, v) in the image plane is the
/// density p(u, v) / (2 pi^2 sin(theta)) in solid angle, since dOmega = 2 pi^2 sin(theta) du dv.

#include <memory>
#include <optional>

#include "raylab/core/vec3.h"
#include "raylab/sampling/distribution.h"
#include "raylab/sampling/pixel_sampler.h"
#include "raylab/scene/environment.h"

namespace raylab {

/// An Environment ready to be evaluated and sampled. Immutable after construction: share one
/// between threads; sampling and evaluation allocate nothing.
class EnvironmentLight {
 public:
  /// A direction drawn toward the environment.
  struct Sample {
    Vec3 wi;          ///< unit direction toward the environment, in world space
    Color radiance;   ///< radiance(wi), bit for bit
    float pdf = 0.f;  ///< solid-angle density of wi, > 0 and equal to pdf(wi) bit for bit
  };

  /// Prepares `env`: its rotation, its scale, and for an image the sampling distribution (one
  /// pass over the texels; keeps a reference to the image, not a copy). Throws
  /// std::invalid_argument for a non-finite rotation, a negative or non-finite scale or colour,
  /// or an image whose size does not match its texels or that holds a negative or non-finite
  /// texel (the loader refuses those with an InputError first).
  explicit EnvironmentLight(const Environment& env);

  /// The radiance arriving from direction `world_dir` (toward the environment; any length but 0),
  /// scale included. A zero or non-finite direction reads a fixed texel rather than failing.
  Color radiance(Vec3 world_dir) const;

  /// Draws a direction from `u` in [0, 1)^2. Empty when the draw lands where the density is 0:
  /// exactly on a pole of an image, or (by float rounding at a texel's edge) in a texel of zero
  /// luminance; both happen with probability about 0 and carry no light.
  std::optional<Sample> sample(Sample2 u) const;

  /// The solid-angle density with which sample() draws `world_dir` (any length but 0): 1 / (4 pi)
  /// for a constant environment; for an image 0 at the poles and in texels of zero luminance.
  float pdf(Vec3 world_dir) const;

  /// The power the environment sends into a scene bounded by a sphere of radius
  /// `scene_radius`: pi r^2 times the integral of radiance over all directions (each direction
  /// lights the disc of the scene's cross-section). What a light sampler that picks lights by
  /// power compares with the other lights' emitted power.
  Color power_estimate(float scene_radius) const;

  /// True when the environment is an image (false: a constant colour).
  bool has_image() const { return m_image != nullptr; }

 private:
  Vec3 to_local(Vec3 world) const;
  Vec3 to_world(Vec3 local) const;

  std::shared_ptr<const EnvironmentImage> m_image;
  Color m_color{0.f};  // constant radiance, scale included
  float m_scale = 1.f;
  float m_cos = 1.f;  // of the rotation about +y
  float m_sin = 0.f;
  Color m_radiance_integral{0.f};                // integral of radiance over the sphere, scale included
  std::optional<Distribution2D> m_distribution;  // over texels, for an image
};

}  // namespace raylab
