// The W-wide float types of the wide BVH's box test and the Double4 of the triangle block test
// must be interchangeable with their scalar versions: scalar::WideFloat<W> follows the documented
// rules (IEEE single precision arithmetic; min and max return the SECOND operand when either is
// NaN; less_equal_mask clear for NaN; sqrt and copysign as std's), and the native avx::Float8 /
// avx512::Float16 (where this build has them) give the same bits lane by lane, on ordinary
// values, NaN in either position, infinities, signed zeros and denormals. Double4 must widen
// exactly and round back as a scalar cast does, so that the SIMD triangle test equals the scalar
// one bit for bit. Also the Float4 operations the triangle block test added (+, /, less_mask,
// equal_mask).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/simd/double4.h"
#include "raylab/simd/float4.h"
#include "raylab/simd/wide_float.h"
#include "simd_test_util.h"

namespace raylab {
namespace {

namespace sc = simd::scalar;
using namespace test;  // simd_test_util.h

template <int W>
using Lanes = std::array<float, W>;

template <int W, class F>
Lanes<W> lanes(const F& f) {
  Lanes<W> out;
  f.store(out.data());
  return out;
}

// The results of every operation of one implementation on (a, b).
template <int W>
struct Results {
  Lanes<W> sub, mul, lo, hi, root, sign;
  unsigned le = 0;
};

// Runs every operation of F on (a, b) and checks each lane against the rules.
template <int W, class F>
Results<W> run_ops(const Lanes<W>& a, const Lanes<W>& b) {
  const F fa = F::load(a.data()), fb = F::load(b.data());
  Results<W> r;
  r.sub = lanes<W>(fa - fb);
  r.mul = lanes<W>(fa * fb);
  r.lo = lanes<W>(min(fa, fb));
  r.hi = lanes<W>(max(fa, fb));
  r.le = static_cast<unsigned>(less_equal_mask(fa, fb));
  r.root = lanes<W>(sqrt(fa));
  r.sign = lanes<W>(copysign(fa, fb));
  unsigned expected = 0;
  for (int i = 0; i < W; ++i) {
    const volatile float x = a[i], y = b[i];  // volatile: the reference is plain scalar code
    EXPECT_TRUE(same_arith(r.sub[i], x - y)) << a[i] << " - " << b[i];
    EXPECT_TRUE(same_arith(r.mul[i], x * y)) << a[i] << " * " << b[i];
    EXPECT_EQ(bits(r.lo[i]), bits(rule_min(a[i], b[i]))) << "min(" << a[i] << ", " << b[i] << ")";
    EXPECT_EQ(bits(r.hi[i]), bits(rule_max(a[i], b[i]))) << "max(" << a[i] << ", " << b[i] << ")";
    EXPECT_TRUE(same_arith(r.root[i], std::sqrt(x))) << "sqrt(" << a[i] << ")";
    EXPECT_EQ(bits(r.sign[i]), bits(std::copysign(a[i], b[i]))) << "copysign(" << a[i] << ", " << b[i] << ")";
    expected |= (a[i] <= b[i] ? 1u : 0u) << i;
  }
  EXPECT_EQ(r.le, expected) << "less_equal_mask";
  return r;
}

// The scalar reference and implementation F give the same lanes.
template <int W, class F>
void compare_with_scalar(const Lanes<W>& a, const Lanes<W>& b) {
  const Results<W> s = run_ops<W, sc::WideFloat<W>>(a, b);
  const Results<W> v = run_ops<W, F>(a, b);
  for (int i = 0; i < W; ++i) {
    EXPECT_TRUE(same_arith(s.sub[i], v.sub[i]) && same_arith(s.mul[i], v.mul[i])) << "lane " << i;
    EXPECT_EQ(bits(s.lo[i]), bits(v.lo[i])) << "min, lane " << i;
    EXPECT_EQ(bits(s.hi[i]), bits(v.hi[i])) << "max, lane " << i;
    EXPECT_TRUE(same_arith(s.root[i], v.root[i])) << "sqrt, lane " << i;
    EXPECT_EQ(bits(s.sign[i]), bits(v.sign[i])) << "copysign, lane " << i;
  }
  EXPECT_EQ(s.le, v.le);
}

template <int W, class F>
void check_random(std::uint64_t seed) {
  Pcg32 rng(seed, 9);
  for (int iter = 0; iter < 4000 && !::testing::Test::HasFailure(); ++iter) {
    Lanes<W> a, b;
    for (int i = 0; i < W; ++i) a[i] = random_value(rng), b[i] = random_value(rng);
    compare_with_scalar<W, F>(a, b);
  }
}

// Every ordered pair of special values, each in every lane position (so NaN in either operand
// and in every lane).
template <int W, class F>
void check_special_pairs() {
  const auto& v = special_values();
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (std::size_t j = 0; j < v.size(); ++j) {
      Lanes<W> a, b;
      for (int k = 0; k < W; ++k) {
        const std::size_t p = (i + std::size_t(k)) % v.size(), q = (j + std::size_t(k) * 3) % v.size();
        a[k] = k % 2 ? v[q] : v[p];
        b[k] = k % 2 ? v[p] : v[q];
      }
      compare_with_scalar<W, F>(a, b);
      if (::testing::Test::HasFailure()) return;
    }
  }
}

// load and store keep every bit (NaN payloads, signaling NaN) at unaligned addresses and write
// only their W floats; broadcast puts the same bits in every lane.
template <int W, class F>
void check_round_trips() {
  const auto& v = special_values();
  std::vector<float> src(W + 8), dst(W + 8);
  for (int offset = 0; offset < 4; ++offset) {
    for (float& x : src) x = from_bits(0x12345678u);
    for (float& x : dst) x = from_bits(0x12345678u);
    for (int i = 0; i < W; ++i) src[std::size_t(offset + i)] = v[std::size_t(i) % v.size()];
    F::load(src.data() + offset).store(dst.data() + 3 - offset);
    for (int i = 0; i < W + 8; ++i) {
      const bool inside = i >= 3 - offset && i < 3 - offset + W;
      const std::uint32_t expected = inside ? bits(v[std::size_t(i - (3 - offset)) % v.size()]) : 0x12345678u;
      EXPECT_EQ(bits(dst[std::size_t(i)]), expected) << "offset " << offset << " index " << i;
    }
  }
  for (const float x : v) {
    const Lanes<W> l = lanes<W>(F::broadcast(x));
    for (int i = 0; i < W; ++i) EXPECT_EQ(bits(l[i]), bits(x)) << "lane " << i;
  }
}

// The fixed cases the box test depends on: a NaN slab distance passed first leaves the running
// value; empty-slot sentinels (+inf - o) * inv never compare <= a finite far distance.
template <int W, class F>
void check_documented_cases() {
  const float nan_a = from_bits(0x7fc00aaau), nan_b = from_bits(0xffc00bbbu), inf = INFINITY;
  Lanes<W> slab, running, a, b;
  for (int i = 0; i < W; ++i) {
    slab[i] = i % 3 == 0 ? nan_a : (i % 3 == 1 ? float(i) - 4.f : nan_b);
    running[i] = float(i) * 0.5f;
    a[i] = i % 4 == 0 ? nan_a : (i % 4 == 1 ? 0.f : (i % 4 == 2 ? -inf : 1.f));
    b[i] = i % 4 == 0 ? 1.f : (i % 4 == 1 ? -0.f : (i % 4 == 2 ? inf : nan_b));
  }
  const F fs = F::load(slab.data()), fr = F::load(running.data());
  const Lanes<W> lo = lanes<W>(min(fs, fr)), hi = lanes<W>(max(fs, fr));
  for (int i = 0; i < W; ++i) {
    const float expect_lo = std::isnan(slab[i]) ? running[i] : std::min(slab[i], running[i]);
    const float expect_hi = std::isnan(slab[i]) ? running[i] : std::max(slab[i], running[i]);
    EXPECT_EQ(bits(lo[i]), bits(expect_lo)) << "lane " << i;
    EXPECT_EQ(bits(hi[i]), bits(expect_hi)) << "lane " << i;
  }
  // NaN <= 1: clear; 0 <= -0: set; -inf <= inf: set; 1 <= NaN: clear.
  unsigned expected = 0;
  for (int i = 0; i < W; ++i) expected |= (i % 4 == 1 || i % 4 == 2 ? 1u : 0u) << i;
  EXPECT_EQ(static_cast<unsigned>(less_equal_mask(F::load(a.data()), F::load(b.data()))), expected);
  // Equal operands: min and max return the second one (+0 and -0 compare equal).
  Lanes<W> z1, z2;
  for (int i = 0; i < W; ++i) z1[i] = i % 2 ? -0.f : 0.f, z2[i] = i % 3 ? 0.f : -0.f;
  const Lanes<W> zlo = lanes<W>(min(F::load(z1.data()), F::load(z2.data())));
  const Lanes<W> zhi = lanes<W>(max(F::load(z1.data()), F::load(z2.data())));
  for (int i = 0; i < W; ++i) {
    EXPECT_EQ(bits(zlo[i]), bits(z2[i])) << "lane " << i;
    EXPECT_EQ(bits(zhi[i]), bits(z2[i])) << "lane " << i;
  }
  // Every lane of the mask reachable on its own (bit i is lane i, for all W bits).
  for (int k = 0; k < W; ++k) {
    Lanes<W> x, y;
    for (int i = 0; i < W; ++i) x[i] = i == k ? 0.f : 2.f, y[i] = 1.f;
    EXPECT_EQ(static_cast<unsigned>(less_equal_mask(F::load(x.data()), F::load(y.data()))), 1u << k);
  }
}

template <int W, class F>
void check_all(std::uint64_t seed) {
  check_documented_cases<W, F>();
  check_round_trips<W, F>();
  check_special_pairs<W, F>();
  check_random<W, F>(seed);
}

// The scalar reference on its own (compared with itself, every lane is checked against the rules).
TEST(WideFloat, ScalarFollowsTheRules) {
  check_all<4, sc::WideFloat<4>>(1);
  check_all<8, sc::WideFloat<8>>(2);
  check_all<16, sc::WideFloat<16>>(3);
}

// What simd::WideFloat<W> names in this build: whatever it is, it equals the scalar reference.
TEST(WideFloat, SelectedEqualsScalar) {
  check_all<4, simd::WideFloat<4>>(4);
  check_all<8, simd::WideFloat<8>>(5);
  check_all<16, simd::WideFloat<16>>(6);
}

TEST(WideFloat, SelectedImplementation) {
  static_assert(std::is_same_v<simd::WideFloat<4>, simd::Float4>);
#if defined(RAYLAB_SIMD_SCALAR)
  static_assert(std::is_same_v<simd::WideFloat<8>, sc::WideFloat<8>>);
  static_assert(std::is_same_v<simd::WideFloat<16>, sc::WideFloat<16>>);
  static_assert(simd::kNativeBoxWidth == 8);
#else
#if defined(__AVX__)
  static_assert(std::is_same_v<simd::WideFloat<8>, simd::avx::Float8>);
#endif
#if defined(__AVX512F__)
  static_assert(std::is_same_v<simd::WideFloat<16>, simd::avx512::Float16>);
  static_assert(simd::kNativeBoxWidth == 16);
#else
  static_assert(simd::kNativeBoxWidth == 8);
#endif
#endif
  SUCCEED();
}

#if !defined(RAYLAB_SIMD_SCALAR) && defined(__AVX__)
TEST(WideFloat, Avx8EqualsScalar) { check_all<8, simd::avx::Float8>(7); }
#endif
#if !defined(RAYLAB_SIMD_SCALAR) && defined(__AVX512F__)
TEST(WideFloat, Avx512x16EqualsScalar) { check_all<16, simd::avx512::Float16>(8); }
#endif

// ---------------------------------------------------------------------------------------------
// Float4's operations of the triangle test: +, /, less_mask, equal_mask.

template <class F>
void float4_ops(const Lanes<4>& a, const Lanes<4>& b, Lanes<4>& sum, Lanes<4>& quot, int& lt, int& eq) {
  const F fa = F::load(a.data()), fb = F::load(b.data());
  sum = lanes<4>(fa + fb);
  quot = lanes<4>(fa / fb);
  lt = less_mask(fa, fb);
  eq = equal_mask(fa, fb);
  int expect_lt = 0, expect_eq = 0;
  for (int i = 0; i < 4; ++i) {
    const volatile float x = a[i], y = b[i];
    EXPECT_TRUE(same_arith(sum[i], x + y)) << a[i] << " + " << b[i];
    EXPECT_TRUE(same_arith(quot[i], x / y)) << a[i] << " / " << b[i];
    expect_lt |= (a[i] < b[i] ? 1 : 0) << i;
    expect_eq |= (a[i] == b[i] ? 1 : 0) << i;
  }
  EXPECT_EQ(lt, expect_lt);
  EXPECT_EQ(eq, expect_eq);
}

TEST(Float4, AddDivideLessEqualMasks) {
  Pcg32 rng(11, 2);
  const auto& v = special_values();
  for (int iter = 0; iter < 20000 && !HasFailure(); ++iter) {
    Lanes<4> a, b;
    for (int i = 0; i < 4; ++i) {
      if (iter < int(v.size() * v.size())) {  // first every pair of special values
        a[i] = v[std::size_t(iter) / v.size()], b[i] = v[std::size_t(iter) % v.size()];
        if (i % 2) std::swap(a[i], b[i]);
      } else {
        a[i] = random_value(rng), b[i] = random_value(rng);
      }
    }
    Lanes<4> ss, sq, vs, vq;
    int sl = 0, se = 0, vl = 0, ve = 0;
    float4_ops<sc::Float4>(a, b, ss, sq, sl, se);
    float4_ops<simd::Float4>(a, b, vs, vq, vl, ve);
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(same_arith(ss[i], vs[i]) && same_arith(sq[i], vq[i])) << "lane " << i;
    EXPECT_EQ(sl, vl);
    EXPECT_EQ(se, ve);
  }
  // Signed zeros compare equal and not less; NaN is neither.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Lanes<4> a = {0.f, -0.f, nan, 1.f}, b = {-0.f, 0.f, nan, nan};
  EXPECT_EQ(equal_mask(simd::Float4::load(a.data()), simd::Float4::load(b.data())), 0b0011);
  EXPECT_EQ(less_mask(simd::Float4::load(a.data()), simd::Float4::load(b.data())), 0);
}

// ---------------------------------------------------------------------------------------------
// Double4

template <class D>
struct DoubleOps {
  // The edge-function form of the triangle test: (a * b - c * d) in double, rounded to float.
  static Lanes<4> edge(const Lanes<4>& a, const Lanes<4>& b, const Lanes<4>& c, const Lanes<4>& d) {
    using F = decltype(D::from(std::declval<simd::Float4>()).to_float());
    const D da = D::from(F::load(a.data())), db = D::from(F::load(b.data())), dc = D::from(F::load(c.data())),
            dd = D::from(F::load(d.data()));
    return lanes<4>((da * db - dc * dd).to_float());
  }
  // Widening and rounding back: every float survives.
  static Lanes<4> round_trip(const Lanes<4>& a) {
    using F = decltype(D::from(std::declval<simd::Float4>()).to_float());
    return lanes<4>(D::from(F::load(a.data())).to_float());
  }
};

// scalar::Double4::from takes a scalar::Float4; the SIMD one takes simd::Float4. A thin adapter
// so that both run from the same lanes.
struct ScalarDouble4 {
  sc::Double4 d;
  static ScalarDouble4 from(const simd::Float4& f) {
    Lanes<4> l;
    f.store(l.data());
    return {sc::Double4::from(sc::Float4::load(l.data()))};
  }
  simd::Float4 to_float() const {
    Lanes<4> l;
    d.to_float().store(l.data());
    return simd::Float4::load(l.data());
  }
  friend ScalarDouble4 operator-(const ScalarDouble4& a, const ScalarDouble4& b) { return {a.d - b.d}; }
  friend ScalarDouble4 operator*(const ScalarDouble4& a, const ScalarDouble4& b) { return {a.d * b.d}; }
};

// The scalar expression the triangle test is written with, one lane at a time.
float scalar_edge(float a, float b, float c, float d) {
  return static_cast<float>(double(a) * double(b) - double(c) * double(d));
}

TEST(Double4, SelectedImplementation) {
#if !defined(RAYLAB_SIMD_SCALAR) && defined(__AVX__)
  static_assert(std::is_same_v<simd::Double4, simd::avx::Double4>);
#elif !defined(RAYLAB_SIMD_SCALAR) && defined(__SSE2__)
  static_assert(std::is_same_v<simd::Double4, simd::sse::Double4>);  // double4_sse_test.cpp
#else
  static_assert(std::is_same_v<simd::Double4, sc::Double4>);
#endif
  SUCCEED();
}

// Products of floats of every magnitude: exact in double, then one rounding to float, with
// overflow to infinity, underflow to denormals and zero, ties to even, NaN and infinite inputs.
TEST(Double4, EdgeFunctionsEqualScalarCode) {
  Pcg32 rng(12, 4);
  const auto& v = special_values();
  for (int iter = 0; iter < 30000 && !HasFailure(); ++iter) {
    Lanes<4> a, b, c, d;
    for (int i = 0; i < 4; ++i) {
      if (iter % 3 == 0) {
        a[i] = random_value(rng), b[i] = random_value(rng), c[i] = random_value(rng), d[i] = random_value(rng);
      } else {
        // Ordinary floats with random exponents, so products span the double range.
        auto any = [&] {
          const float m = 1.f + rng.next_float();
          const int e = static_cast<int>(rng.next_u32() % 300) - 150;
          return std::ldexp(rng.next_float() < 0.5f ? m : -m, e);
        };
        a[i] = any(), b[i] = any(), c[i] = any(), d[i] = any();
        if (iter % 3 == 1) c[i] = a[i], d[i] = std::nextafter(b[i], 0.f);  // cancellation
      }
    }
    if (iter < int(v.size())) a[0] = v[std::size_t(iter)], d[3] = v[std::size_t(iter)];
    const Lanes<4> simd_edge = DoubleOps<simd::Double4>::edge(a, b, c, d);
    const Lanes<4> scalar_simd = DoubleOps<ScalarDouble4>::edge(a, b, c, d);
    for (int i = 0; i < 4; ++i) {
      const float expected = scalar_edge(a[i], b[i], c[i], d[i]);
      EXPECT_TRUE(same_arith(simd_edge[i], expected))
          << a[i] << " * " << b[i] << " - " << c[i] << " * " << d[i] << ": " << simd_edge[i] << " vs " << expected;
      EXPECT_TRUE(same_arith(scalar_simd[i], expected)) << "scalar Double4, lane " << i;
    }
  }
  // Ties to even: (1 + 2^-12)^2 = 1 + 2^-11 + 2^-24 lies halfway between two floats.
  const float x = 1.f + 0x1p-12f;
  const Lanes<4> a = {x, -x, x, 0x1p64f}, b = {x, x, x, 0x1p64f}, zero = {0.f, 0.f, 0.f, 0.f};
  const Lanes<4> r = DoubleOps<simd::Double4>::edge(a, b, zero, zero);
  EXPECT_EQ(r[0], 1.f + 0x1p-11f);
  EXPECT_EQ(r[1], -(1.f + 0x1p-11f));
  EXPECT_EQ(r[3], INFINITY) << "2^128 overflows float";
}

TEST(Double4, WidenAndRoundBackKeepsEveryFloat) {
  Pcg32 rng(13, 4);
  for (int iter = 0; iter < 20000; ++iter) {
    Lanes<4> a;
    for (float& x : a) x = random_value(rng);
    const Lanes<4> r = DoubleOps<simd::Double4>::round_trip(a);
    const Lanes<4> s = DoubleOps<ScalarDouble4>::round_trip(a);
    for (int i = 0; i < 4; ++i) {
      // A signaling NaN comes back quiet; everything else bit for bit.
      if (std::isnan(a[i])) {
        EXPECT_TRUE(std::isnan(r[i]) && std::isnan(s[i]));
      } else {
        EXPECT_EQ(bits(r[i]), bits(a[i])) << a[i];
        EXPECT_EQ(bits(s[i]), bits(a[i])) << a[i];
      }
    }
    if (HasFailure()) return;
  }
}

}  // namespace
}  // namespace raylab
