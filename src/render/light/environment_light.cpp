#include "raylab/render/environment_light.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace raylab {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInvFourPi = 0.25f * std::numbers::inv_pi_v<float>;
constexpr double kPiD = std::numbers::pi;

// cos and sin of a turn of `degrees`, exact for whole quarter turns: 90 degrees in float radians
// is not pi / 2, and a cos of -4e-8 would move every direction off the axis it belongs on.
std::pair<float, float> turn(float degrees) {
  double d = std::fmod(static_cast<double>(degrees), 360.0);
  if (d < 0.0) d += 360.0;
  if (d == 0.0) return {1.f, 0.f};
  if (d == 90.0) return {0.f, 1.f};
  if (d == 180.0) return {-1.f, 0.f};
  if (d == 270.0) return {0.f, -1.f};
  const double r = d * kPiD / 180.0;
  return {static_cast<float>(std::cos(r)), static_cast<float>(std::sin(r))};
}

bool finite_non_negative(Color c) { return is_finite(c) && c.x >= 0.f && c.y >= 0.f && c.z >= 0.f; }

// (u, v) of a direction in the environment's frame, as scene/environment.h defines them. Both
// angles come from atan2, which needs no unit vector and stays accurate near the poles, where
// acos(y) loses digits.
Sample2 lat_long_uv(Vec3 d) {
  const float rho = std::sqrt(d.x * d.x + d.z * d.z);
  const float phi = std::atan2(d.z, d.x);
  const float theta = std::atan2(rho, d.y);
  return {0.5f + phi * (0.5f * std::numbers::inv_pi_v<float>), theta * std::numbers::inv_pi_v<float>};
}

// Uniform over the unit sphere: height y uniform in [-1, 1] (Archimedes' hat-box theorem).
Vec3 uniform_sphere(Sample2 u) {
  const float y = 1.f - 2.f * u.y;
  const float r = std::sqrt(std::max(0.f, 1.f - y * y));
  const float phi = 2.f * kPi * u.x;
  return {r * std::cos(phi), y, r * std::sin(phi)};
}

// The solid angle of one texel of row j of a lat-long image of `width` x `height`: its share of
// the band between theta = pi j / height and pi (j + 1) / height. Never 0, not even at a pole.
double texel_solid_angle(int j, int width, int height) {
  const double band = std::cos(kPiD * j / height) - std::cos(kPiD * (j + 1) / height);
  return 2.0 * kPiD / width * band;
}

void check_image(const EnvironmentImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.texels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
    throw std::invalid_argument("environment image '" + image.path + "': " + std::to_string(image.texels.size()) +
                                " texels for " + std::to_string(image.width) + " x " + std::to_string(image.height));
  }
}

}  // namespace

EnvironmentLight::EnvironmentLight(const Environment& env) : m_image(env.image), m_scale(env.scale) {
  if (!std::isfinite(env.rotate_degrees)) throw std::invalid_argument("environment rotation is not finite");
  if (!(env.scale >= 0.f) || !std::isfinite(env.scale)) {
    throw std::invalid_argument("environment scale must be finite and >= 0");
  }
  std::tie(m_cos, m_sin) = turn(env.rotate_degrees);
  if (!m_image) {
    if (!finite_non_negative(env.color)) throw std::invalid_argument("environment colour must be finite and >= 0");
    m_color = env.color * env.scale;
    m_radiance_integral = m_color * (4.f * kPi);
    return;
  }
  const EnvironmentImage& image = *m_image;
  check_image(image);
  std::vector<float> weights(image.texels.size());
  double integral[3] = {0.0, 0.0, 0.0};
  for (int j = 0; j < image.height; ++j) {
    const double solid_angle = texel_solid_angle(j, image.width, image.height);
    for (int i = 0; i < image.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * image.width + i;
      const Color c = image.texels[k];
      if (!finite_non_negative(c)) {
        throw std::invalid_argument("environment image '" + image.path + "': texel " + std::to_string(i) + ", " +
                                    std::to_string(j) + " is negative or not finite");
      }
      // Luminance times solid angle: the texel's share of the light, as far as one number can
      // say it. The solid angle goes in as a float: the row's relative weight is what counts.
      weights[k] = static_cast<float>(luminance(c) * solid_angle);
      for (int ch = 0; ch < 3; ++ch) integral[ch] += c[ch] * solid_angle;
    }
  }
  m_distribution.emplace(weights, image.width, image.height);
  m_radiance_integral =
      Color{static_cast<float>(integral[0]), static_cast<float>(integral[1]), static_cast<float>(integral[2])} *
      m_scale;
}

Vec3 EnvironmentLight::to_local(Vec3 w) const { return {w.x * m_cos - w.z * m_sin, w.y, w.x * m_sin + w.z * m_cos}; }

Vec3 EnvironmentLight::to_world(Vec3 l) const { return {l.x * m_cos + l.z * m_sin, l.y, l.z * m_cos - l.x * m_sin}; }

Color EnvironmentLight::radiance(Vec3 world_dir) const {
  if (!m_image) return m_color;
  const EnvironmentImage& image = *m_image;
  // The texel by piecewise_bin, the rule the sampling distribution's cells follow: a direction's
  // radiance and its density always come from the same texel.
  const Sample2 uv = lat_long_uv(to_local(world_dir));
  const int i = piecewise_bin(uv.x, image.width);
  const int j = piecewise_bin(uv.y, image.height);
  return image.texels[static_cast<std::size_t>(j) * image.width + i] * m_scale;
}

float EnvironmentLight::pdf(Vec3 world_dir) const {
  if (!m_distribution) return kInvFourPi;
  const Vec3 d = to_local(world_dir);
  const float rho = std::sqrt(d.x * d.x + d.z * d.z);
  const float sin_theta = rho / std::sqrt(rho * rho + d.y * d.y);
  // On the polar axis the image-plane density covers no solid angle; the density is 0 there
  // (and a NaN direction fails this test too).
  if (!(sin_theta > 0.f)) return 0.f;
  return m_distribution->pdf(lat_long_uv(d)) / (2.f * kPi * kPi * sin_theta);
}

std::optional<EnvironmentLight::Sample> EnvironmentLight::sample(Sample2 u) const {
  if (!m_distribution) return Sample{uniform_sphere(u), m_color, kInvFourPi};
  const Sample2 uv = m_distribution->sample(u).point;
  const Vec3 wi = to_world(lat_long_direction(uv.x, uv.y));
  // The density and radiance are read back from wi rather than from the sampled cell: the trip
  // through sin and cos can move a point on a texel's edge into its neighbour, and then wi is
  // the neighbour's direction. Reading both from wi keeps them equal to pdf(wi) and
  // radiance(wi), which is what multiple importance sampling compares.
  const float density = pdf(wi);
  if (!(density > 0.f)) return std::nullopt;
  return Sample{wi, radiance(wi), density};
}

Color EnvironmentLight::power_estimate(float scene_radius) const {
  return m_radiance_integral * (kPi * scene_radius * scene_radius);
}

}  // namespace raylab
