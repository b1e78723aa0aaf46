#include "jittered_sampler.h"

#include "raylab/core/rng.h"
#include "raylab/sampling/seed_salts.h"
#include "raylab/sampling/stratum.h"
#include "sample_rng.h"

namespace raylab {

Sample2 JitteredGridSampler::sample(int px, int py, int index) const {
  Pcg32 rng = detail::sample_rng(seed() ^ kUnsaltedSeed, px, py, index);
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
