#pragma once
// Empty-space distances of a uniform grid (internal to src/accel): for every cell, how far the
// nearest cell holding primitives is, counted in cells along the worst axis (the chessboard
// distance). A ray in a cell at distance d can cross the cube of cells within d - 1 of it in one
// jump: all of them are empty (Cohen & Sheffer's proximity clouds, 1994).

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <tbb/parallel_for.h>

namespace raylab {

/// Chessboard distances from each cell to the nearest occupied cell, capped at `cap` (<= 255):
/// 0 for an occupied cell, `cap` for one with no occupied cell within cap - 1. `occupied(c)`
/// tells whether linear cell c (x fastest) holds primitives. Exact below the cap, computed one
/// axis at a time: the distance along x within each row, then min over a column of
/// max(offset, distance so far) along y, then the same along z.
template <class Occupied>
std::vector<std::uint8_t> chessboard_distances(std::array<int, 3> n, int cap, Occupied&& occupied) {
  const std::size_t nx = n[0], ny = n[1], nz = n[2];
  std::vector<std::uint8_t> d(nx * ny * nz);
  const auto top = static_cast<std::uint8_t>(cap);

  // Along x: distance to the nearest occupied cell of the row, by a sweep each way.
  tbb::parallel_for(std::size_t{0}, ny * nz, [&](std::size_t row) {
    std::uint8_t* line = d.data() + row * nx;
    int run = cap;
    for (std::size_t x = 0; x < nx; ++x) {
      run = occupied(row * nx + x) ? 0 : std::min(run + 1, cap);
      line[x] = static_cast<std::uint8_t>(run);
    }
    run = cap;
    for (std::size_t x = nx; x-- > 0;) {
      run = line[x] == 0 ? 0 : std::min(run + 1, cap);
      line[x] = std::min(line[x], static_cast<std::uint8_t>(run));
    }
  });

  // Along y, then z: d'(i) = min over j of max(|i - j|, d(j)). Offsets at or past the best so
  // far cannot improve it, which ends the scan early near occupied cells.
  auto sweep = [&](std::size_t count, std::size_t stride, std::size_t lines, auto&& line_start) {
    tbb::parallel_for(std::size_t{0}, lines, [&](std::size_t l) {
      const std::size_t base = line_start(l);
      std::vector<std::uint8_t> in(count);
      for (std::size_t i = 0; i < count; ++i) in[i] = d[base + i * stride];
      for (std::size_t i = 0; i < count; ++i) {
        std::uint8_t best = in[i];
        for (std::size_t k = 1; k < best; ++k) {
          if (i >= k) best = std::min(best, std::max(static_cast<std::uint8_t>(k), in[i - k]));
          if (i + k < count) best = std::min(best, std::max(static_cast<std::uint8_t>(k), in[i + k]));
        }
        d[base + i * stride] = std::min(best, top);
      }
    });
  };
  sweep(ny, nx, nx * nz, [&](std::size_t l) { return (l / nx) * nx * ny + l % nx; });
  sweep(nz, nx * ny, nx * ny, [&](std::size_t l) { return l; });
  return d;
}

}  // namespace raylab
