// The adaptive sampler's 16-sample multi-jittered pattern: the three stratifications it
// promises (4 x 4 cells, 16 columns, 16 rows, checked by counting), the cell each index lands
// in, that every ordering of the sub-columns occurs, and that it is a pure function of
// (seed, pixel, index).

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <set>

#include "raylab/sampling/multi_jittered_pattern.h"

namespace raylab {
namespace {

constexpr int kN = MultiJitteredPattern::kSize;

/// Which of `n` equal intervals of [0, 1) holds `v` (exact: v * n is exact in double here).
int interval(float v, int n) { return static_cast<int>(std::floor(static_cast<double>(v) * n)); }

TEST(MultiJitteredPattern, StratifiedInCellsColumnsAndRows) {
  for (std::uint64_t seed : {0ull, 1ull, 0xdeadbeefull}) {
    for (int p = 0; p < 200; ++p) {
      const MultiJitteredPattern pattern(seed, p * 37 % 1920, p * 11);
      std::array<int, kN> cells{}, columns{}, rows{};
      for (int i = 0; i < kN; ++i) {
        const Sample2 s = pattern.sample(i);
        ASSERT_TRUE(s.x >= 0.f && s.x < 1.f && s.y >= 0.f && s.y < 1.f) << "seed " << seed << " pixel " << p;
        // Sample i lies in cell (i % 4, i / 4): the adaptive sampler's levels rely on it.
        ASSERT_EQ(interval(s.x, 4), i % 4);
        ASSERT_EQ(interval(s.y, 4), i / 4);
        ++cells[static_cast<std::size_t>(interval(s.x, 4) + 4 * interval(s.y, 4))];
        ++columns[static_cast<std::size_t>(interval(s.x, kN))];
        ++rows[static_cast<std::size_t>(interval(s.y, kN))];
      }
      for (int k = 0; k < kN; ++k) {
        EXPECT_EQ(cells[static_cast<std::size_t>(k)], 1);
        EXPECT_EQ(columns[static_cast<std::size_t>(k)], 1);
        EXPECT_EQ(rows[static_cast<std::size_t>(k)], 1);
      }
    }
  }
}

TEST(MultiJitteredPattern, EveryOrderingOfTheSubColumnsOccurs) {
  // The sub-columns used by the four cells of column 0, from bottom to top, over many pixels:
  // all 4! = 24 orderings must appear, or the pattern would be a fixed shuffle.
  std::set<std::array<int, 4>> orderings;
  for (int p = 0; p < 2000; ++p) {
    const MultiJitteredPattern pattern(5, p, 0);
    std::array<int, 4> order{};
    for (int cy = 0; cy < 4; ++cy) order[static_cast<std::size_t>(cy)] = interval(pattern.sample(4 * cy).x, kN) % 4;
    orderings.insert(order);
  }
  EXPECT_EQ(orderings.size(), 24u);
}

TEST(MultiJitteredPattern, IsAPureFunctionOfSeedPixelAndIndex) {
  const MultiJitteredPattern a(42, 3, 7);
  const MultiJitteredPattern b(42, 3, 7);
  int differ_pixel = 0;
  int differ_seed = 0;
  for (int i = kN - 1; i >= 0; --i) {  // backwards: the order samples are asked in must not matter
    const Sample2 s = a.sample(i);
    const Sample2 t = b.sample(i);
    EXPECT_EQ(std::bit_cast<std::uint32_t>(s.x), std::bit_cast<std::uint32_t>(t.x));
    EXPECT_EQ(std::bit_cast<std::uint32_t>(s.y), std::bit_cast<std::uint32_t>(t.y));
    const Sample2 other_pixel = MultiJitteredPattern(42, 4, 7).sample(i);
    const Sample2 other_seed = MultiJitteredPattern(43, 3, 7).sample(i);
    differ_pixel += (other_pixel.x != s.x || other_pixel.y != s.y) ? 1 : 0;
    differ_seed += (other_seed.x != s.x || other_seed.y != s.y) ? 1 : 0;
  }
  EXPECT_EQ(differ_pixel, kN);
  EXPECT_EQ(differ_seed, kN);
}

}  // namespace
}  // namespace raylab
