// Bsdf: the constructors, which clamp their parameters into the models' domains, and the
// dispatch by model to the free functions of src/render/bsdf/ (one switch per call, no virtual
// call).

#include "raylab/render/bsdf.h"

#include "microfacet.h"
#include "models.h"

namespace raylab {

namespace {

// Smallest index accepted: a zero or negative index has no physical meaning and would divide
// by zero.
constexpr float kMinEta = 1e-3f;

Color clamp01(Color c) { return min(max(c, Color{0.f}), Color{1.f}); }

float clamp_alpha(float alpha) { return alpha > 0.f ? alpha : 0.f; }  // NaN too gives 0

float clamp_eta(float eta) { return eta > kMinEta ? eta : kMinEta; }

}  // namespace

Bsdf Bsdf::diffuse(Color albedo) {
  Bsdf b;
  b.m_model = Model::kDiffuse;
  b.m_color = clamp01(albedo);
  return b;
}

Bsdf Bsdf::conductor(const ConductorIor& ior, float alpha, Color tint) {
  Bsdf b;
  b.m_model = Model::kConductor;
  b.m_ior = ior;
  b.m_alpha = clamp_alpha(alpha);
  b.m_color = tint;
  return b;
}

Bsdf Bsdf::dielectric(float eta, float alpha, Color tint) {
  Bsdf b;
  b.m_model = Model::kDielectric;
  b.m_eta = clamp_eta(eta);
  b.m_alpha = clamp_alpha(alpha);
  b.m_color = tint;
  return b;
}

Bsdf Bsdf::plastic(Color albedo, float eta, float alpha) {
  Bsdf b;
  b.m_model = Model::kPlastic;
  b.m_color = clamp01(albedo);
  b.m_eta = clamp_eta(eta);
  b.m_alpha = clamp_alpha(alpha);
  b.m_fdr_internal = fresnel_diffuse_reflectance(1.f / b.m_eta);
  return b;
}

bool Bsdf::is_delta() const {
  switch (m_model) {
    case Model::kDiffuse:
    case Model::kPlastic:
      return false;
    case Model::kConductor:
      return ggx::effectively_smooth(m_alpha);
    case Model::kDielectric:
      return detail::dielectric_is_smooth(m_eta, m_alpha);
  }
  return false;
}

Color Bsdf::eval(Vec3 wo, Vec3 wi) const {
  switch (m_model) {
    case Model::kDiffuse:
      return detail::diffuse_eval(m_color, wo, wi);
    case Model::kConductor:
      return detail::conductor_eval(m_ior, m_color, m_alpha, wo, wi);
    case Model::kDielectric:
      return detail::dielectric_eval(m_eta, m_color, m_alpha, wo, wi);
    case Model::kPlastic:
      return detail::plastic_eval({m_color, m_eta, m_alpha, m_fdr_internal}, wo, wi);
  }
  return Color{0.f};
}

float Bsdf::pdf(Vec3 wo, Vec3 wi) const {
  switch (m_model) {
    case Model::kDiffuse:
      return detail::diffuse_pdf(wo, wi);
    case Model::kConductor:
      return detail::conductor_pdf(m_alpha, wo, wi);
    case Model::kDielectric:
      return detail::dielectric_pdf(m_eta, m_alpha, wo, wi);
    case Model::kPlastic:
      return detail::plastic_pdf({m_color, m_eta, m_alpha, m_fdr_internal}, wo, wi);
  }
  return 0.f;
}

std::optional<BsdfSample> Bsdf::sample(Vec3 wo, float u_lobe, Sample2 u) const {
  switch (m_model) {
    case Model::kDiffuse:
      return detail::diffuse_sample(m_color, wo, u);
    case Model::kConductor:
      return detail::conductor_sample(m_ior, m_color, m_alpha, wo, u);
    case Model::kDielectric:
      return detail::dielectric_sample(m_eta, m_color, m_alpha, wo, u_lobe, u);
    case Model::kPlastic:
      return detail::plastic_sample({m_color, m_eta, m_alpha, m_fdr_internal}, wo, u_lobe, u);
  }
  return std::nullopt;
}

}  // namespace raylab
