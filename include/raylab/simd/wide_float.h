#pragma once
/// \file
/// W floats as one value (W = 4, 8 or 16), for the box tests of the wide BVH. `scalar::WideFloat<W>`
/// is a plain array, always built and tested; `WideFloat<W>` names the best implementation this
/// build enables: SSE for 4, AVX for 8, AVX-512 for 16 (scalar otherwise, and everywhere with
/// -DRAYLAB_SIMD_SCALAR=ON). Same NaN rule as Float4: min and max return the SECOND operand when
/// either is NaN.

#include <cmath>
#include <cstring>

#include "raylab/simd/isa_namespace.h"

#include "raylab/simd/float4.h"

#if !defined(RAYLAB_SIMD_SCALAR) && (defined(__AVX__) || defined(__AVX512F__))
#include <immintrin.h>
#endif

namespace raylab::simd {
RAYLAB_ISA_BEGIN

namespace scalar {

/// W floats in an array.
template <int W>
struct WideFloat {
  float v[W];

  /// Loads W consecutive floats.
  static WideFloat load(const float* p) {
    WideFloat r;
    std::memcpy(r.v, p, sizeof r.v);
    return r;
  }
  /// All lanes equal to `x`.
  static WideFloat broadcast(float x) {
    WideFloat r;
    for (int i = 0; i < W; ++i) r.v[i] = x;
    return r;
  }
  /// Stores the lanes to `p[0..W-1]`.
  void store(float* p) const { std::memcpy(p, v, sizeof v); }
};

template <int W>
inline WideFloat<W> operator-(const WideFloat<W>& a, const WideFloat<W>& b) {
  WideFloat<W> r;
  for (int i = 0; i < W; ++i) r.v[i] = a.v[i] - b.v[i];
  return r;
}
template <int W>
inline WideFloat<W> operator*(const WideFloat<W>& a, const WideFloat<W>& b) {
  WideFloat<W> r;
  for (int i = 0; i < W; ++i) r.v[i] = a.v[i] * b.v[i];
  return r;
}
template <int W>
inline WideFloat<W> operator+(const WideFloat<W>& a, const WideFloat<W>& b) {
  WideFloat<W> r;
  for (int i = 0; i < W; ++i) r.v[i] = a.v[i] + b.v[i];
  return r;
}
template <int W>
inline WideFloat<W> operator/(const WideFloat<W>& a, const WideFloat<W>& b) {
  WideFloat<W> r;
  for (int i = 0; i < W; ++i) r.v[i] = a.v[i] / b.v[i];
  return r;
}
/// Lane-wise correctly rounded square root (NaN below zero, as std::sqrt).
template <int W>
inline WideFloat<W> sqrt(const WideFloat<W>& a) {
  WideFloat<W> r;
  for (int i = 0; i < W; ++i) r.v[i] = std::sqrt(a.v[i]);
  return r;
}
/// Lane-wise the magnitude of `magnitude` with the sign bit of `sign` (std::copysign).
template <int W>
inline WideFloat<W> copysign(const WideFloat<W>& magnitude, const WideFloat<W>& sign) {
  WideFloat<W> r;
  for (int i = 0; i < W; ++i) r.v[i] = std::copysign(magnitude.v[i], sign.v[i]);
  return r;
}
/// Lane-wise float(double(a) * double(b) - double(c) * double(d)): both products are exact in
/// double, so the result is the exact difference rounded (twice, as the scalar expression does).
template <int W>
inline WideFloat<W> difference_of_products(const WideFloat<W>& a, const WideFloat<W>& b, const WideFloat<W>& c,
                                           const WideFloat<W>& d) {
  WideFloat<W> r;
  for (int i = 0; i < W; ++i) {
    r.v[i] = static_cast<float>(double(a.v[i]) * double(b.v[i]) - double(c.v[i]) * double(d.v[i]));
  }
  return r;
}
/// Lane-wise a < b ? a : b (so b when either is NaN).
template <int W>
inline WideFloat<W> min(const WideFloat<W>& a, const WideFloat<W>& b) {
  WideFloat<W> r;
  for (int i = 0; i < W; ++i) r.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i];
  return r;
}
/// Lane-wise a > b ? a : b (so b when either is NaN).
template <int W>
inline WideFloat<W> max(const WideFloat<W>& a, const WideFloat<W>& b) {
  WideFloat<W> r;
  for (int i = 0; i < W; ++i) r.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i];
  return r;
}
/// Bit i set where a[i] <= b[i] (clear where either is NaN).
template <int W>
inline unsigned less_equal_mask(const WideFloat<W>& a, const WideFloat<W>& b) {
  unsigned m = 0;
  for (int i = 0; i < W; ++i) m |= (a.v[i] <= b.v[i] ? 1u : 0u) << i;
  return m;
}
/// Bit i set where a[i] < b[i] (clear where either is NaN).
template <int W>
inline unsigned less_mask(const WideFloat<W>& a, const WideFloat<W>& b) {
  unsigned m = 0;
  for (int i = 0; i < W; ++i) m |= (a.v[i] < b.v[i] ? 1u : 0u) << i;
  return m;
}
/// Bit i set where a[i] == b[i] (clear where either is NaN).
template <int W>
inline unsigned equal_mask(const WideFloat<W>& a, const WideFloat<W>& b) {
  unsigned m = 0;
  for (int i = 0; i < W; ++i) m |= (a.v[i] == b.v[i] ? 1u : 0u) << i;
  return m;
}

}  // namespace scalar

