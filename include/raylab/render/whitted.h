#pragma once
/// \file
/// The Whitted integrator: direct Phong lighting with shadow rays, mirror reflection and
/// refraction, recursively, following the rules of the SPD testing procedure.

#include <cstdint>
#include <span>

#include "raylab/core/rng.h"
#include "raylab/geometry/shading.h"
#include "raylab/render/integrator.h"
#include "raylab/render/trace_context.h"

namespace raylab {

/// A light's shadow test decided before shading, for WhittedIntegrator::shade: the packet path
/// traces the shadow rays of a group of hit points together and passes the answers in.
enum class ShadowAnswer : std::uint8_t {
  kTrace = 0,  ///< not decided: shading casts the shadow ray(s) itself
  kVisible,    ///< the single shadow ray toward this light is unobstructed (already counted)
  kBlocked,    ///< the single shadow ray toward this light is blocked (already counted)
};

/// One sample of a light as shading sees it from a point.
struct LightSample {
  Vec3 wi;         ///< unit direction to the light
  float distance;  ///< to the sample point (infinity for directional lights)
  Color radiance;  ///< what arrives from the sample (the light's intensity share, falloff, spot cone)
};

/// A single-sample light's shadow test decided before shading, with the light sample it was
/// decided for, so that shading does not sample the light again.
struct DecidedShadow {
  ShadowAnswer answer = ShadowAnswer::kTrace;  ///< kTrace: nothing decided (`sample` unused)
  LightSample sample{};                        ///< single_sample_shadow_ray's sample
};

/// A surface point as light sampling sees it: where shadow rays start and the normals that
/// decide whether they are cast. Made once per hit (WhittedIntegrator::shading_point) and used
/// for every light and every ray the hit spawns.
struct ShadingPoint {
  Vec3 p;   ///< position
  Vec3 n;   ///< shading normal, toward the arriving ray
  Vec3 ng;  ///< geometric normal, toward the arriving ray
  /// The normals the SPD procedure's rule 10 holds against each light: n and ng, or for
  /// ShadowFacing::kOutward the primitive's own (turned back where the ray arrived from behind).
  Vec3 rule_n, rule_ng;
  /// offset_origins(p, ng): the origins of every ray leaving the hit.
  OffsetOrigins origins;

  /// offset_origin(p, ng, dir), without computing the offset again.
  Vec3 origin_toward(Vec3 dir) const { return origins.toward(dir, ng); }
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
class WhittedIntegrator final : public Integrator {
 public:
  /// "whitted".
  std::string_view name() const override { return "whitted"; }
  /// trace(ctx, ray, 1, RayKind::kPrimary, samples.rng(), feature).
  Color radiance(const TraceContext& ctx, const Ray& ray, SampleSource& samples,
                 PrimaryFeature* feature = nullptr) const override;
  /// True: the packet path gives the same bits (packet_tracing.h).
  bool traces_packets() const override { return true; }

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
  /// light of the scene; a decided answer replaces the sampling and the shadow ray of a
  /// single-sample light, and is given only where single_sample_shadow_ray returned true (with
  /// the sample it gave). trace() is exactly count + intersect + this, so both give the same
  /// bits.
  /// `at` is shading_point(si, ctx.shadow_facing), made by the caller, which may have used it to
  /// cast the decided shadow rays.
  static Color shade(const TraceContext& ctx, const Ray& ray, const SurfaceInteraction& si, const ShadingPoint& at,
                     int depth, Pcg32& rng, std::span<const DecidedShadow> shadows = {},
                     PrimaryFeature* feature = nullptr);

  /// True when shading toward `light` casts one shadow ray at a fixed position and draws no random
  /// numbers: point and directional lights, and area lights whose `samples` round to a 1x1 grid.
  static bool is_single_sample(const Light& light);

  /// Hit `si` as light sampling sees it under the `facing` rule.
  static ShadingPoint shading_point(const SurfaceInteraction& si, ShadowFacing facing);

  /// The shadow ray shading casts toward single-sample `light` from `at`, in `shadow`, and the
  /// light sample it is cast for, in `sample`; false when it casts none (the surface faces away
  /// from the light by the rule `at` was made under, or sits on it).
  static bool single_sample_shadow_ray(const Light& light, const ShadingPoint& at, Ray& shadow, LightSample& sample);

  /// The background seen by a ray leaving in direction `dir`.
  static Color background(const RenderSettings& s, Vec3 dir);
};

}  // namespace raylab
