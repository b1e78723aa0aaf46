#include "cmj_sampler.h"
#include "permutation.h"

#include <cstdint>
#include <utility>

#include "raylab/core/rng.h"
#include "raylab/sampling/seed_salts.h"
#include "raylab/sampling/stratum.h"

namespace raylab {

namespace {

/// Independent keys for the pixel's separate random choices (one mix of the pixel's key each).
std::uint64_t sub_key(std::uint64_t pixel_key, std::uint64_t which) {
  return mix64(pixel_key + which * 0x9e3779b97f4a7c15ull);
}

}  // namespace

CmjSampler::CmjSampler(int spp, std::uint64_t seed) : PixelSampler(spp, seed) {
  // The factorisation closest to square keeps the cells as compact as possible.
  int rows = 1;
  for (int d = 1; static_cast<long long>(d) * d <= spp; ++d) {
    if (spp % d == 0) rows = d;
  }
  m_rows = rows;
  m_cols = spp / rows;
}

Sample2 CmjSampler::sample(int px, int py, int index) const {
  const int n = spp();
  const std::uint64_t pixel_key =
      hash_seed(seed() ^ kCmjSamplerSalt, static_cast<std::uint64_t>(px), static_cast<std::uint64_t>(py));
  // Which cell sample `index` goes to is shuffled too, so that a prefix of the indices is not
  // confined to the bottom rows.
  const int cell = detail::permute(index, n, sub_key(pixel_key, 1));
  const int col = cell % m_cols;
  const int row = cell / m_cols;
  // Cell (col, row) holds x-interval col * rows + sub_x and y-interval row * cols + sub_y. The
  // sub-interval depends on the other coordinate through one permutation shared by the whole
  // column (row), so every column (row) uses each of its sub-intervals exactly once.
  const int sub_x = detail::permute(row, m_rows, sub_key(pixel_key, 2));
  const int sub_y = detail::permute(col, m_cols, sub_key(pixel_key, 3));
  // The jitter within the sub-interval: 64 hashed bits, half for each axis (SplitMix64 style).
  const std::uint64_t jitter = sub_key(sub_key(pixel_key, 4), static_cast<std::uint64_t>(index));
  const float jx = bits_to_unit_float(static_cast<std::uint32_t>(jitter));
  const float jy = bits_to_unit_float(static_cast<std::uint32_t>(jitter >> 32));
  return {point_in_interval(col * m_rows + sub_x, jx, n), point_in_interval(row * m_cols + sub_y, jy, n)};
}

}  // namespace raylab
