// Coated diffuse (plastic): a dielectric coat of index eta, smooth or GGX-rough, over a
// Lambertian base of albedo rho, after Mitsuba 0.6's smooth/rough "plastic" in its nonlinear
// form (which follows Weidlich & Wilkie 2007). The base is seen through the coat:
//
//   f_base = (1 - F(cos wi)) (1 - F(cos wo)) rho / (pi eta^2 (1 - rho Fdr_int))
//
// Light crosses the coat down with 1 - F(cos wi) and up with 1 - F(cos wo); 1 / eta^2 is the
// radiance scale of leaving the denser coat; and of the light the base sends back up, the coat
// returns the fraction Fdr_int (its reflectance to diffuse light from below) to the base, which
// reflects rho of it again: the geometric series sum (rho Fdr_int)^k gives the denominator.
// With a white base (rho = 1) and a smooth coat the model conserves energy exactly, since
// (1 - Fdr_ext) / eta^2 = 1 - Fdr_int. The rough coat attenuates the base with the smooth
// Fresnel factors too, an approximation (Mitsuba tabulates the rough coat's transmittance).

#include <numbers>

#include "microfacet.h"
#include "models.h"

namespace raylab::detail {

namespace {

float coat_fresnel(const Plastic& p, float cos_theta) { return fresnel_dielectric(cos_theta, 1.f, p.eta); }

// Probability of sampling the coat's reflection rather than the base: the share of the coat's
// reflectance at wo in an estimate of the total, F + (1 - F) mean(rho). Where the base is black
// only the coat is sampled.
float coat_probability(const Plastic& p, float cos_o) {
  const float f = coat_fresnel(p, cos_o);
  const float base = (1.f - f) * (p.albedo.x + p.albedo.y + p.albedo.z) / 3.f;
  const float total = f + base;
  return total > 0.f ? f / total : 1.f;
}

}  // namespace

Color plastic_eval(const Plastic& p, Vec3 wo, Vec3 wi) {
  if (wo.z <= 0.f || wi.z <= 0.f) return Color{0.f};
  const float through_coat =
      (1.f - coat_fresnel(p, wi.z)) * (1.f - coat_fresnel(p, wo.z)) / (std::numbers::pi_v<float> * p.eta * p.eta);
  Color f = p.albedo / (Color{1.f} - p.albedo * p.fdr_internal) * through_coat;
  Vec3 wm;
  if (!ggx::effectively_smooth(p.alpha) && ggx::reflection_half_vector(wo, wi, wm)) {
    f += Color{coat_fresnel(p, dot(wo, wm)) * ggx::reflection_f(wo, wi, wm, p.alpha)};
  }
  return f;
}

float plastic_pdf(const Plastic& p, Vec3 wo, Vec3 wi) {
  if (wo.z <= 0.f || wi.z <= 0.f) return 0.f;
  const float p_coat = coat_probability(p, wo.z);
  float pdf = (1.f - p_coat) * diffuse_pdf(wo, wi);
  Vec3 wm;
  if (!ggx::effectively_smooth(p.alpha) && ggx::reflection_half_vector(wo, wi, wm)) {
    pdf += p_coat * ggx::reflection_pdf(wo, wm, p.alpha);
  }
  return pdf;
}

std::optional<BsdfSample> plastic_sample(const Plastic& p, Vec3 wo, float u_lobe, Sample2 u) {
  if (wo.z <= 0.f) return std::nullopt;
  const float p_coat = coat_probability(p, wo.z);
  BsdfSample s;
  if (u_lobe < p_coat) {
    if (ggx::effectively_smooth(p.alpha)) {
      s.wi = {-wo.x, -wo.y, wo.z};
      s.weight = Color{coat_fresnel(p, wo.z) / p_coat};
      s.pdf = p_coat;
      s.delta = true;
      return s;
    }
    s.wi = reflect(-wo, ggx::sample_visible_normal(wo, p.alpha, u));
  } else {
    s.wi = sample_cosine_hemisphere(u);
  }
  if (s.wi.z <= 0.f) return std::nullopt;
  // Either lobe could have produced wi: the one-sample mixture weight uses the summed f and pdf.
  s.pdf = plastic_pdf(p, wo, s.wi);
  if (s.pdf <= 0.f) return std::nullopt;
  s.weight = plastic_eval(p, wo, s.wi) * (s.wi.z / s.pdf);
  return s;
}

}  // namespace raylab::detail
