#pragma once
/// \file
/// Scattering models of the path integrator: built per hit from a material, evaluated, sampled
/// and asked for their density in the local shading frame. Each model lives in its own file
/// under src/render/bsdf/; Bsdf is a small value type that dispatches on the model (no
/// allocation or virtual call per hit).
///
/// Conventions (as pbrt-v4 and Mitsuba 3 use them): directions are unit vectors in the local
/// frame, z along the shading normal, both `wo` (toward the viewer) and `wi` (toward the light)
/// pointing away from the surface. `eval` returns f(wo, wi) without the cosine; `sample`
/// returns the throughput weight f |cos wi| / pdf. Radiance is transported (the camera end of a
/// path): refraction scales by 1 / eta^2 where the ray enters the denser medium.
///
/// Reflectors (diffuse, conductor, plastic) are one-sided: they scatter only when wo.z > 0
/// (an integrator turns the frame toward the viewer for a two-sided surface). The dielectric is
/// two-sided, with +z outside. `alpha` is GGX's width parameter itself (no perceptual
/// remapping); below 1e-3 a lobe is a delta.

#include <optional>
#include <string_view>

#include "raylab/core/vec3.h"
#include "raylab/render/optics.h"
#include "raylab/sampling/pixel_sampler.h"
#include "raylab/scene/metals.h"

namespace raylab {

/// One sampled scattering direction.
struct BsdfSample {
  Vec3 wi;                   ///< sampled direction (local frame), pointing away from the surface
  Color weight{0.f};         ///< f(wo, wi) |cos wi| / pdf: what the path's throughput is multiplied by
  float pdf = 0.f;           ///< solid-angle density of wi; for a delta lobe the probability of choosing it
  bool delta = false;        ///< from a perfectly specular lobe (no light sampling can reach it: no MIS)
  bool transmitted = false;  ///< wi is on the other side of the surface from wo
};

/// A scattering model at one surface point.
class Bsdf {
 public:
  /// Which model.
  enum class Model : unsigned char { kDiffuse, kConductor, kDielectric, kPlastic };

  /// Lambertian reflection of albedo `albedo` (each channel clamped to [0, 1]).
  static Bsdf diffuse(Color albedo);
  /// A metal: Fresnel reflectance from the complex index `ior`, times `tint` (1 for a measured
  /// metal); GGX (Trowbridge-Reitz) microfacets of roughness `alpha` (0 = a perfect mirror).
  static Bsdf conductor(const ConductorIor& ior, float alpha, Color tint = Color{1.f});
  /// A dielectric interface of relative index `eta` (inside / outside, > 0, != 1 for glass;
  /// the shading normal points outside); smooth for alpha = 0 (Fresnel-weighted mirror and
  /// refraction, total internal reflection), else GGX-rough (Walter et al. 2007). `tint`
  /// multiplies the transmitted light.
  static Bsdf dielectric(float eta, float alpha, Color tint = Color{1.f});
  /// A coated diffuse surface (plastic): a Lambertian base of albedo `albedo` under a
  /// dielectric coat of index `eta` and roughness `alpha`; light reflected by the coat plus
  /// light that crosses it twice, with the base's interreflections under the coat (Mitsuba
  /// 0.6's plastic in its nonlinear form). A smooth coat's reflection is a delta lobe outside
  /// eval and pdf, so is_delta() is false.
  static Bsdf plastic(Color albedo, float eta, float alpha);

  /// The model.
  Model model() const { return m_model; }
  /// True when sample() reads its `u_lobe` (models of two lobes: dielectric, plastic).
  bool chooses_lobe() const { return m_model == Model::kDielectric || m_model == Model::kPlastic; }
  /// True when every lobe is a delta (a smooth mirror or smooth glass): eval and pdf are zero,
  /// and light sampling cannot help.
  bool is_delta() const;

  /// f(wo, wi), without the cosine; zero for delta lobes.
  Color eval(Vec3 wo, Vec3 wi) const;
  /// Solid-angle density with which sample() picks wi given wo (zero for delta lobes); its
  /// integral over the sphere is the probability that sample() returns a non-delta direction.
  float pdf(Vec3 wo, Vec3 wi) const;
  /// Picks wi given wo from `u_lobe` (choice between lobes) and `u` (the direction).
  /// std::nullopt when nothing is scattered (wo below a reflector, a sample outside the lobe).
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Sample2 u) const;

 private:
  // 52 bytes, copied per hit: the parameters of every model side by side rather than a union,
  // since they are few and the switch in each call reads only its own.
  Model m_model = Model::kDiffuse;
  float m_alpha = 0.f;         // GGX roughness (conductor, dielectric, plastic's coat)
  float m_eta = 1.f;           // dielectric, plastic: index inside / outside
  float m_fdr_internal = 0.f;  // plastic: diffuse Fresnel reflectance of the coat from below
  Color m_color{0.f};          // diffuse, plastic: albedo; conductor, dielectric: tint
  ConductorIor m_ior;          // conductor: complex index
};

}  // namespace raylab
