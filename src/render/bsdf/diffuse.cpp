// Lambertian reflection: f = albedo / pi, sampled in proportion to cos(wi), so every sample's
// weight is exactly the albedo.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "models.h"

namespace raylab::detail {

namespace {
constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInvPi = std::numbers::inv_pi_v<float>;
}  // namespace

Color diffuse_eval(Color albedo, Vec3 wo, Vec3 wi) {
  if (wo.z <= 0.f || wi.z <= 0.f) return Color{0.f};
  return albedo * kInvPi;
}

float diffuse_pdf(Vec3 wo, Vec3 wi) {
  if (wo.z <= 0.f || wi.z <= 0.f) return 0.f;
  return wi.z * kInvPi;
}

Vec3 sample_cosine_hemisphere(Sample2 u) {
  // Malley: a point uniform on the unit disk, lifted onto the hemisphere, has density cos / pi.
  // The disk point comes from Shirley & Chiu's concentric map, which sends squares to rings
  // without the polar map's squeeze at the centre.
  const float a = 2.f * u.x - 1.f;
  const float b = 2.f * u.y - 1.f;
  if (a == 0.f && b == 0.f) return {0.f, 0.f, 1.f};
  float r = 0.f;
  float phi = 0.f;
  if (std::fabs(a) > std::fabs(b)) {
    r = a;
    phi = 0.25f * kPi * (b / a);
  } else {
    r = b;
    phi = 0.5f * kPi - 0.25f * kPi * (a / b);
  }
  const float x = r * std::cos(phi);
  const float y = r * std::sin(phi);
  return {x, y, std::sqrt(std::max(0.f, 1.f - x * x - y * y))};
}

std::optional<BsdfSample> diffuse_sample(Color albedo, Vec3 wo, Sample2 u) {
  if (wo.z <= 0.f) return std::nullopt;
  const Vec3 wi = sample_cosine_hemisphere(u);
  if (wi.z <= 0.f) return std::nullopt;
  BsdfSample s;
  s.wi = wi;
  s.weight = albedo;
  s.pdf = wi.z * kInvPi;
  return s;
}

}  // namespace raylab::detail
