// scalar::Float4 and simd::Float4 (the SSE one where it is built) must be interchangeable: the
// same bits from every operation, on ordinary values and on NaN, infinities, signed zeros and
// denormals, and the documented NaN rule of min/max (the SECOND operand when either is NaN),
// which the BVH traversal relies on to drop NaN slab distances.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <type_traits>

#include "raylab/core/rng.h"
#include "raylab/simd/float4.h"
#include "simd_test_util.h"

namespace raylab {
namespace {

using Lanes = std::array<float, 4>;
namespace sc = simd::scalar;
using namespace test;  // simd_test_util.h

template <class F>
Lanes lanes(const F& f) {
  Lanes out;
  f.store(out.data());
  return out;
}
template <class F>
F make(const Lanes& l) {
  return F::load(l.data());
}

Lanes random_lanes(Pcg32& rng) { return {random_value(rng), random_value(rng), random_value(rng), random_value(rng)}; }

// Checks one implementation F against the rules (min/max bit for bit, the selected operand
// unchanged; arithmetic as IEEE single precision); returns its results for comparison.
template <class F>
void check_ops(const Lanes& a, const Lanes& b, Lanes out[4], int& mask) {
  const F fa = make<F>(a), fb = make<F>(b);
  out[0] = lanes(fa - fb);
  out[1] = lanes(fa * fb);
  out[2] = lanes(min(fa, fb));
  out[3] = lanes(max(fa, fb));
  mask = less_equal_mask(fa, fb);
  int expected_mask = 0;
  for (int i = 0; i < 4; ++i) {
    const volatile float x = a[i], y = b[i];  // volatile: the reference is plain scalar code
    EXPECT_TRUE(same_arith(out[0][i], x - y)) << a[i] << " - " << b[i];
    EXPECT_TRUE(same_arith(out[1][i], x * y)) << a[i] << " * " << b[i];
    EXPECT_EQ(bits(out[2][i]), bits(rule_min(a[i], b[i]))) << "min(" << a[i] << ", " << b[i] << ")";
    EXPECT_EQ(bits(out[3][i]), bits(rule_max(a[i], b[i]))) << "max(" << a[i] << ", " << b[i] << ")";
    expected_mask |= (a[i] <= b[i] ? 1 : 0) << i;
  }
  EXPECT_EQ(mask, expected_mask);
}

TEST(Float4, SelectedImplementation) {
#if defined(RAYLAB_HAVE_SSE)
  static_assert(std::is_same_v<simd::Float4, simd::sse::Float4>);
#else
  static_assert(std::is_same_v<simd::Float4, sc::Float4>);
#endif
#if defined(RAYLAB_SIMD_SCALAR)
  EXPECT_TRUE((std::is_same_v<simd::Float4, sc::Float4>)) << "RAYLAB_SIMD_SCALAR must select the scalar Float4";
#elif defined(__x86_64__)
  EXPECT_FALSE((std::is_same_v<simd::Float4, sc::Float4>)) << "x86-64 builds use SSE";
#endif
}

TEST(Float4, ScalarAndSimdAgreeBitForBit) {
  Pcg32 rng(2024, 5);
  for (int iter = 0; iter < 20000 && !HasFailure(); ++iter) {
    const Lanes a = random_lanes(rng), b = random_lanes(rng);
    Lanes rs[4], rv[4];
    int ms = 0, mv = 0;
    check_ops<sc::Float4>(a, b, rs, ms);
    check_ops<simd::Float4>(a, b, rv, mv);
    for (int i = 0; i < 4; ++i) {
      const bool ok = same_arith(rs[0][i], rv[0][i]) && same_arith(rs[1][i], rv[1][i]) &&
                      bits(rs[2][i]) == bits(rv[2][i]) && bits(rs[3][i]) == bits(rv[3][i]);
      EXPECT_TRUE(ok) << "lane " << i << ": a=" << a[i] << " b=" << b[i];
    }
    EXPECT_EQ(ms, mv) << "less_equal_mask";
  }
}

// sqrt and copysign, lane by lane against std::sqrt and std::copysign, on random and special
// values: both implementations bit for bit (the sphere blocks rely on it).
TEST(Float4, SqrtAndCopysignMatchTheStandardLibrary) {
  Pcg32 rng(77, 3);
  const auto& special = special_values();
  for (int iter = 0; iter < 20000 && !HasFailure(); ++iter) {
    Lanes a = random_lanes(rng), b = random_lanes(rng);
    if (iter < int(special.size())) a[0] = special[iter], b[1] = special[iter], a[2] = -special[iter];
    const Lanes sq_s = lanes(sqrt(make<sc::Float4>(a))), sq_v = lanes(sqrt(make<simd::Float4>(a)));
    const Lanes cs_s = lanes(copysign(make<sc::Float4>(a), make<sc::Float4>(b)));
    const Lanes cs_v = lanes(copysign(make<simd::Float4>(a), make<simd::Float4>(b)));
    for (int i = 0; i < 4; ++i) {
      const volatile float x = a[i], y = b[i];
      EXPECT_TRUE(same_arith(sq_s[i], std::sqrt(x))) << "sqrt(" << a[i] << ")";
      EXPECT_TRUE(same_arith(sq_v[i], std::sqrt(x))) << "sqrt(" << a[i] << ")";
      EXPECT_EQ(bits(cs_s[i]), bits(std::copysign(x, y))) << "copysign(" << a[i] << ", " << b[i] << ")";
      EXPECT_EQ(bits(cs_v[i]), bits(std::copysign(x, y))) << "copysign(" << a[i] << ", " << b[i] << ")";
    }
  }
}

// Every pair of special values, in every lane.
TEST(Float4, SpecialValuePairs) {
  const auto& v = special_values();
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (std::size_t j = 0; j < v.size(); ++j) {
      const Lanes a = {v[i], v[j], v[i], -v[j]}, b = {v[j], v[i], -v[j], v[i]};
      Lanes rs[4], rv[4];
      int ms = 0, mv = 0;
      check_ops<sc::Float4>(a, b, rs, ms);
      check_ops<simd::Float4>(a, b, rv, mv);
      for (int k = 0; k < 4; ++k) {
        EXPECT_TRUE(same_arith(rs[0][k], rv[0][k]) && same_arith(rs[1][k], rv[1][k]));
        EXPECT_EQ(bits(rs[2][k]), bits(rv[2][k]));
        EXPECT_EQ(bits(rs[3][k]), bits(rv[3][k]));
      }
      EXPECT_EQ(ms, mv);
      if (HasFailure()) return;
    }
  }
}

template <class F>
void check_nan_rule() {
  const float nan_a = from_bits(0x7fc00aaau), nan_b = from_bits(0xffc00bbbu), inf = INFINITY;
  // min(NaN, b) == b and min(a, NaN) == that NaN: the second operand, bits unchanged.
  const Lanes a = {nan_a, 1.f, nan_a, -inf}, b = {2.f, nan_b, nan_b, nan_b};
  const Lanes lo = lanes(min(make<F>(a), make<F>(b))), hi = lanes(max(make<F>(a), make<F>(b)));
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(bits(lo[i]), bits(b[i])) << "min lane " << i;
    EXPECT_EQ(bits(hi[i]), bits(b[i])) << "max lane " << i;
  }
  // Equal operands (+0 and -0 compare equal): also the second one.
  const Lanes z1 = {0.f, -0.f, 0.f, -0.f}, z2 = {-0.f, 0.f, 0.f, -0.f};
  const Lanes zmin = lanes(min(make<F>(z1), make<F>(z2))), zmax = lanes(max(make<F>(z1), make<F>(z2)));
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(bits(zmin[i]), bits(z2[i])) << "min of zeros, lane " << i;
    EXPECT_EQ(bits(zmax[i]), bits(z2[i])) << "max of zeros, lane " << i;
  }
  // Ordinary values, and infinities.
  const Lanes p = {1.f, -inf, 5.f, inf}, q = {2.f, 0.f, -5.f, 3.f};
  EXPECT_EQ(lanes(min(make<F>(p), make<F>(q))), (Lanes{1.f, -inf, -5.f, 3.f}));
  EXPECT_EQ(lanes(max(make<F>(p), make<F>(q))), (Lanes{2.f, 0.f, 5.f, inf}));
  // The traversal's use: a NaN slab distance passed first leaves the running value.
  const Lanes running = {0.f, 1.f, 2.f, 3.f}, slab = {nan_a, 0.5f, nan_b, 7.f};
  EXPECT_EQ(lanes(max(make<F>(slab), make<F>(running))), (Lanes{0.f, 1.f, 2.f, 7.f}));
  EXPECT_EQ(lanes(min(make<F>(slab), make<F>(running))), (Lanes{0.f, 0.5f, 2.f, 3.f}));
  // less_equal_mask: bit i for lane i; clear for NaN; +0 <= -0; -inf <= inf.
  EXPECT_EQ(less_equal_mask(make<F>({1.f, nan_a, 3.f, -inf}), make<F>({1.f, 2.f, nan_b, inf})), 0b1001);
  EXPECT_EQ(less_equal_mask(make<F>({0.f, 2.f, -1.f, inf}), make<F>({-0.f, 1.f, 0.f, inf})), 0b1101);
  EXPECT_EQ(less_equal_mask(make<F>({nan_a, nan_a, nan_a, nan_a}), make<F>({nan_a, nan_a, nan_a, nan_a})), 0);
}

