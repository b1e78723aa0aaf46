#include "basic_samplers.h"

#include "raylab/core/rng.h"
#include "raylab/sampling/stratum.h"

namespace raylab {

namespace {

/// Keeps the random sampler's draws apart from the jittered sampler's, which hash the same
/// (seed, pixel, index) without a salt.
constexpr std::uint64_t kRandomSalt = 0x7a4d0c3e91b25f68ull;

/// The per-sample generator: hashing every coordinate (rather than advancing one shared
/// generator) is what makes a sample addressable in any order.
Pcg32 sample_rng(std::uint64_t seed, int px, int py, int index) {
  return Pcg32(hash_seed(seed, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py),
                         static_cast<std::uint64_t>(index)));
}

}  // namespace

Sample2 CenterSampler::sample(int /*px*/, int /*py*/, int /*index*/) const { return {0.5f, 0.5f}; }

Sample2 RegularSampler::sample(int /*px*/, int /*py*/, int index) const {
  return {point_in_interval(column(index), 0.5f, strata()), point_in_interval(row(index), 0.5f, strata())};
}

Sample2 RandomSampler::sample(int px, int py, int index) const {
  Pcg32 rng = sample_rng(seed() ^ kRandomSalt, px, py, index);
  const float x = rng.next_float();  // next_float() is already in [0, 1)
  const float y = rng.next_float();
  return {x, y};
}

Sample2 JitteredGridSampler::sample(int px, int py, int index) const {
  Pcg32 rng = sample_rng(seed(), px, py, index);
  const int sx = column(index);
  const int sy = row(index);
  // The same float expressions as the original JitteredSampler, so reference images keep their
  // pixels. Float rounding can put (sx + u) / n on the next stratum's edge (1.0 for the last);
  // the clamp moves only those rare values back inside their stratum.
  const float n = static_cast<float>(strata());
  const float x = (static_cast<float>(sx) + rng.next_float()) / n;
  const float y = (static_cast<float>(sy) + rng.next_float()) / n;
  return {clamp_to_interval(x, sx, strata()), clamp_to_interval(y, sy, strata())};
}

}  // namespace raylab
