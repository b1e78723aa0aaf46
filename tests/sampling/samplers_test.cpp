// Pixel samplers: rounding of the sample count, the exact patterns of center and regular, the
// stratification each stratified sampler promises (checked by counting samples per stratum),
// uniformity of random, and determinism: any (pixel, index) gives the same sample bit for bit
// whatever order it is asked in.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "../test_util.h"
#include "raylab/core/error.h"
#include "raylab/core/rng.h"
#include "raylab/sampling/pixel_sampler.h"

namespace raylab {
namespace {

constexpr std::string_view kAllNames[] = {"center", "regular", "random", "jittered", "cmj", "sobol"};

/// Pixels and seeds every pattern test runs on: ordinary, far away, and a zero pixel.
struct PixelSeed {
  int px;
  int py;
  std::uint64_t seed;
};
constexpr PixelSeed kPixelSeeds[] = {{0, 0, 0}, {3, 7, 1}, {1919, 1079, 42}, {12345, 6, 0xdeadbeefull}};

std::vector<Sample2> pixel_samples(const PixelSampler& sampler, int px, int py) {
  std::vector<Sample2> out;
  for (int i = 0; i < sampler.spp(); ++i) out.push_back(sampler.sample(px, py, i));
  return out;
}

/// The bits of a sample, for bit-exact comparisons.
std::uint64_t bits(Sample2 s) {
  return (static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(s.x)) << 32) | std::bit_cast<std::uint32_t>(s.y);
}

std::vector<std::uint64_t> bits(const std::vector<Sample2>& samples) {
  std::vector<std::uint64_t> out;
  for (Sample2 s : samples) out.push_back(bits(s));
  return out;
}

/// Which of `n` equal intervals of [0, 1) holds `v` (exact: v * n is exact in double here).
int interval(float v, int n) { return static_cast<int>(std::floor(static_cast<double>(v) * n)); }

bool in_unit_square(Sample2 s) { return s.x >= 0.f && s.x < 1.f && s.y >= 0.f && s.y < 1.f; }

/// True when each of the nx * ny cells holds exactly one sample (there must be nx * ny samples).
bool one_per_cell(const std::vector<Sample2>& samples, int nx, int ny) {
  if (static_cast<long long>(samples.size()) != static_cast<long long>(nx) * ny) return false;
  std::vector<int> count(samples.size(), 0);
  for (Sample2 s : samples) {
    if (!in_unit_square(s)) return false;
    ++count[interval(s.y, ny) * nx + interval(s.x, nx)];
  }
  return std::all_of(count.begin(), count.end(), [](int c) { return c == 1; });
}

TEST(PixelSamplerNames, ListsTheSixUniformSamplers) {
  const auto names = pixel_sampler_names();
  ASSERT_EQ(names.size(), std::size(kAllNames));
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(names[i], kAllNames[i]);
  for (std::string_view name : kAllNames) EXPECT_TRUE(is_pixel_sampler(name));
  EXPECT_FALSE(is_pixel_sampler("adaptive"));
  EXPECT_FALSE(is_pixel_sampler(""));
  EXPECT_FALSE(is_pixel_sampler("Jittered"));
}

TEST(ValidSpp, RoundsToTheNearestUsableCountTiesUp) {
  struct Case {
    std::string_view name;
    int requested;
    int expected;
  };
  const Case cases[] = {
      {"center", 1, 1},
      {"center", 7, 1},
      {"regular", 1, 1},
      {"regular", 2, 1},
      {"regular", 3, 4},
      {"regular", 10, 9},
      {"regular", 12, 9},
      {"regular", 13, 16},
      {"jittered", 4, 4},
      {"jittered", 20, 16},
      {"jittered", 21, 25},
      {"jittered", 10, 9},
      {"sobol", 1, 1},
      {"sobol", 2, 2},
      {"sobol", 3, 4},
      {"sobol", 5, 4},
      {"sobol", 6, 8},
      {"sobol", 12, 16},
      {"sobol", 100, 128},
      {"sobol", 1024, 1024},
      {"random", 7, 7},
      {"random", 1, 1},
      {"cmj", 13, 13},
      {"cmj", 1, 1},
      {"jittered", INT_MAX, 46340 * 46340},
      {"sobol", INT_MAX, 1 << 30},
      {"cmj", INT_MAX, INT_MAX},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(valid_spp(c.name, c.requested), c.expected) << c.name << " " << c.requested;
  }
}

TEST(ValidSpp, RejectsCountsBelowOne) {
  for (std::string_view name : kAllNames) {
    EXPECT_THROW(valid_spp(name, 0), UsageError) << name;
    EXPECT_THROW(valid_spp(name, -4), UsageError) << name;
    EXPECT_THROW(make_pixel_sampler(name, 0, 1), UsageError) << name;
  }
}

TEST(ValidSpp, UnknownNameErrorListsTheValidNames) {
  for (auto call : {+[] { valid_spp("halton", 4); }, +[] { (void)make_pixel_sampler("halton", 4, 0); },
                    +[] { (void)spp_rounding_notice("halton", 4); }}) {
    const std::string message = test::thrown_message<UsageError>(call);
    test::expect_contains_all(message, {"halton"});
    test::expect_contains_all(message, kAllNames);
  }
}

TEST(SppRoundingNotice, SaysWhatWasUsedAndWhy) {
  EXPECT_EQ(spp_rounding_notice("jittered", 10),
            "--spp 10 rounded to 9 for the jittered sampler (it needs a square count n*n)");
  EXPECT_EQ(spp_rounding_notice("regular", 3),
            "--spp 3 rounded to 4 for the regular sampler (it needs a square count n*n)");
  EXPECT_EQ(spp_rounding_notice("sobol", 6), "--spp 6 rounded to 8 for the sobol sampler (it needs a power of two)");
  EXPECT_EQ(spp_rounding_notice("center", 4),
            "--spp 4 rounded to 1 for the center sampler (it takes one sample per pixel)");
  // No notice when the request is used as is.
  EXPECT_EQ(spp_rounding_notice("jittered", 16), "");
  EXPECT_EQ(spp_rounding_notice("sobol", 64), "");
  EXPECT_EQ(spp_rounding_notice("center", 1), "");
  EXPECT_EQ(spp_rounding_notice("random", 10), "");
  EXPECT_EQ(spp_rounding_notice("cmj", 10), "");
}

TEST(MakePixelSampler, UsesTheValidCountNameAndSeed) {
  for (std::string_view name : kAllNames) {
    for (int requested : {1, 2, 5, 10, 16}) {
      const auto sampler = make_pixel_sampler(name, requested, 99);
      ASSERT_NE(sampler, nullptr);
      EXPECT_EQ(sampler->name(), name);
      EXPECT_EQ(sampler->spp(), valid_spp(name, requested)) << name << " " << requested;
      EXPECT_EQ(sampler->seed(), 99u);
    }
  }
}

TEST(SamplePathSeed, IsTheOriginalJitteredFormulaAndVariesWithEachArgument) {
  for (const PixelSeed& p : kPixelSeeds) {
    for (int index : {0, 1, 15}) {
      const std::uint64_t expected = hash_seed(p.seed ^ 0x5eedf00dull, static_cast<std::uint64_t>(p.px),
                                               static_cast<std::uint64_t>(p.py), static_cast<std::uint64_t>(index));
      EXPECT_EQ(sample_path_seed(p.seed, p.px, p.py, index), expected);
    }
  }
  const std::uint64_t base = sample_path_seed(1, 2, 3, 4);
  EXPECT_NE(sample_path_seed(2, 2, 3, 4), base);
  EXPECT_NE(sample_path_seed(1, 3, 3, 4), base);
  EXPECT_NE(sample_path_seed(1, 2, 4, 4), base);
  EXPECT_NE(sample_path_seed(1, 2, 3, 5), base);
}

TEST(CenterSampler, IsThePixelCentre) {
  const auto sampler = make_pixel_sampler("center", 1, 5);
  for (const PixelSeed& p : kPixelSeeds) {
    const Sample2 s = sampler->sample(p.px, p.py, 0);
    EXPECT_EQ(s.x, 0.5f);
    EXPECT_EQ(s.y, 0.5f);
  }
}

TEST(RegularSampler, IsTheGridOfStratumCentres) {
  for (int n = 1; n <= 6; ++n) {
    const auto sampler = make_pixel_sampler("regular", n * n, 3);
    for (const PixelSeed& p : kPixelSeeds) {
      for (int index = 0; index < n * n; ++index) {
        const Sample2 s = sampler->sample(p.px, p.py, index);
        EXPECT_EQ(s.x, static_cast<float>((index % n + 0.5) / n)) << n << " " << index;
        EXPECT_EQ(s.y, static_cast<float>((index / n + 0.5) / n)) << n << " " << index;
      }
    }
  }
}

TEST(RandomSampler, StaysInTheUnitSquareAndIsUniform) {
  // 16384 samples in 8 x 8 cells: 256 expected per cell. The chi-square statistic (63 degrees of
  // freedom: mean 63, standard deviation 11.2) of a uniform sampler stays far below 130; the
  // inputs are fixed, so the test cannot flake. Same for the 1D marginals in 64 bins.
  const auto sampler = make_pixel_sampler("random", 64, 2024);
  std::vector<int> cells(64, 0);
  std::vector<int> xs(64, 0);
  std::vector<int> ys(64, 0);
  int total = 0;
  for (int py = 0; py < 16; ++py) {
    for (int px = 0; px < 16; ++px) {
      for (Sample2 s : pixel_samples(*sampler, px, py)) {
        ASSERT_TRUE(in_unit_square(s));
        ++cells[interval(s.y, 8) * 8 + interval(s.x, 8)];
        ++xs[interval(s.x, 64)];
        ++ys[interval(s.y, 64)];
        ++total;
      }
    }
  }
  auto chi_square = [total](const std::vector<int>& counts) {
    const double expected = static_cast<double>(total) / static_cast<double>(counts.size());
    double sum = 0;
    for (int c : counts) sum += (c - expected) * (c - expected) / expected;
    return sum;
  };
  EXPECT_LT(chi_square(cells), 130.0);
  EXPECT_LT(chi_square(xs), 130.0);
  EXPECT_LT(chi_square(ys), 130.0);
  // Not suspiciously even either (a grid would give 0).
  EXPECT_GT(chi_square(cells), 20.0);
}

TEST(JitteredSampler, OneSamplePerStratum) {
  for (int n : {1, 2, 3, 4, 7, 16}) {
    for (const PixelSeed& p : kPixelSeeds) {
      const auto sampler = make_pixel_sampler("jittered", n * n, p.seed);
      const auto samples = pixel_samples(*sampler, p.px, p.py);
      EXPECT_TRUE(one_per_cell(samples, n, n)) << n << " at " << p.px << "," << p.py;
      // Sample `index` is in stratum (index % n, index / n).
      for (int index = 0; index < n * n; ++index) {
        EXPECT_EQ(interval(samples[index].x, n), index % n);
        EXPECT_EQ(interval(samples[index].y, n), index / n);
      }
    }
  }
}

TEST(JitteredSampler, ReproducesTheOriginalJitteredPositions) {
  // The renderer's original JitteredSampler: one PCG32 per (seed, pixel, index), two draws.
  for (int n : {2, 3, 4, 8}) {
    for (const PixelSeed& p : kPixelSeeds) {
      const auto sampler = make_pixel_sampler("jittered", n * n, p.seed);
      for (int index = 0; index < n * n; ++index) {
        Pcg32 rng(hash_seed(p.seed, static_cast<std::uint64_t>(p.px), static_cast<std::uint64_t>(p.py),
                            static_cast<std::uint64_t>(index)));
        const float x = (static_cast<float>(index % n) + rng.next_float()) / static_cast<float>(n);
        const float y = (static_cast<float>(index / n) + rng.next_float()) / static_cast<float>(n);
        const Sample2 s = sampler->sample(p.px, p.py, index);
        EXPECT_EQ(bits(s), bits(Sample2{x, y})) << n << " " << index;
      }
    }
  }
}

TEST(JitteredSampler, OneSampleIsJitteredOverThePixel) {
  const auto sampler = make_pixel_sampler("jittered", 1, 7);
  std::vector<std::uint64_t> seen;
  for (int px = 0; px < 32; ++px) {
    const Sample2 s = sampler->sample(px, 0, 0);
    EXPECT_TRUE(in_unit_square(s));
    seen.push_back(bits(s));
  }
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(std::unique(seen.begin(), seen.end()), seen.end()) << "one sample per pixel should not repeat";
  EXPECT_NE(seen.front(), bits(Sample2{0.5f, 0.5f}));
}

TEST(JitteredSampler, RoundingOntoAStratumEdgeIsPulledBack) {
  // With 40000 strata per axis, (sx + u) / 40000 computed in float rounds onto the next
  // stratum's edge (exactly 1.0f for the last column) when u is within ~2^-9 of 1. Find such
  // draws with the original formula; the sampler must keep them inside their own stratum.
  constexpr int n = 40000;
  const auto sampler = make_pixel_sampler("jittered", n * n, 11);
  int found_last = 0;
  int found_inner = 0;
  for (int px = 0; px < 200000 && (found_last < 3 || found_inner < 3); ++px) {
    const int sx = (px % 2 == 0) ? n - 1 : n - 2;
    const int index = (px % 5) * n + sx;
    Pcg32 rng(hash_seed(11, static_cast<std::uint64_t>(px), 0, static_cast<std::uint64_t>(index)));
    const float x = (static_cast<float>(sx) + rng.next_float()) / static_cast<float>(n);
    if (interval(x, n) == sx) continue;
    (sx == n - 1 ? found_last : found_inner) += 1;
    const Sample2 s = sampler->sample(px, 0, index);
    EXPECT_LT(s.x, 1.f);
    EXPECT_EQ(interval(s.x, n), sx);
    EXPECT_EQ(interval(s.y, n), px % 5);
  }
  EXPECT_GE(found_last, 3) << "too few draws rounded onto 1.0: widen the search";
  EXPECT_GE(found_inner, 3) << "too few draws rounded onto an inner edge: widen the search";
}

/// The cmj grid: rows the largest divisor of n not above sqrt(n), cols = n / rows.
void cmj_grid(int n, int& cols, int& rows) {
  rows = 1;
  for (int d = 1; d * d <= n; ++d) {
    if (n % d == 0) rows = d;
  }
  cols = n / rows;
}

TEST(CmjSampler, StratifiedIn2DAndInBothProjections) {
  for (int n : {1, 2, 3, 4, 5, 7, 9, 12, 16, 64, 100}) {
    int cols = 0;
    int rows = 0;
    cmj_grid(n, cols, rows);
    for (const PixelSeed& p : kPixelSeeds) {
      const auto sampler = make_pixel_sampler("cmj", n, p.seed);
      ASSERT_EQ(sampler->spp(), n);
      const auto samples = pixel_samples(*sampler, p.px, p.py);
      EXPECT_TRUE(one_per_cell(samples, cols, rows)) << n << ": " << cols << " x " << rows << " cells";
      EXPECT_TRUE(one_per_cell(samples, n, 1)) << n << ": x projection";
      EXPECT_TRUE(one_per_cell(samples, 1, n)) << n << ": y projection";
    }
  }
}

TEST(CmjSampler, EveryPixelHasItsOwnPattern) {
  for (int n : {4, 9, 16}) {
    const auto sampler = make_pixel_sampler("cmj", n, 5);
    std::vector<std::vector<std::uint64_t>> patterns;
    for (int px = 0; px < 8; ++px) {
      auto b = bits(pixel_samples(*sampler, px, 1));
      std::sort(b.begin(), b.end());
      patterns.push_back(b);
    }
    std::sort(patterns.begin(), patterns.end());
    EXPECT_EQ(std::unique(patterns.begin(), patterns.end()), patterns.end()) << n;
  }
}

TEST(SobolSampler, EveryElementaryIntervalHoldsOnePoint) {
  for (int k = 0; k <= 10; ++k) {
    const int n = 1 << k;
    for (const PixelSeed& p : kPixelSeeds) {
      const auto sampler = make_pixel_sampler("sobol", n, p.seed);
      ASSERT_EQ(sampler->spp(), n);
      const auto samples = pixel_samples(*sampler, p.px, p.py);
      for (int a = 0; a <= k; ++a) {
        EXPECT_TRUE(one_per_cell(samples, 1 << a, 1 << (k - a))) << "2^" << a << " x 2^" << (k - a);
      }
    }
  }
}

TEST(SobolSampler, EveryPixelHasItsOwnPattern) {
  for (int n : {1, 4, 16}) {
    const auto sampler = make_pixel_sampler("sobol", n, 5);
    std::vector<std::vector<std::uint64_t>> patterns;
    for (int px = 0; px < 8; ++px) {
      for (int py = 0; py < 2; ++py) {
        auto b = bits(pixel_samples(*sampler, px, py));
        std::sort(b.begin(), b.end());
        patterns.push_back(b);
      }
    }
    std::sort(patterns.begin(), patterns.end());
    EXPECT_EQ(std::unique(patterns.begin(), patterns.end()), patterns.end()) << n;
  }
  // Scrambled: the first point is not the unscrambled sequence's (0, 0).
  const auto sampler = make_pixel_sampler("sobol", 4, 5);
  for (int px = 0; px < 8; ++px) EXPECT_NE(bits(sampler->sample(px, 0, 0)), bits(Sample2{0.f, 0.f}));
}

TEST(AllSamplers, StayInsideTheUnitSquare) {
  for (std::string_view name : kAllNames) {
    for (int spp : {1, 3, 16, 64}) {
      const auto sampler = make_pixel_sampler(name, spp, 77);
      for (int px = 0; px < 6; ++px) {
        for (Sample2 s : pixel_samples(*sampler, px, 2 * px + 1)) EXPECT_TRUE(in_unit_square(s)) << name;
      }
    }
  }
}

TEST(AllSamplers, AnyOrderGivesTheSameSamplesBitForBit) {
  for (std::string_view name : kAllNames) {
    for (int spp : {1, 9, 16}) {
      const auto first = make_pixel_sampler(name, spp, 1234);
      std::vector<std::vector<std::uint64_t>> forward;
      for (int px = 0; px < 4; ++px) forward.push_back(bits(pixel_samples(*first, px, 3)));
      // A fresh sampler, pixels and indices visited in reverse.
      const auto second = make_pixel_sampler(name, spp, 1234);
      for (int px = 3; px >= 0; --px) {
        for (int index = second->spp() - 1; index >= 0; --index) {
          EXPECT_EQ(bits(second->sample(px, 3, index)), forward[px][index]) << name << " " << spp;
        }
      }
      // Interleaved across pixels on the first sampler again.
      for (int index = 0; index < first->spp(); ++index) {
        for (int px = 0; px < 4; ++px) EXPECT_EQ(bits(first->sample(px, 3, index)), forward[px][index]) << name;
      }
    }
  }
}

TEST(AllSamplers, DifferentSeedsGiveDifferentPatterns) {
  // center and regular are the same in every pixel by definition; the others draw from the seed.
  for (std::string_view name : {"random", "jittered", "cmj", "sobol"}) {
    const auto a = make_pixel_sampler(name, 16, 1);
    const auto b = make_pixel_sampler(name, 16, 2);
    for (int px = 0; px < 4; ++px) {
      EXPECT_NE(bits(pixel_samples(*a, px, 0)), bits(pixel_samples(*b, px, 0))) << name;
    }
  }
  for (std::string_view name : {"center", "regular"}) {
    EXPECT_EQ(bits(pixel_samples(*make_pixel_sampler(name, 16, 1), 0, 0)),
              bits(pixel_samples(*make_pixel_sampler(name, 16, 2), 5, 9)))
        << name;
  }
}

}  // namespace
}  // namespace raylab