#if !defined(RAYLAB_SIMD_SCALAR) && defined(__AVX__)
namespace avx {

/// Eight floats in one AVX register.
struct Float8 {
  __m256 v;

  /// Loads 8 consecutive floats.
  static Float8 load(const float* p) { return {_mm256_loadu_ps(p)}; }
  /// All lanes equal to `x`.
  static Float8 broadcast(float x) { return {_mm256_set1_ps(x)}; }
  /// Stores the lanes to `p[0..7]`.
  void store(float* p) const { _mm256_storeu_ps(p, v); }
};

inline Float8 operator-(Float8 a, Float8 b) { return {_mm256_sub_ps(a.v, b.v)}; }
inline Float8 operator*(Float8 a, Float8 b) { return {_mm256_mul_ps(a.v, b.v)}; }
inline Float8 operator+(Float8 a, Float8 b) { return {_mm256_add_ps(a.v, b.v)}; }
inline Float8 operator/(Float8 a, Float8 b) { return {_mm256_div_ps(a.v, b.v)}; }
/// Lane-wise correctly rounded square root: VSQRTPS.
inline Float8 sqrt(Float8 a) { return {_mm256_sqrt_ps(a.v)}; }
/// Lane-wise the magnitude of `magnitude` with the sign bit of `sign` (std::copysign).
inline Float8 copysign(Float8 magnitude, Float8 sign) {
  const __m256 sign_bit = _mm256_set1_ps(-0.f);
  return {_mm256_or_ps(_mm256_andnot_ps(sign_bit, magnitude.v), _mm256_and_ps(sign_bit, sign.v))};
}
/// Lane-wise float(double(a) * double(b) - double(c) * double(d)), in two halves of four doubles.
inline Float8 difference_of_products(Float8 a, Float8 b, Float8 c, Float8 d) {
  auto half = [&](auto take) {
    return _mm256_cvtpd_ps(_mm256_sub_pd(_mm256_mul_pd(_mm256_cvtps_pd(take(a.v)), _mm256_cvtps_pd(take(b.v))),
                                         _mm256_mul_pd(_mm256_cvtps_pd(take(c.v)), _mm256_cvtps_pd(take(d.v)))));
  };
  const __m128 lo = half([](__m256 x) { return _mm256_castps256_ps128(x); });
  const __m128 hi = half([](__m256 x) { return _mm256_extractf128_ps(x, 1); });
  return {_mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1)};
}
/// Lane-wise a < b ? a : b (so b when either is NaN): VMINPS.
inline Float8 min(Float8 a, Float8 b) { return {_mm256_min_ps(a.v, b.v)}; }
/// Lane-wise a > b ? a : b (so b when either is NaN): VMAXPS.
inline Float8 max(Float8 a, Float8 b) { return {_mm256_max_ps(a.v, b.v)}; }
/// Bit i set where a[i] <= b[i] (clear where either is NaN; ordered, quiet compare).
inline unsigned less_equal_mask(Float8 a, Float8 b) {
  return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)));
}
/// Bit i set where a[i] < b[i] (clear where either is NaN).
inline unsigned less_mask(Float8 a, Float8 b) {
  return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)));
}
/// Bit i set where a[i] == b[i] (clear where either is NaN).
inline unsigned equal_mask(Float8 a, Float8 b) {
  return static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ)));
}

}  // namespace avx
#endif

#if !defined(RAYLAB_SIMD_SCALAR) && defined(__AVX512F__)
namespace avx512 {

/// Sixteen floats in one AVX-512 register.
struct Float16 {
  __m512 v;

