#include "raylab/sampling/filter.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "raylab/core/error.h"

namespace raylab {

namespace {

constexpr std::array<std::string_view, 4> kNames = {"box", "tent", "gaussian", "mitchell"};
constexpr std::array<float, 4> kDefaultRadii = {0.5f, 1.f, 1.5f, 2.f};

/// The largest radius make_filter accepts: wider filters blur more than any use calls for and
/// make every sample touch hundreds of pixels.
constexpr float kMaxRadius = 8.f;

/// The gaussian's sigma is radius / 3: at the radius it has fallen to exp(-4.5) ~ 1.1% of its
/// peak, small enough that the shift that makes it reach zero there changes little.
constexpr double kGaussianSigmas = 3.0;

std::string name_list() {
  std::string list;
  for (std::string_view n : kNames) list += (list.empty() ? "" : ", ") + std::string(n);
  return list;
}

/// Index of `name` in kNames; throws UsageError for an unknown name.
std::size_t filter_index(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == name) return i;
  }
  throw UsageError("unknown filter '" + std::string(name) + "' (valid: " + name_list() + ")");
}

/// Mitchell & Netravali's cubic with B = C = 1/3 at |t| (support [0, 2)); its integral over
/// [-2, 2] is 1 for every B and C.
double mitchell_1d(double t) {
  constexpr double b = 1.0 / 3.0;
  constexpr double c = 1.0 / 3.0;
  if (t < 1.0) {
    return ((12 - 9 * b - 6 * c) * t * t * t + (-18 + 12 * b + 6 * c) * t * t + (6 - 2 * b)) / 6.0;
  }
  return ((-b - 6 * c) * t * t * t + (6 * b + 30 * c) * t * t + (-12 * b - 48 * c) * t + (8 * b + 24 * c)) / 6.0;
}

/// The un-normalised profile at |x| < radius.
double raw_profile(FilterKind kind, double ax, double radius) {
  switch (kind) {
    case FilterKind::kBox:
      return 1.0;
    case FilterKind::kTent:
      return radius - ax;
    case FilterKind::kGaussian: {
      const double s = kGaussianSigmas / radius;
      return std::exp(-0.5 * s * s * ax * ax) - std::exp(-0.5 * kGaussianSigmas * kGaussianSigmas);
    }
    case FilterKind::kMitchell:
      return mitchell_1d(2.0 * ax / radius);
  }
  return 0.0;
}

/// The integral of raw_profile over [-radius, radius], in closed form.
double raw_integral(FilterKind kind, double radius) {
  switch (kind) {
    case FilterKind::kBox:
      return 2.0 * radius;
    case FilterKind::kTent:
      return radius * radius;
    case FilterKind::kGaussian: {
      const double sigma = radius / kGaussianSigmas;
      const double bell = sigma * std::sqrt(2.0 * std::numbers::pi) * std::erf(kGaussianSigmas / std::numbers::sqrt2);
      return bell - 2.0 * radius * std::exp(-0.5 * kGaussianSigmas * kGaussianSigmas);
    }
    case FilterKind::kMitchell:
      return radius / 2.0;  // the cubic integrates to 1 over [-2, 2], stretched by radius / 2
  }
  return 1.0;
}

}  // namespace

Filter::Filter(FilterKind kind, float radius) : m_kind(kind), m_radius(radius) {
  if (!(radius > 0.f) || !std::isfinite(radius)) {
    throw UsageError("filter radius must be a positive number of pixels (got " + std::to_string(radius) + ")");
  }
  m_scale = static_cast<float>(1.0 / raw_integral(kind, radius));
}

float Filter::evaluate_1d(float x) const {
  const double ax = std::abs(static_cast<double>(x));
  if (!(ax < static_cast<double>(m_radius))) return 0.f;  // also 0 for NaN
  return static_cast<float>(raw_profile(m_kind, ax, m_radius) * m_scale);
}

std::span<const std::string_view> filter_names() { return kNames; }

float default_filter_radius(std::string_view name) { return kDefaultRadii[filter_index(name)]; }

Filter make_filter(std::string_view name, float radius) {
  const std::size_t index = filter_index(name);
  if (!(radius >= 0.f && radius <= kMaxRadius)) {
    throw UsageError("filter radius must be between 0 and " + std::to_string(static_cast<int>(kMaxRadius)) +
                     " pixels, 0 for the filter's default (got " + std::to_string(radius) + ")");
  }
  constexpr std::array<FilterKind, 4> kKinds = {FilterKind::kBox, FilterKind::kTent, FilterKind::kGaussian,
                                                FilterKind::kMitchell};
  return Filter(kKinds[index], radius == 0.f ? kDefaultRadii[index] : radius);
}

}  // namespace raylab
