#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <string>

#include "basic_samplers.h"
#include "cmj_sampler.h"
#include "jittered_sampler.h"
#include "raylab/core/error.h"
#include "raylab/core/rng.h"
#include "raylab/sampling/pixel_sampler.h"
#include "raylab/sampling/seed_salts.h"
#include "sobol_sampler.h"

namespace raylab {

namespace {

constexpr std::array<std::string_view, 6> kNames = {"center", "regular", "random", "jittered", "cmj", "sobol"};

/// Which counts a sampler can use.
enum class CountRule { kOne, kSquare, kPowerOfTwo, kAny };

CountRule count_rule(std::string_view name) {
  if (name == "center") return CountRule::kOne;
  if (name == "regular" || name == "jittered") return CountRule::kSquare;
  if (name == "sobol") return CountRule::kPowerOfTwo;
  if (name == "random" || name == "cmj") return CountRule::kAny;
  std::string list;
  for (std::string_view n : kNames) list += (list.empty() ? "" : ", ") + std::string(n);
  throw UsageError("unknown sampler '" + std::string(name) + "' (valid: " + list + ")");
}

/// The nearer of two candidates lo <= requested <= hi; ties go to hi unless hi overflows int.
int nearest(long long requested, long long lo, long long hi) {
  if (hi > INT_MAX) return static_cast<int>(lo);
  return static_cast<int>(hi - requested <= requested - lo ? hi : lo);
}

/// floor(sqrt(v)) exactly (the double estimate is corrected by integer checks).
long long integer_sqrt(long long v) {
  auto r = static_cast<long long>(std::sqrt(static_cast<double>(v)));
  while (r * r > v) --r;
  while ((r + 1) * (r + 1) <= v) ++r;
  return r;
}

}  // namespace

std::span<const std::string_view> pixel_sampler_names() { return kNames; }

bool is_pixel_sampler(std::string_view name) {
  for (std::string_view n : kNames) {
    if (n == name) return true;
  }
  return false;
}

int valid_spp(std::string_view name, int requested) {
  const CountRule rule = count_rule(name);  // first, so that an unknown name is the error reported
  if (requested < 1) throw UsageError("--spp must be at least 1 (got " + std::to_string(requested) + ")");
  switch (rule) {
    case CountRule::kOne:
      return 1;
    case CountRule::kSquare: {
      const long long n = integer_sqrt(requested);
      return nearest(requested, n * n, (n + 1) * (n + 1));
    }
    case CountRule::kPowerOfTwo: {
      long long lo = 1;
      while (lo * 2 <= requested) lo *= 2;
      return nearest(requested, lo, lo * 2);
    }
    case CountRule::kAny:
      break;
  }
  return requested;
}

std::string spp_rounding_notice(std::string_view name, int requested) {
  const int used = valid_spp(name, requested);
  if (used == requested) return "";
  std::string why;
  switch (count_rule(name)) {
    case CountRule::kOne:
      why = "it takes one sample per pixel";
      break;
    case CountRule::kSquare:
      why = "it needs a square count n*n";
      break;
    case CountRule::kPowerOfTwo:
      why = "it needs a power of two";
      break;
    case CountRule::kAny:
      break;
  }
  return "--spp " + std::to_string(requested) + " rounded to " + std::to_string(used) + " for the " +
         std::string(name) + " sampler (" + why + ")";
}

std::unique_ptr<PixelSampler> make_pixel_sampler(std::string_view name, int spp, std::uint64_t seed) {
  const int n = valid_spp(name, spp);
  if (name == "center") return std::make_unique<CenterSampler>(seed);
  if (name == "regular") return std::make_unique<RegularSampler>(static_cast<int>(integer_sqrt(n)), seed);
  if (name == "random") return std::make_unique<RandomSampler>(n, seed);
  if (name == "jittered") return std::make_unique<JitteredGridSampler>(static_cast<int>(integer_sqrt(n)), seed);
  if (name == "cmj") return std::make_unique<CmjSampler>(n, seed);
  return std::make_unique<SobolSampler>(n, seed);  // valid_spp has rejected every other name
}

std::uint64_t sample_path_seed(std::uint64_t seed, int px, int py, int index) {
  // The formula of the original JitteredSampler::path_seed, so that area-light samples (and the
  // reference images made with them) stay the same.
  return hash_seed(seed ^ kSamplePathSalt, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py),
                   static_cast<std::uint64_t>(index));
}

}  // namespace raylab
