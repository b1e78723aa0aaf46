#pragma once
// Internal to src/render/bsdf/: the scattering models that Bsdf (bsdf.cpp) dispatches to, one
// file each, as free functions of the model's parameters and the local directions. Each follows
// the contract of Bsdf::eval, Bsdf::pdf and Bsdf::sample (include/raylab/render/bsdf.h).
//
// Reflectors (diffuse, conductor, plastic) are one-sided: they scatter only when wo is above
// the surface (wo.z > 0), and only into the upper hemisphere. The dielectric is two-sided: +z is
// outside (index 1), -z inside (index eta).

#include <optional>

#include "raylab/core/vec3.h"
#include "raylab/render/bsdf.h"
#include "raylab/render/optics.h"
#include "raylab/sampling/pixel_sampler.h"

namespace raylab::detail {

// Lambertian reflection, diffuse.cpp. Its sampling is plastic's base lobe too.

/// albedo / pi above the surface, 0 elsewhere.
Color diffuse_eval(Color albedo, Vec3 wo, Vec3 wi);
/// cos(wi) / pi above the surface, 0 elsewhere.
float diffuse_pdf(Vec3 wo, Vec3 wi);
/// A direction over the upper hemisphere with density cos / pi (Shirley & Chiu's concentric
/// disk lifted onto the hemisphere, which keeps strata of `u` compact); wi.z may be 0 only on
/// the disk's rim.
Vec3 sample_cosine_hemisphere(Sample2 u);
/// A cosine-distributed direction; its weight is the albedo.
std::optional<BsdfSample> diffuse_sample(Color albedo, Vec3 wo, Sample2 u);

// Metal, conductor.cpp: a perfect mirror when ggx::effectively_smooth(alpha), else GGX.

/// f(wo, wi) of the rough conductor; 0 when smooth.
Color conductor_eval(const ConductorIor& ior, Color tint, float alpha, Vec3 wo, Vec3 wi);
/// Density of conductor_sample; 0 when smooth.
float conductor_pdf(float alpha, Vec3 wo, Vec3 wi);
/// The mirror direction (delta) or a reflection through a visible normal.
std::optional<BsdfSample> conductor_sample(const ConductorIor& ior, Color tint, float alpha, Vec3 wo, Sample2 u);

// Glass, dielectric.cpp: smooth (Fresnel-chosen delta reflection or refraction) or GGX-rough
// (Walter et al. 2007).

/// True when the interface has only delta lobes: smooth, or index-matched (eta = 1, where light
/// passes straight through and the rough model's half vector is undefined).
bool dielectric_is_smooth(float eta, float alpha);
/// f(wo, wi), radiance-scaled on transmission; 0 when smooth.
Color dielectric_eval(float eta, Color tint, float alpha, Vec3 wo, Vec3 wi);
/// Density of dielectric_sample over the whole sphere; 0 when smooth.
float dielectric_pdf(float eta, float alpha, Vec3 wo, Vec3 wi);
/// Reflection or transmission chosen by `u_lobe` against the Fresnel reflectance (of the
/// macro surface when smooth, of the sampled microfacet when rough).
std::optional<BsdfSample> dielectric_sample(float eta, Color tint, float alpha, Vec3 wo, float u_lobe, Sample2 u);

// Coated diffuse, plastic.cpp.

/// Parameters of the plastic model.
struct Plastic {
  Color albedo;        ///< the Lambertian base's albedo
  float eta;           ///< the coat's index (relative to outside)
  float alpha;         ///< the coat's GGX roughness; smooth below ggx::kSmoothAlpha
  float fdr_internal;  ///< fresnel_diffuse_reflectance(1 / eta): the coat's reflectance to
                       ///< diffuse light from below
};
/// The coat's reflection (rough only) plus the base seen through the coat.
Color plastic_eval(const Plastic& p, Vec3 wo, Vec3 wi);
/// Density of plastic_sample's non-delta outcomes.
float plastic_pdf(const Plastic& p, Vec3 wo, Vec3 wi);
/// The coat's reflection or the base's cosine lobe, chosen by `u_lobe`.
std::optional<BsdfSample> plastic_sample(const Plastic& p, Vec3 wo, float u_lobe, Sample2 u);

}  // namespace raylab::detail
