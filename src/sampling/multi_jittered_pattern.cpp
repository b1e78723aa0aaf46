#include "raylab/sampling/multi_jittered_pattern.h"

#include <array>
#include <cstddef>

#include "raylab/core/rng.h"
#include "raylab/sampling/seed_salts.h"
#include "raylab/sampling/stratum.h"

namespace raylab {

namespace {

/// The 24 orderings of 0..3.
constexpr std::array<std::array<std::uint8_t, 4>, 24> kPermutations4 = {
    {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 3, 2, 1}, {1, 0, 2, 3}, {1, 0, 3, 2},
     {1, 2, 0, 3}, {1, 2, 3, 0}, {1, 3, 0, 2}, {1, 3, 2, 0}, {2, 0, 1, 3}, {2, 0, 3, 1}, {2, 1, 0, 3}, {2, 1, 3, 0},
     {2, 3, 0, 1}, {2, 3, 1, 0}, {3, 0, 1, 2}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 1, 2, 0}, {3, 2, 0, 1}, {3, 2, 1, 0}}};

}  // namespace

MultiJitteredPattern::MultiJitteredPattern(std::uint64_t seed, int px, int py)
    : m_key(hash_seed(seed ^ kMultiJitteredPatternSalt, static_cast<std::uint64_t>(px),
                      static_cast<std::uint64_t>(py))) {}

Sample2 MultiJitteredPattern::sample(int i) const {
  const int cx = i & 3;
  const int cy = i >> 2;
  // Eight 5-bit fields of the key pick the orderings of the 4 columns and the 4 rows.
  const auto& column_order = kPermutations4[((m_key >> (5 * cx)) & 31u) % 24u];
  const auto& row_order = kPermutations4[((m_key >> (20 + 5 * cy)) & 31u) % 24u];
  Pcg32 rng(m_key ^ mix64(static_cast<std::uint64_t>(i) + 1u));
  const float u = rng.next_float();
  const float v = rng.next_float();
  // Kept inside its 1/16 column and row: (k + u) / 16 in float can round onto the next one.
  return {point_in_interval(4 * cx + column_order[static_cast<std::size_t>(cy)], u, 16),
          point_in_interval(4 * cy + row_order[static_cast<std::size_t>(cx)], v, 16)};
}

}  // namespace raylab
