#include "raylab/sampling/sample_dimensions.h"

#include <cmath>
#include <string_view>

#include "permutation.h"
#include "raylab/core/rng.h"
#include "raylab/sampling/seed_salts.h"
#include "raylab/sampling/stratum.h"
#include "sample_rng.h"

namespace raylab {
namespace {

// The sampler whose pattern gives the pairs past the position: the same kind, except that the
// samplers placing every pixel's samples alike get their randomised counterparts.
std::string_view twin_name(std::string_view name) {
  if (name == "center") return "random";
  if (name == "regular") return "jittered";
  return name;
}

}  // namespace

SampleDimensions::SampleDimensions(const PixelSampler& pixel_sampler)
    : m_spp(pixel_sampler.spp()), m_seed(pixel_sampler.seed()) {
  const std::string_view twin = twin_name(pixel_sampler.name());
  if (twin == "jittered") {
    m_jittered_strata = static_cast<int>(std::lround(std::sqrt(static_cast<double>(m_spp))));
    if (m_jittered_strata * m_jittered_strata == m_spp) return;
    m_jittered_strata = 0;  // never for a jittered pixel sampler; kept safe all the same
  }
  m_twins.reserve(kStratifiedPairs - 1);
  for (int k = 1; k < kStratifiedPairs; ++k) {
    m_twins.push_back(
        make_pixel_sampler(twin, m_spp, hash_seed(m_seed ^ kSampleDimensionSalt, static_cast<std::uint64_t>(k))));
  }
}

SampleDimensions::~SampleDimensions() = default;
SampleDimensions::SampleDimensions(SampleDimensions&&) noexcept = default;
SampleDimensions& SampleDimensions::operator=(SampleDimensions&&) noexcept = default;

std::uint64_t SampleDimensions::pixel_key(int px, int py) const {
  return hash_seed(m_seed ^ kDimensionShuffleSalt, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py));
}

Sample2 SampleDimensions::pair(int k, int px, int py, int index, std::uint64_t key) const {
  if (k < kStratifiedPairs) {
    const std::uint64_t pair_key = mix64(key + static_cast<std::uint64_t>(k) * 0x9e3779b97f4a7c15ull);
    const int stratum = detail::shuffle(index, m_spp, pair_key);
    if (m_jittered_strata > 0) {
      // One uniform position in the stratum, from one hash of the pair's key and the stratum.
      const std::uint64_t h = mix64(pair_key ^ (static_cast<std::uint64_t>(stratum) * 0xd1b54a32d192ed03ull));
      const int n = m_jittered_strata;
      return {point_in_interval(stratum % n, bits_to_unit_float(static_cast<std::uint32_t>(h)), n),
              point_in_interval(stratum / n, bits_to_unit_float(static_cast<std::uint32_t>(h >> 32)), n)};
    }
    return m_twins[static_cast<std::size_t>(k - 1)]->sample(px, py, stratum);
  }
  Pcg32 rng = detail::sample_rng(m_seed ^ kDeepDimensionSalt ^ static_cast<std::uint64_t>(k) * 0x9e3779b97f4a7c15ull,
                                 px, py, index);
  const float x = rng.next_float();
  return {x, rng.next_float()};
}

}  // namespace raylab
