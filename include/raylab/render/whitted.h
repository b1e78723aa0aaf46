#pragma once
/// \file
/// The Whitted integrator: direct Phong lighting with shadow rays, mirror reflection and
/// refraction, recursively, following the rules of the SPD testing procedure.

#include <cstdint>

#include "raylab/accel/accelerator.h"
#include "raylab/core/rng.h"
#include "raylab/core/stats.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Everything one thread needs to trace: the scene, its structure, whether to count traversal
/// work, and where to count.
struct TraceContext {
  const Scene& scene;
  const Accelerator& accel;
  RenderStats& stats;
  bool count_traversal = false;  ///< use the counted kernels (slower; for --stats)
};

/// What a primary ray met first: the features adaptive sampling compares between samples.
struct PrimaryFeature {
  std::int32_t object = -1;    ///< object id of the first hit; -1 when the ray left the scene
  Vec3 normal{0.f, 0.f, 0.f};  ///< unit shading normal there (zero when nothing was hit)
};

/// Whitted-style recursive ray tracer.
///  - Depth: a ray at depth `max_depth` is the last; secondary rays start at depth 2.
///  - Shadow rays are cast only when the surface faces the light (N.L > 0).
///  - Dielectrics (transmittance > 0): reflection and refraction weighted by the exact Fresnel
///    equations (unpolarised); total internal reflection sends all the weight to reflection.
///  - Area lights: `Light::samples` stratified shadow rays, randomised by `rng`.
class WhittedIntegrator {
 public:
  /// Radiance arriving along `ray` (ray kind `kind`, at depth `depth` >= 1). When `feature` is
  /// given, it receives what `ray` itself hit (not what later bounces hit).
  static Color trace(const TraceContext& ctx, Ray ray, int depth, RayKind kind, Pcg32& rng,
                     PrimaryFeature* feature = nullptr);

  /// The background seen by a ray leaving in direction `dir`.
  static Color background(const RenderSettings& s, Vec3 dir);

  /// Fresnel reflectance of an unpolarised ray at cosine `cos_i` (> 0) going from index `eta_i`
  /// into `eta_t`; 1 for total internal reflection.
  static float fresnel_dielectric(float cos_i, float eta_i, float eta_t);

  /// Refracts unit direction `d` through unit normal `n` (facing against `d`) with relative index
  /// eta = eta_i / eta_t; returns false on total internal reflection.
  static bool refract(Vec3 d, Vec3 n, float eta, Vec3& out);
};

}  // namespace raylab
