// next_float_up / next_float_down against std::nextafter, bit for bit: the special values (zeros,
// denormals, the largest finite, infinities, NaN) and a million random bit patterns.

#include "raylab/core/float_neighbour.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "raylab/core/rng.h"

namespace raylab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// NaN compares unequal to itself; any NaN is the right answer for a NaN.
bool same(float a, float b) {
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

void expect_as_nextafter(float x) {
  EXPECT_TRUE(same(next_float_up(x), std::nextafter(x, kInf))) << "up from " << x;
  EXPECT_TRUE(same(next_float_down(x), std::nextafter(x, -kInf))) << "down from " << x;
}

TEST(FloatNeighbour, SpecialValuesAsNextafter) {
  const float d = std::numeric_limits<float>::denorm_min(), m = std::numeric_limits<float>::max();
  for (float x :
       {0.f, -0.f, d, -d, 2 * d, -2 * d, std::numeric_limits<float>::min(), -std::numeric_limits<float>::min(), 1.f,
        -1.f, m, -m, kInf, -kInf, std::numeric_limits<float>::quiet_NaN()}) {
    expect_as_nextafter(x);
  }
}

TEST(FloatNeighbour, RandomBitPatternsAsNextafter) {
  Pcg32 rng(5);
  int failures = 0;
  for (int i = 0; i < 1000000 && failures < 10; ++i) {
    const float x = std::bit_cast<float>(rng.next_u32());
    const bool ok =
        same(next_float_up(x), std::nextafter(x, kInf)) && same(next_float_down(x), std::nextafter(x, -kInf));
    if (!ok) {
      ++failures;
      ADD_FAILURE() << "differs from std::nextafter at bits " << std::bit_cast<std::uint32_t>(x);
    }
  }
}

}  // namespace
}  // namespace raylab
