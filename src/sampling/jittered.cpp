#include "raylab/sampling/jittered.h"

#include <cmath>

#include "raylab/core/rng.h"

namespace raylab {

JitteredSampler::JitteredSampler(int spp, std::uint64_t seed) : m_spp(spp < 1 ? 1 : spp), m_seed(seed) {
  // The factorisation nx * ny == spp closest to square: the strata stay as compact as possible.
  m_nx = static_cast<int>(std::sqrt(static_cast<double>(m_spp)));
  while (m_spp % m_nx != 0) --m_nx;
  m_ny = m_spp / m_nx;
}

Sample2 JitteredSampler::pixel_sample(int px, int py, int index) const {
  if (m_spp == 1) {
    // One sample: the pixel centre, so a 1-spp image is the classic one ray per pixel.
    return {0.5f, 0.5f};
  }
  Pcg32 rng(hash_seed(m_seed, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py),
                      static_cast<std::uint64_t>(index)));
  const int sx = index % m_ny;
  const int sy = index / m_ny;
  // Strata: m_ny columns by m_nx rows (wider than tall when spp is not square).
  const float x = (static_cast<float>(sx) + rng.next_float()) / static_cast<float>(m_ny);
  const float y = (static_cast<float>(sy) + rng.next_float()) / static_cast<float>(m_nx);
  return {x, y};
}

std::uint64_t JitteredSampler::path_seed(int px, int py, int index) const {
  return hash_seed(m_seed ^ 0x5eedf00dull, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py),
                   static_cast<std::uint64_t>(index));
}

}  // namespace raylab
