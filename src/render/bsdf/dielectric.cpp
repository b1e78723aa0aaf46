// Glass: a dielectric interface between the outside (+z, index 1) and the inside (-z, index
// eta). Smooth, it reflects or refracts along the single Fresnel-chosen delta direction; rough,
// it is Walter et al. 2007 ("Microfacet Models for Refraction through Rough Surfaces") on GGX,
// sampled through the visible normals of wo and choosing reflection or refraction by the
// sampled facet's Fresnel reflectance.
//
// Radiance is what the camera path carries, so light refracted toward the viewer is scaled by
// 1 / eta_rel^2, eta_rel = (index on wi's side) / (index on wo's side): radiance entering the
// denser medium is compressed into a narrower cone (Veach 1997, section 5.2). Hence the
// generalised reciprocity f(wo, wi) / n(wo)^2 = f(wi, wo) / n(wi)^2 for transmission.

#include <cmath>

#include "microfacet.h"
#include "models.h"

namespace raylab::detail {

namespace {

// Relative index eta_t / eta_i seen by a ray arriving along -w: eta entering from outside,
// 1 / eta leaving from inside.
float relative_eta(Vec3 w, float eta) { return w.z > 0.f ? eta : 1.f / eta; }

// Fresnel reflectance at a facet of normal wm (upper side) for the ray arriving along -w, with
// cos_wm = w.wm: from outside when positive, from inside when negative.
float facet_fresnel(float cos_wm, float eta) {
  return cos_wm > 0.f ? fresnel_dielectric(cos_wm, 1.f, eta) : fresnel_dielectric(-cos_wm, eta, 1.f);
}

// Everything about a rough pair (wo, wi) that eval and pdf share: the generalised half vector,
// the facet's Fresnel reflectance, and whether the pair is a reflection.
struct RoughPair {
  Vec3 wm;
  float fresnel = 0.f;
  float eta_rel = 1.f;
  bool reflection = false;
};

// False when no facet joins wo and wi: grazing directions, or a half vector that would face
// away from one of them.
bool rough_pair(float eta, Vec3 wo, Vec3 wi, RoughPair& p) {
  const float cos_o = wo.z;
  const float cos_i = wi.z;
  if (cos_o == 0.f || cos_i == 0.f) return false;
  p.reflection = cos_o * cos_i > 0.f;
  p.eta_rel = relative_eta(wo, eta);
  // Walter's half vector: wo + wi for reflection, wo + eta_rel wi for refraction (the facet
  // normal for which Snell's law takes -wo to wi).
  const Vec3 h = p.reflection ? wo + wi : wo + wi * p.eta_rel;
  const float len2 = length_squared(h);
  if (len2 == 0.f) return false;
  p.wm = h / std::sqrt(len2);
  if (p.wm.z < 0.f) p.wm = -p.wm;
  if (dot(p.wm, wi) * cos_i <= 0.f || dot(p.wm, wo) * cos_o <= 0.f) return false;
  p.fresnel = facet_fresnel(dot(wo, p.wm), eta);
  return true;
}

// (wi.wm + wo.wm / eta_rel)^2: the Jacobian of the refraction map is |wi.wm| over it.
float refraction_denominator(Vec3 wo, Vec3 wi, Vec3 wm, float eta_rel) {
  const float d = dot(wi, wm) + dot(wo, wm) / eta_rel;
  return d * d;
}

std::optional<BsdfSample> sample_smooth(float eta, Color tint, Vec3 wo, float u_lobe) {
  if (wo.z == 0.f) return std::nullopt;
  const bool outside = wo.z > 0.f;
  const float eta_i = outside ? 1.f : eta;
  const float eta_t = outside ? eta : 1.f;
  const float r = fresnel_dielectric(std::fabs(wo.z), eta_i, eta_t);
  BsdfSample s;
  s.delta = true;
  if (u_lobe < r) {
    // f = R delta / |cos|, chosen with probability R: weight 1.
    s.wi = {-wo.x, -wo.y, wo.z};
    s.weight = Color{1.f};
    s.pdf = r;
    return s;
  }
  const Vec3 n{0.f, 0.f, outside ? 1.f : -1.f};
  if (!refract(-wo, n, eta_i / eta_t, s.wi)) return std::nullopt;  // r = 1 there: unreachable
  const float eta_rel = eta_t / eta_i;
  s.weight = tint / (eta_rel * eta_rel);
  s.pdf = 1.f - r;
  s.transmitted = true;
  return s;
}

}  // namespace

bool dielectric_is_smooth(float eta, float alpha) { return ggx::effectively_smooth(alpha) || eta == 1.f; }

Color dielectric_eval(float eta, Color tint, float alpha, Vec3 wo, Vec3 wi) {
  RoughPair p;
  if (dielectric_is_smooth(eta, alpha) || !rough_pair(eta, wo, wi, p)) return Color{0.f};
  if (p.reflection) return Color{p.fresnel * ggx::reflection_f(wo, wi, p.wm, alpha)};
  const float jacobian_terms = std::fabs(dot(wi, p.wm) * dot(wo, p.wm)) /
                               (std::fabs(wi.z * wo.z) * refraction_denominator(wo, wi, p.wm, p.eta_rel));
  const float f = ggx::ndf(p.wm, alpha) * ggx::smith_g2(wo, wi, alpha) * (1.f - p.fresnel) * jacobian_terms;
  return tint * (f / (p.eta_rel * p.eta_rel));
}

float dielectric_pdf(float eta, float alpha, Vec3 wo, Vec3 wi) {
  RoughPair p;
  if (dielectric_is_smooth(eta, alpha) || !rough_pair(eta, wo, wi, p)) return 0.f;
  if (p.reflection) return p.fresnel * ggx::reflection_pdf(wo, p.wm, alpha);
  const float dwm_dwi = std::fabs(dot(wi, p.wm)) / refraction_denominator(wo, wi, p.wm, p.eta_rel);
  return (1.f - p.fresnel) * ggx::visible_normal_pdf(wo, p.wm, alpha) * dwm_dwi;
}

std::optional<BsdfSample> dielectric_sample(float eta, Color tint, float alpha, Vec3 wo, float u_lobe, Sample2 u) {
  if (dielectric_is_smooth(eta, alpha)) return sample_smooth(eta, tint, wo, u_lobe);
  if (wo.z == 0.f) return std::nullopt;
  const Vec3 wm = ggx::sample_visible_normal(wo, alpha, u);
  const float cos_om = dot(wo, wm);
  if (cos_om * wo.z <= 0.f) return std::nullopt;  // a facet seen edge-on (measure zero)
  const float r = facet_fresnel(cos_om, eta);
  const float pdf_wm = ggx::visible_normal_pdf(wo, wm, alpha);
  BsdfSample s;
  if (u_lobe < r) {
    s.wi = reflect(-wo, wm);
    if (s.wi.z * wo.z <= 0.f) return std::nullopt;
    s.weight = Color{ggx::g2_over_g1(wo, s.wi, alpha)};  // R G2 / G1 over R
    s.pdf = r * pdf_wm / (4.f * std::fabs(cos_om));
    return s;
  }
  const float eta_rel = relative_eta(wo, eta);
  if (!refract(-wo, cos_om > 0.f ? wm : -wm, 1.f / eta_rel, s.wi)) return std::nullopt;
  if (s.wi.z * wo.z >= 0.f) return std::nullopt;
  // f |cos wi| / pdf: D, (1 - F) and the Jacobian cancel, leaving G2 / G1 and the radiance
  // scale.
  s.weight = tint * (ggx::g2_over_g1(wo, s.wi, alpha) / (eta_rel * eta_rel));
  s.pdf = (1.f - r) * pdf_wm * std::fabs(dot(s.wi, wm)) / refraction_denominator(wo, s.wi, wm, eta_rel);
  s.transmitted = true;
  return s;
}

}  // namespace raylab::detail
