#pragma once
// Internal to src/render/bsdf/: the GGX (Trowbridge-Reitz) microfacet distribution shared by
// the rough conductor, the rough dielectric and plastic's rough coat. Isotropic, of width
// `alpha` (the slope parameter, not a perceptual roughness: no squaring here), in the local
// frame with the macro normal along +z. Inline: these run several times per scattering event.
//
// Masking-shadowing is Smith's, height-correlated (Heitz 2014, "Understanding the
// masking-shadowing function in microfacet-based BRDFs", eq. 99): G2 = 1 / (1 + L(wo) + L(wi)).
// It is closer to measured microsurfaces than the separable G1 G1, which counts a facet hidden
// from both directions twice. The same form serves transmission, as pbrt-v4 and Mitsuba 3 do.
//
// Visible normals are sampled on the spherical cap of Dupuy & Benyoub 2023 ("Sound and
// Efficient Sampling of the Visible Normals of Trowbridge-Reitz Distributions"): the stretched
// configuration reduces GGX to alpha = 1, where the visible normals are the half vectors of
// the view direction and points uniform on a spherical cap.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "raylab/core/vec3.h"
#include "raylab/sampling/pixel_sampler.h"

namespace raylab::ggx {

/// Below this alpha a lobe is treated as a perfect mirror (or perfect refraction): the NDF's
/// peak 1 / (pi alpha^2) would exceed 3e5 and float could no longer resolve the lobe.
inline constexpr float kSmoothAlpha = 1e-3f;

/// True when a lobe of width `alpha` is a delta lobe.
inline bool effectively_smooth(float alpha) { return alpha < kSmoothAlpha; }

/// The distribution of normals D(wm), normalised so that the integral of D(wm) cos(wm) over
/// the hemisphere is 1; 0 for wm below the macro surface.
inline float ndf(Vec3 wm, float alpha) {
  if (wm.z <= 0.f) return 0.f;
  const float a2 = alpha * alpha;
  // D = 1 / (pi a^2 cos^4 (1 + tan^2 / a^2)^2), with cos^4 (1 + tan^2 / a^2)^2 written without
  // the tangent, which is infinite at the horizon.
  const float t = (wm.x * wm.x + wm.y * wm.y) / a2 + wm.z * wm.z;
  return 1.f / (std::numbers::pi_v<float> * a2 * t * t);
}

/// Smith's Lambda(w) = (sqrt(1 + alpha^2 tan^2(w)) - 1) / 2, the same from either side of the
/// surface; infinite at the horizon.
inline float smith_lambda(Vec3 w, float alpha) {
  const float z2 = w.z * w.z;
  if (z2 == 0.f) return std::numeric_limits<float>::infinity();
  const float tan2 = (w.x * w.x + w.y * w.y) / z2;
  return 0.5f * (std::sqrt(1.f + alpha * alpha * tan2) - 1.f);
}

/// Smith's masking G1(w): the fraction of the microsurface facing w that w sees.
inline float smith_g1(Vec3 w, float alpha) { return 1.f / (1.f + smith_lambda(w, alpha)); }

/// Height-correlated masking-shadowing G2(wo, wi).
inline float smith_g2(Vec3 wo, Vec3 wi, float alpha) {
  return 1.f / (1.f + smith_lambda(wo, alpha) + smith_lambda(wi, alpha));
}

/// Density of visible normals D_w(wm) = G1(w) max(0, w.wm) D(wm) / |cos w|, with w taken on
/// the upper side (a direction below the surface sees the same facets from their back).
inline float visible_normal_pdf(Vec3 w, Vec3 wm, float alpha) {
  const float cos_w = std::fabs(w.z);
  const float cos_wm = w.z >= 0.f ? dot(w, wm) : -dot(w, wm);
  if (cos_w == 0.f || cos_wm <= 0.f) return 0.f;
  return smith_g1(w, alpha) * cos_wm * ndf(wm, alpha) / cos_w;
}

/// A normal drawn with density visible_normal_pdf(w, ., alpha) from `u`; always on the upper
/// side (wm.z >= 0), whichever side `w` is on.
inline Vec3 sample_visible_normal(Vec3 w, float alpha, Sample2 u) {
  const Vec3 up = w.z < 0.f ? -w : w;
  // Stretch to alpha = 1, where the visible normals are wh + (a point uniform on the sphere's
  // cap z > -wh.z), normalised.
  const Vec3 wh = normalize(Vec3{alpha * up.x, alpha * up.y, up.z});
  const float phi = 2.f * std::numbers::pi_v<float> * u.x;
  const float z = (1.f - u.y) * (1.f + wh.z) - wh.z;
  const float r = std::sqrt(std::max(0.f, 1.f - z * z));
  const Vec3 h = Vec3{r * std::cos(phi), r * std::sin(phi), z} + wh;
  // Unstretch: normals transform by the inverse transpose of the stretch.
  const Vec3 m{alpha * h.x, alpha * h.y, std::max(h.z, 0.f)};
  const float len2 = length_squared(m);
  return len2 > 0.f ? m / std::sqrt(len2) : Vec3{0.f, 0.f, 1.f};
}

/// The half vector of a reflection pair (wo, wi on the same side), turned to the upper side;
/// false when wo = -wi.
inline bool reflection_half_vector(Vec3 wo, Vec3 wi, Vec3& wm) {
  const Vec3 h = wo + wi;
  const float len2 = length_squared(h);
  if (len2 == 0.f) return false;
  wm = h / std::sqrt(len2);
  if (wm.z < 0.f) wm = -wm;
  return true;
}

/// The reflection lobe without its Fresnel factor, D(wm) G2(wo, wi) / (4 |cos wo| |cos wi|),
/// for wo and wi on the same side and wm their half vector.
inline float reflection_f(Vec3 wo, Vec3 wi, Vec3 wm, float alpha) {
  return ndf(wm, alpha) * smith_g2(wo, wi, alpha) / (4.f * std::fabs(wo.z) * std::fabs(wi.z));
}

/// Solid-angle density of wi = reflect(-wo, wm) when wm is a visible normal drawn from wo:
/// D_wo(wm) / (4 |wo.wm|), the Jacobian of the reflection map.
inline float reflection_pdf(Vec3 wo, Vec3 wm, float alpha) {
  const float cos_om = std::fabs(dot(wo, wm));
  return cos_om > 0.f ? visible_normal_pdf(wo, wm, alpha) / (4.f * cos_om) : 0.f;
}

/// G2(wo, wi) / G1(wo): the weight f |cos wi| / pdf of a direction drawn through a visible
/// normal, less Fresnel (and the radiance scale of a refraction); D and the Jacobians cancel.
inline float g2_over_g1(Vec3 wo, Vec3 wi, float alpha) {
  const float lambda_o = smith_lambda(wo, alpha);
  return (1.f + lambda_o) / (1.f + lambda_o + smith_lambda(wi, alpha));
}

}  // namespace raylab::ggx
