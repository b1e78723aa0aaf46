#pragma once
/// \file
/// The Whitted integrator: direct Phong lighting with shadow rays, mirror reflection and
/// refraction, recursively, following the rules of the SPD testing procedure.

#include <cstdint>
#include <span>

#include "raylab/accel/accelerator.h"
#include "raylab/core/rng.h"
#include "raylab/core/stats.h"
#include "raylab/geometry/shading.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Which normal decides whether a surface faces a light (the SPD testing procedure's rule 10: "a
/// shadow ray is not generated if the surface normal points away from the light"). The rule can
/// be read two ways, and published ray counts differ by which one their tracer followed.
enum class ShadowFacing : std::uint8_t {
  /// The normal turned toward the arriving ray: a surface is lit from the side the ray sees. At a
  /// hit on the inside of a glass sphere, shadow rays go toward the lights on the inner side of
  /// the tangent plane there.
  kViewer = 0,
  /// The primitive's own (outward) normal, whichever side the ray came from. At a hit on the
  /// inside of a glass sphere no shadow ray goes toward a light on the inner side of the tangent
  /// plane (behind the surface, seen from outside); one goes toward each light on the outer side,
  /// and is counted, but adds nothing: the side the ray sees faces away from that light.
  kOutward,
};

/// Everything one thread needs to trace: the scene, its structure, whether to count traversal
/// work, where to count, and the facing rule for shadow rays.
struct TraceContext {
  const Scene& scene;
  const Accelerator& accel;
  RenderStats& stats;
  bool count_traversal = false;                        ///< use the counted kernels (slower; for --stats)
  ShadowFacing shadow_facing = ShadowFacing::kViewer;  ///< which normal must face a light for a shadow ray
};

/// What a primary ray met first: the features adaptive sampling compares between samples.
struct PrimaryFeature {
  std::int32_t object = -1;    ///< object id of the first hit; -1 when the ray left the scene
  Vec3 normal{0.f, 0.f, 0.f};  ///< unit shading normal there (zero when nothing was hit)
};

/// A light's shadow test decided before shading, for WhittedIntegrator::shade: the packet path
/// traces the shadow rays of a group of hit points together and passes the answers in.
enum class ShadowAnswer : std::uint8_t {
  kTrace = 0,  ///< not decided: shading casts the shadow ray(s) itself
  kVisible,    ///< the single shadow ray toward this light is unobstructed (already counted)
  kBlocked,    ///< the single shadow ray toward this light is blocked (already counted)
};

/// Whitted-style recursive ray tracer.
///  - Depth: a ray at depth `max_depth` is the last; secondary rays start at depth 2.
///  - Shadow rays are cast only when the surface faces the light (N.L > 0), N chosen by
///    TraceContext::shadow_facing; light adds only to the side the ray sees.
///  - Reflectors (reflectivity > 0) spawn a mirror reflection ray.
///  - Transmitters (transmittance > 0) spawn a reflection ray at every hit and a refraction ray
///    unless total internal reflection occurs (SPD testing procedure, rules 8 and 9; a dielectric
///    interface always reflects). With Material::fresnel the exact unpolarised Fresnel equations
///    split the transmittance between the two (reflection = reflectivity + T F, refraction =
///    T (1 - F)); without it the reflection ray carries the reflectivity alone. Total internal
///    reflection sends all of T to the reflection ray.
///  - Area lights: `Light::samples` stratified shadow rays, randomised by `rng`.
class WhittedIntegrator {
 public:
  /// The deepest ray tree any render traces, whatever RenderSettings::max_depth says (the scene
  /// files and the command line accept 1 to 64 as well): the integrator recurses once per level.
  static constexpr int kMaxDepth = 64;

  /// Radiance arriving along `ray` (ray kind `kind`, at depth `depth` >= 1). When `feature` is
  /// given, it receives what `ray` itself hit (not what later bounces hit).
  static Color trace(const TraceContext& ctx, Ray ray, int depth, RayKind kind, Pcg32& rng,
                     PrimaryFeature* feature = nullptr);

  /// What trace() does once the closest hit of `ray` is known: the radiance leaving surface
  /// point `si` (found by `ray`, of depth `depth`) back along `ray`, reflection and refraction
  /// included. `shadows` is empty (every light casts its own shadow rays) or holds one answer per
  /// light of the scene; a decided answer replaces the shadow ray of a single-sample light (see
  /// single_sample_shadow_ray), and is used only where that function returns true. trace() is
  /// exactly count + intersect + this, so both give the same bits.
  static Color shade(const TraceContext& ctx, const Ray& ray, const SurfaceInteraction& si, int depth, Pcg32& rng,
                     std::span<const ShadowAnswer> shadows = {}, PrimaryFeature* feature = nullptr);

  /// True when shading toward `light` casts one shadow ray at a fixed position and draws no random
  /// numbers: point and directional lights, and area lights whose `samples` round to a 1x1 grid.
  static bool is_single_sample(const Light& light);

  /// The shadow ray shading casts toward single-sample `light` from `si`, in `shadow`; false when
  /// it casts none (the surface faces away from the light by the `facing` rule, or sits on it).
  static bool single_sample_shadow_ray(const Light& light, const SurfaceInteraction& si, ShadowFacing facing,
                                       Ray& shadow);

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