TEST(Float4, NanRuleScalar) { check_nan_rule<sc::Float4>(); }
TEST(Float4, NanRuleSimd) { check_nan_rule<simd::Float4>(); }

template <class F>
void check_round_trips() {
  // load/store from and to unaligned addresses keep every bit (NaN payloads, signaling NaN).
  alignas(16) float src[9], dst[9];
  const auto& v = special_values();
  for (std::size_t start = 0; start + 4 <= v.size(); ++start) {
    for (int offset = 0; offset < 4; ++offset) {
      for (int i = 0; i < 9; ++i) src[i] = dst[i] = from_bits(0x12345678u);
      for (int i = 0; i < 4; ++i) src[offset + i] = v[start + i];
      F::load(src + offset).store(dst + 4 - offset);
      for (int i = 0; i < 4; ++i) EXPECT_EQ(bits(dst[4 - offset + i]), bits(v[start + i]));
      for (int i = 0; i < 4 - offset; ++i) EXPECT_EQ(bits(dst[i]), 0x12345678u) << "store wrote before its range";
      for (int i = 8 - offset; i < 9; ++i) EXPECT_EQ(bits(dst[i]), 0x12345678u) << "store wrote past its range";
    }
  }
  // broadcast puts the same bits in every lane.
  for (const float x : v) {
    const Lanes l = lanes(F::broadcast(x));
    for (int i = 0; i < 4; ++i) EXPECT_EQ(bits(l[i]), bits(x)) << "lane " << i << " of broadcast(" << x << ")";
  }
}

TEST(Float4, LoadStoreBroadcastScalar) { check_round_trips<sc::Float4>(); }
TEST(Float4, LoadStoreBroadcastSimd) { check_round_trips<simd::Float4>(); }

}  // namespace
}  // namespace raylab
