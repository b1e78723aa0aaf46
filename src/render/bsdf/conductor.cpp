// Metal: exact conductor Fresnel reflectance on a perfect mirror, or on GGX microfacets sampled
// through their visible normals (so a sample's weight is F G2 / G1, never above F).

#include "microfacet.h"
#include "models.h"

namespace raylab::detail {

Color conductor_eval(const ConductorIor& ior, Color tint, float alpha, Vec3 wo, Vec3 wi) {
  if (ggx::effectively_smooth(alpha) || wo.z <= 0.f || wi.z <= 0.f) return Color{0.f};
  Vec3 wm;
  if (!ggx::reflection_half_vector(wo, wi, wm)) return Color{0.f};
  return tint * fresnel_conductor(dot(wo, wm), ior) * ggx::reflection_f(wo, wi, wm, alpha);
}

float conductor_pdf(float alpha, Vec3 wo, Vec3 wi) {
  if (ggx::effectively_smooth(alpha) || wo.z <= 0.f || wi.z <= 0.f) return 0.f;
  Vec3 wm;
  if (!ggx::reflection_half_vector(wo, wi, wm)) return 0.f;
  return ggx::reflection_pdf(wo, wm, alpha);
}

std::optional<BsdfSample> conductor_sample(const ConductorIor& ior, Color tint, float alpha, Vec3 wo, Sample2 u) {
  if (wo.z <= 0.f) return std::nullopt;
  BsdfSample s;
  if (ggx::effectively_smooth(alpha)) {
    s.wi = {-wo.x, -wo.y, wo.z};
    s.weight = tint * fresnel_conductor(wo.z, ior);
    s.pdf = 1.f;
    s.delta = true;
    return s;
  }
  const Vec3 wm = ggx::sample_visible_normal(wo, alpha, u);
  const Vec3 wi = reflect(-wo, wm);
  // A visible facet can still send the reflection below the horizon: that light is lost (the
  // single-scattering model's energy loss at high roughness).
  if (wi.z <= 0.f) return std::nullopt;
  s.wi = wi;
  s.weight = tint * fresnel_conductor(dot(wo, wm), ior) * ggx::g2_over_g1(wo, wi, alpha);
  s.pdf = ggx::reflection_pdf(wo, wm, alpha);
  return s;
}

}  // namespace raylab::detail
