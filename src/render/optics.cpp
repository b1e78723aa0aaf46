#include "raylab/render/optics.h"

#include <algorithm>
#include <cmath>

namespace raylab {

FresnelTerms fresnel_dielectric_sp(float cos_i, float eta_i, float eta_t) {
  cos_i = std::clamp(cos_i, 0.f, 1.f);
  const float sin_t = eta_i / eta_t * std::sqrt(std::max(0.f, 1.f - cos_i * cos_i));
  if (sin_t >= 1.f) return {1.f, 1.f};
  const float cos_t = std::sqrt(std::max(0.f, 1.f - sin_t * sin_t));
  const float r_parallel = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
  const float r_perpendicular = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
  return {r_perpendicular * r_perpendicular, r_parallel * r_parallel};
}

float fresnel_dielectric(float cos_i, float eta_i, float eta_t) {
  const FresnelTerms r = fresnel_dielectric_sp(cos_i, eta_i, eta_t);
  return 0.5f * (r.s + r.p);
}

namespace {

// The closed form of 2 * integral of F(mu) mu dmu over [0, 1] for n > 1. Double precision: its
// terms are large and of opposite signs near n = 1, where the sum is small.
double diffuse_reflectance_denser(double n) {
  const double n2 = n * n;
  const double n4 = n2 * n2;
  return 0.5 + (n - 1.) * (3. * n + 1.) / (6. * (n + 1.) * (n + 1.)) +
         n2 * (n2 - 1.) * (n2 - 1.) / ((n2 + 1.) * (n2 + 1.) * (n2 + 1.)) * std::log((n - 1.) / (n + 1.)) -
         2. * n2 * n * (n2 + 2. * n - 1.) / ((n2 + 1.) * (n4 - 1.)) +
         8. * n4 * (n4 + 1.) / ((n2 + 1.) * (n4 - 1.) * (n4 - 1.)) * std::log(n);
}

// Within this distance of 1 the closed form loses its digits to cancellation (2% wrong at
// 1 + 1e-5); Fdr(1 + d) is about d / 3 there, below 4e-5, so 0 is the better answer.
constexpr double kIndexMatched = 1e-4;

}  // namespace

float fresnel_diffuse_reflectance(float eta) {
  const double n = eta;
  if (std::fabs(n - 1.) < kIndexMatched) return 0.f;
  if (n > 1.) return static_cast<float>(diffuse_reflectance_denser(n));
  return static_cast<float>(1. - n * n * (1. - diffuse_reflectance_denser(1. / n)));
}

Color fresnel_conductor(float cos_i, const ConductorIor& ior) {
  // With the complex relative index m = n + ik, let w = a + ib = sqrt(m^2 - sin_i^2) (= m cos_t;
  // the principal root, the transmitted wave decaying into the metal). The amplitude ratios are
  // r_s = (cos_i - w) / (cos_i + w) and r_p = (m^2 cos_i - w) / (m^2 cos_i + w); their squared
  // moduli are written in real arithmetic, since std::complex's division and root are several
  // times slower (they guard against overflow that cannot happen here).
  cos_i = std::clamp(cos_i, 0.f, 1.f);
  const float cos2 = cos_i * cos_i;
  const float sin2 = 1.f - cos2;
  Color r;
  for (int c = 0; c < 3; ++c) {
    const float n = ior.eta[c];
    const float k = ior.k[c];
    const float re_w2 = n * n - k * k - sin2;                             // Re(w^2)
    const float abs_w2 = std::sqrt(re_w2 * re_w2 + 4.f * n * n * k * k);  // |w|^2 = a^2 + b^2
    const float a = std::sqrt(std::max(0.f, 0.5f * (abs_w2 + re_w2)));    // Re(w)
    const float r_s = (abs_w2 + cos2 - 2.f * a * cos_i) / (abs_w2 + cos2 + 2.f * a * cos_i);
    const float p_term = cos2 * abs_w2 + sin2 * sin2;
    const float p_den = p_term + 2.f * a * cos_i * sin2;  // 0 only for the unphysical n = k = 0
    const float r_p = p_den > 0.f ? r_s * (p_term - 2.f * a * cos_i * sin2) / p_den : r_s;
    r[c] = 0.5f * (r_s + r_p);
  }
  return r;
}

bool refract(Vec3 d, Vec3 n, float eta, Vec3& out) {
  const float cos_i = -dot(d, n);
  const float sin2_t = eta * eta * std::max(0.f, 1.f - cos_i * cos_i);
  if (sin2_t >= 1.f) return false;
  out = d * eta + n * (eta * cos_i - std::sqrt(1.f - sin2_t));
  return true;
}

}  // namespace raylab
