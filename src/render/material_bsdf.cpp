#include "material_bsdf.h"

#include <algorithm>
#include <cmath>

namespace raylab::detail {
namespace {

// GGX alpha from perceptual roughness (glTF's convention). The BSDFs decide themselves below
// which alpha a lobe is a delta (ggx::effectively_smooth).
float alpha_of(float roughness) { return roughness * roughness; }

// A conductor index with normal-incidence reflectance `f0` in each channel: a real index
// (k = 0) with ((n - 1) / (n + 1))^2 = f0. The Fresnel curve then rises to 1 at grazing angles,
// which is how a metal behaves; the artist's colour is exact where it matters most.
ConductorIor ior_for_reflectance(Color f0) {
  auto n = [](float r) {
    const float s = std::sqrt(std::clamp(r, 0.f, 0.9999f));
    return (1.f + s) / (1.f - s);
  };
  return {Color{n(f0.x), n(f0.y), n(f0.z)}, Color{0.f}};
}

// Whitted's Phong material under the path integrator: glass stays glass, a mirror a smooth
// metal, a diffuse surface with highlights or a reflection a coated diffuse surface whose coat
// roughness follows the Phong exponent (alpha = sqrt(2 / (n + 2)), the Phong-to-microfacet
// correspondence of Walter et al. 2007).
Bsdf phong_bsdf(const Material& m, Color base) {
  if (m.transmittance > 0.f)
    return Bsdf::dielectric(std::max(m.ior, 1.0001f), 0.f, Color{std::min(1.f, m.transmittance)});
  const Color diffuse = base * std::clamp(m.kd, 0.f, 1.f);
  if (m.reflectivity >= 0.5f || (m.reflectivity > 0.f && !(max_component(diffuse) > 0.f))) {
    return Bsdf::conductor(ior_for_reflectance(Color{std::min(1.f, m.reflectivity)}), 0.f);
  }
  if (m.reflectivity > 0.f) return Bsdf::plastic(diffuse, 1.5f, 0.f);
  if (m.ks > 0.f) return Bsdf::plastic(diffuse, 1.5f, std::sqrt(2.f / (std::max(m.shininess, 0.f) + 2.f)));
  return Bsdf::diffuse(diffuse);
}

}  // namespace

Bsdf material_bsdf(const Material& m, const MaterialPoint& at, float u_mix) {
  const Color base = at.base;
  const float alpha = alpha_of(at.roughness);
  switch (m.model) {
    case MaterialModel::kPhong:
      return phong_bsdf(m, base);
    case MaterialModel::kDiffuse:
      return Bsdf::diffuse(base);
    case MaterialModel::kConductor:
      return Bsdf::conductor(ConductorIor{m.conductor_eta, m.conductor_k}, alpha, base);
    case MaterialModel::kDielectric:
      return Bsdf::dielectric(std::max(m.ior, 1.0001f), alpha, base);
    case MaterialModel::kPlastic:
      return Bsdf::plastic(base, std::max(m.ior, 1.0001f), alpha);
    case MaterialModel::kMetallicRoughness: {
      // glTF 2.0's model: a metal of reflectance `base` with probability `metallic`, else a
      // dielectric: transmitting with probability `transmission`, else a coated diffuse base.
      if (u_mix < at.metallic) return Bsdf::conductor(ior_for_reflectance(base), alpha);
      const float rest = (u_mix - at.metallic) / std::max(1.f - at.metallic, 1e-6f);
      const float ior = std::max(m.ior, 1.0001f);
      if (rest < at.transmission) return Bsdf::dielectric(ior, alpha, base);
      return Bsdf::plastic(base, ior, alpha);
    }
  }
  return Bsdf::diffuse(base);
}

}  // namespace raylab::detail
