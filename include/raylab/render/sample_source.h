#pragma once
/// \file
/// The random numbers one camera sample's path draws, handed to the integrator.

#include <cstdint>

#include "raylab/core/rng.h"
#include "raylab/sampling/pixel_sampler.h"
#include "raylab/sampling/sample_dimensions.h"

namespace raylab {

/// The random numbers of one camera sample. The uniform pixel loops address the sample by
/// (pixel, index) and give stratified dimension pairs (SampleDimensions); the adaptive loops,
/// whose samples have no index in a fixed pattern, give independent numbers from the sample's
/// path seed. Either way the numbers depend only on where the sample is, never on the thread.
class SampleSource {
 public:
  /// Independent numbers only, every one from Pcg32(path_seed).
  explicit SampleSource(std::uint64_t path_seed) : m_rng(path_seed) {}

  /// Pairs 1, 2, ... of sample `index` of pixel (px, py) from `dims` (which must outlive this);
  /// rng() still starts from Pcg32(path_seed).
  SampleSource(std::uint64_t path_seed, const SampleDimensions& dims, int px, int py, int index)
      : m_rng(path_seed), m_dims(&dims), m_px(px), m_py(py), m_index(index), m_pixel_key(dims.pixel_key(px, py)) {}

  /// The path's generator of independent numbers: Whitted's area-light samples draw from it, as
  /// they always have, and the path integrator's one-dimensional decisions that gain nothing from
  /// stratification (Russian roulette, a mixed material's model).
  Pcg32& rng() { return m_rng; }

  /// The next dimension pair: pair 1 on the first call, then 2, 3, ... (pair 0 is the position
  /// in the pixel, which the pixel loop has used).
  Sample2 next_2d() {
    if (m_dims != nullptr) return m_dims->pair(m_next_pair++, m_px, m_py, m_index, m_pixel_key);
    const float x = m_rng.next_float();
    return {x, m_rng.next_float()};
  }

  /// Moves to pair `k` (>= 1), so that each bounce of a path starts at a fixed pair whatever
  /// the previous bounce drew.
  void seek_pair(int k) { m_next_pair = k; }

  /// True when pairs are addressed (the sample dimensions): pair(k) then gives what next_2d()
  /// gives after seek_pair(k), and pairs not asked for cost nothing and change nothing.
  bool addressed() const { return m_dims != nullptr; }
  /// Pair `k` of an addressed source, without moving its position.
  Sample2 pair(int k) const { return m_dims->pair(k, m_px, m_py, m_index, m_pixel_key); }

 private:
  Pcg32 m_rng;
  const SampleDimensions* m_dims = nullptr;
  int m_px = 0, m_py = 0, m_index = 0;
  std::uint64_t m_pixel_key = 0;
  int m_next_pair = 1;
};

}  // namespace raylab
