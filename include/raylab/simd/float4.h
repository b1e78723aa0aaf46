#pragma once
/// \file
/// Four floats as one value: the only place raylab's kernels get SIMD from. Two implementations
/// with one interface: `scalar::Float4` (a plain array, always built and tested) and, on x86-64,
/// `sse::Float4` (one __m128; SSE2 is part of the x86-64 baseline). `Float4` names the best one;
/// configure with -DRAYLAB_SIMD_SCALAR=ON to use the scalar one everywhere.
///
/// min and max follow the x86 rule on NaN, in both implementations: when either operand is NaN
/// the SECOND operand is returned. Kernels rely on it to ignore NaN slab distances, by passing
/// the running value second.

#include <cmath>
#include <cstring>

#include "raylab/simd/isa_namespace.h"

#if defined(__SSE2__) && !defined(RAYLAB_SIMD_SCALAR)
#include <immintrin.h>
#define RAYLAB_HAVE_SSE 1
#endif

namespace raylab::simd {
RAYLAB_ISA_BEGIN

namespace scalar {

/// Four floats in an array.
struct Float4 {
  float v[4];

  /// Loads 4 consecutive floats.
  static Float4 load(const float* p) {
    Float4 r;
    std::memcpy(r.v, p, sizeof r.v);
    return r;
  }
  /// All lanes equal to `x`.
  static Float4 broadcast(float x) { return {{x, x, x, x}}; }
  /// Stores the lanes to `p[0..3]`.
  void store(float* p) const { std::memcpy(p, v, sizeof v); }
};

inline Float4 operator-(const Float4& a, const Float4& b) {
  return {{a.v[0] - b.v[0], a.v[1] - b.v[1], a.v[2] - b.v[2], a.v[3] - b.v[3]}};
}
inline Float4 operator*(const Float4& a, const Float4& b) {
  return {{a.v[0] * b.v[0], a.v[1] * b.v[1], a.v[2] * b.v[2], a.v[3] * b.v[3]}};
}
inline Float4 operator+(const Float4& a, const Float4& b) {
  return {{a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2], a.v[3] + b.v[3]}};
}
inline Float4 operator/(const Float4& a, const Float4& b) {
  return {{a.v[0] / b.v[0], a.v[1] / b.v[1], a.v[2] / b.v[2], a.v[3] / b.v[3]}};
}
/// Lane-wise correctly rounded square root (NaN below zero, as std::sqrt).
inline Float4 sqrt(const Float4& a) {
  return {{std::sqrt(a.v[0]), std::sqrt(a.v[1]), std::sqrt(a.v[2]), std::sqrt(a.v[3])}};
}
/// Lane-wise the magnitude of `magnitude` with the sign bit of `sign` (std::copysign).
inline Float4 copysign(const Float4& magnitude, const Float4& sign) {
  Float4 r;
  for (int i = 0; i < 4; ++i) r.v[i] = std::copysign(magnitude.v[i], sign.v[i]);
  return r;
}
/// Lane-wise a < b ? a : b (so b when either is NaN).
inline Float4 min(const Float4& a, const Float4& b) {
  Float4 r;
  for (int i = 0; i < 4; ++i) r.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i];
  return r;
}
/// Lane-wise a > b ? a : b (so b when either is NaN).
inline Float4 max(const Float4& a, const Float4& b) {
  Float4 r;
  for (int i = 0; i < 4; ++i) r.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i];
  return r;
}
/// Bit i set where a[i] <= b[i] (clear where either is NaN).
inline int less_equal_mask(const Float4& a, const Float4& b) {
  int m = 0;
  for (int i = 0; i < 4; ++i) m |= (a.v[i] <= b.v[i] ? 1 : 0) << i;
  return m;
}
/// Bit i set where a[i] < b[i] (clear where either is NaN).
inline int less_mask(const Float4& a, const Float4& b) {
  int m = 0;
  for (int i = 0; i < 4; ++i) m |= (a.v[i] < b.v[i] ? 1 : 0) << i;
  return m;
}
/// Bit i set where a[i] == b[i] (clear where either is NaN).
inline int equal_mask(const Float4& a, const Float4& b) {
  int m = 0;
  for (int i = 0; i < 4; ++i) m |= (a.v[i] == b.v[i] ? 1 : 0) << i;
  return m;
}

}  // namespace scalar

#ifdef RAYLAB_HAVE_SSE
namespace sse {

/// Four floats in one SSE register.
struct Float4 {
  __m128 v;

  /// Loads 4 consecutive floats.
  static Float4 load(const float* p) { return {_mm_loadu_ps(p)}; }
  /// All lanes equal to `x`.
  static Float4 broadcast(float x) { return {_mm_set1_ps(x)}; }
  /// Stores the lanes to `p[0..3]`.
  void store(float* p) const { _mm_storeu_ps(p, v); }
};

inline Float4 operator-(Float4 a, Float4 b) { return {_mm_sub_ps(a.v, b.v)}; }
inline Float4 operator*(Float4 a, Float4 b) { return {_mm_mul_ps(a.v, b.v)}; }
inline Float4 operator+(Float4 a, Float4 b) { return {_mm_add_ps(a.v, b.v)}; }
inline Float4 operator/(Float4 a, Float4 b) { return {_mm_div_ps(a.v, b.v)}; }
/// Lane-wise correctly rounded square root: SQRTPS.
inline Float4 sqrt(Float4 a) { return {_mm_sqrt_ps(a.v)}; }
/// Lane-wise the magnitude of `magnitude` with the sign bit of `sign` (std::copysign).
inline Float4 copysign(Float4 magnitude, Float4 sign) {
  const __m128 sign_bit = _mm_set1_ps(-0.f);
  return {_mm_or_ps(_mm_andnot_ps(sign_bit, magnitude.v), _mm_and_ps(sign_bit, sign.v))};
}
/// Lane-wise a < b ? a : b (so b when either is NaN): MINPS.
inline Float4 min(Float4 a, Float4 b) { return {_mm_min_ps(a.v, b.v)}; }
/// Lane-wise a > b ? a : b (so b when either is NaN): MAXPS.
inline Float4 max(Float4 a, Float4 b) { return {_mm_max_ps(a.v, b.v)}; }
/// Bit i set where a[i] <= b[i] (clear where either is NaN).
inline int less_equal_mask(Float4 a, Float4 b) { return _mm_movemask_ps(_mm_cmple_ps(a.v, b.v)); }
/// Bit i set where a[i] < b[i] (clear where either is NaN).
inline int less_mask(Float4 a, Float4 b) { return _mm_movemask_ps(_mm_cmplt_ps(a.v, b.v)); }
/// Bit i set where a[i] == b[i] (clear where either is NaN).
inline int equal_mask(Float4 a, Float4 b) { return _mm_movemask_ps(_mm_cmpeq_ps(a.v, b.v)); }

}  // namespace sse
using Float4 = sse::Float4;
#else
using Float4 = scalar::Float4;
#endif

RAYLAB_ISA_END
}  // namespace raylab::simd
