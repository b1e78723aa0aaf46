#include "basic_samplers.h"

#include "raylab/core/rng.h"
#include "raylab/sampling/seed_salts.h"
#include "raylab/sampling/stratum.h"
#include "sample_rng.h"

namespace raylab {

Sample2 CenterSampler::sample(int /*px*/, int /*py*/, int /*index*/) const { return {0.5f, 0.5f}; }

Sample2 RegularSampler::sample(int /*px*/, int /*py*/, int index) const {
  return {point_in_interval(column(index), 0.5f, strata()), point_in_interval(row(index), 0.5f, strata())};
}

Sample2 RandomSampler::sample(int px, int py, int index) const {
  Pcg32 rng = detail::sample_rng(seed() ^ kRandomSamplerSalt, px, py, index);
  const float x = rng.next_float();  // next_float() is already in [0, 1)
  const float y = rng.next_float();
  return {x, y};
}

}  // namespace raylab