  /// Loads 16 consecutive floats.
  static Float16 load(const float* p) { return {_mm512_loadu_ps(p)}; }
  /// All lanes equal to `x`.
  static Float16 broadcast(float x) { return {_mm512_set1_ps(x)}; }
  /// Stores the lanes to `p[0..15]`.
  void store(float* p) const { _mm512_storeu_ps(p, v); }
};

inline Float16 operator-(Float16 a, Float16 b) { return {_mm512_sub_ps(a.v, b.v)}; }
inline Float16 operator*(Float16 a, Float16 b) { return {_mm512_mul_ps(a.v, b.v)}; }
inline Float16 operator+(Float16 a, Float16 b) { return {_mm512_add_ps(a.v, b.v)}; }
inline Float16 operator/(Float16 a, Float16 b) { return {_mm512_div_ps(a.v, b.v)}; }
/// Lane-wise correctly rounded square root: VSQRTPS.
inline Float16 sqrt(Float16 a) { return {_mm512_sqrt_ps(a.v)}; }
/// Lane-wise the magnitude of `magnitude` with the sign bit of `sign` (std::copysign): one
/// bitwise select, since AVX-512F alone has no float AND.
inline Float16 copysign(Float16 magnitude, Float16 sign) {
  const __m512i sign_bit = _mm512_set1_epi32(static_cast<int>(0x80000000u));
  // Bit by bit, sign_bit ? sign : magnitude: truth table 0xCA over (sign_bit, sign, magnitude).
  return {_mm512_castsi512_ps(
      _mm512_ternarylogic_epi32(sign_bit, _mm512_castps_si512(sign.v), _mm512_castps_si512(magnitude.v), 0xCA))};
}
/// Lane-wise float(double(a) * double(b) - double(c) * double(d)), in two halves of eight doubles.
inline Float16 difference_of_products(Float16 a, Float16 b, Float16 c, Float16 d) {
  auto half = [&](auto take) {
    return _mm512_cvtpd_ps(_mm512_sub_pd(_mm512_mul_pd(_mm512_cvtps_pd(take(a.v)), _mm512_cvtps_pd(take(b.v))),
                                         _mm512_mul_pd(_mm512_cvtps_pd(take(c.v)), _mm512_cvtps_pd(take(d.v)))));
  };
  const __m256 lo = half([](__m512 x) { return _mm512_castps512_ps256(x); });
  const __m256 hi = half([](__m512 x) { return _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(x), 1)); });
  return {_mm512_castpd_ps(_mm512_insertf64x4(_mm512_castps_pd(_mm512_castps256_ps512(lo)), _mm256_castps_pd(hi), 1))};
}
// The zero-masking forms with every lane selected are plain VMINPS/VMAXPS; GCC 12's unmasked
// _mm512_min_ps/_mm512_max_ps start from an undefined register and raise -Wmaybe-uninitialized.
/// Lane-wise a < b ? a : b (so b when either is NaN): VMINPS.
inline Float16 min(Float16 a, Float16 b) { return {_mm512_maskz_min_ps(0xFFFF, a.v, b.v)}; }
/// Lane-wise a > b ? a : b (so b when either is NaN): VMAXPS.
inline Float16 max(Float16 a, Float16 b) { return {_mm512_maskz_max_ps(0xFFFF, a.v, b.v)}; }
/// Bit i set where a[i] <= b[i] (clear where either is NaN).
inline unsigned less_equal_mask(Float16 a, Float16 b) {
  return static_cast<unsigned>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ));
}
/// Bit i set where a[i] < b[i] (clear where either is NaN).
inline unsigned less_mask(Float16 a, Float16 b) {
  return static_cast<unsigned>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ));
}
/// Bit i set where a[i] == b[i] (clear where either is NaN).
inline unsigned equal_mask(Float16 a, Float16 b) {
  return static_cast<unsigned>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_EQ_OQ));
}

}  // namespace avx512
#endif

/// The best W-wide implementation of this build.
template <int W>
struct WideFloatOf {
  using type = scalar::WideFloat<W>;
};
template <>
struct WideFloatOf<4> {
  using type = Float4;  // SSE where built
};
#if !defined(RAYLAB_SIMD_SCALAR) && defined(__AVX__)
template <>
struct WideFloatOf<8> {
  using type = avx::Float8;
};
#endif
#if !defined(RAYLAB_SIMD_SCALAR) && defined(__AVX512F__)
template <>
struct WideFloatOf<16> {
  using type = avx512::Float16;
};
#endif

/// W floats: the SIMD type where this build has one for W, else the scalar array.
template <int W>
using WideFloat = typename WideFloatOf<W>::type;

/// The widest node this build tests with one instruction per plane: 16 with AVX-512, else 8.
#if !defined(RAYLAB_SIMD_SCALAR) && defined(__AVX512F__)
inline constexpr int kNativeBoxWidth = 16;
#else
inline constexpr int kNativeBoxWidth = 8;
#endif

RAYLAB_ISA_END
}  // namespace raylab::simd
