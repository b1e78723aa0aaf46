#pragma once
/// \file
/// Four doubles as one value, for kernels that need exact products of floats (a product of two
/// floats fits exactly in a double): `scalar::Double4` (always built and tested) and, where AVX
/// is enabled, `avx::Double4` (one __m256d), else with SSE2 `sse::Double4` (two __m128d).
/// Conversions round to nearest as a scalar cast does, so a kernel gives bit for bit the same
/// results as its scalar version.

#include "raylab/simd/float4.h"
#include "raylab/simd/isa_namespace.h"

#if defined(__AVX__) && !defined(RAYLAB_SIMD_SCALAR)
#include <immintrin.h>
#define RAYLAB_HAVE_AVX 1
#endif

namespace raylab::simd {
RAYLAB_ISA_BEGIN

namespace scalar {

/// Four doubles in an array.
struct Double4 {
  double v[4];

  /// Each lane of `f` widened exactly.
  static Double4 from(const Float4& f) { return {{f.v[0], f.v[1], f.v[2], f.v[3]}}; }
  /// Each lane rounded to the nearest float.
  Float4 to_float() const {
    return {{static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]), static_cast<float>(v[3])}};
  }
};

inline Double4 operator-(const Double4& a, const Double4& b) {
  return {{a.v[0] - b.v[0], a.v[1] - b.v[1], a.v[2] - b.v[2], a.v[3] - b.v[3]}};
}
inline Double4 operator*(const Double4& a, const Double4& b) {
  return {{a.v[0] * b.v[0], a.v[1] * b.v[1], a.v[2] * b.v[2], a.v[3] * b.v[3]}};
}

}  // namespace scalar

#if defined(RAYLAB_HAVE_AVX) && defined(RAYLAB_HAVE_SSE)
namespace avx {

/// Four doubles in one AVX register.
struct Double4 {
  __m256d v;

  /// Each lane of `f` widened exactly (VCVTPS2PD).
  static Double4 from(sse::Float4 f) { return {_mm256_cvtps_pd(f.v)}; }
  /// Each lane rounded to the nearest float (VCVTPD2PS, in the default rounding mode).
  sse::Float4 to_float() const { return {_mm256_cvtpd_ps(v)}; }
};

inline Double4 operator-(Double4 a, Double4 b) { return {_mm256_sub_pd(a.v, b.v)}; }
inline Double4 operator*(Double4 a, Double4 b) { return {_mm256_mul_pd(a.v, b.v)}; }

}  // namespace avx
using Double4 = avx::Double4;
#elif defined(RAYLAB_HAVE_SSE)
namespace sse {

/// Four doubles in two SSE2 registers, for builds with SSE but no AVX (-march=x86-64, or a
/// program using the installed headers without -mavx), where Float4 is sse::Float4.
struct Double4 {
  __m128d lo, hi;  ///< lanes 0-1 and 2-3

  /// Each lane of `f` widened exactly (CVTPS2PD of each half).
  static Double4 from(Float4 f) { return {_mm_cvtps_pd(f.v), _mm_cvtps_pd(_mm_movehl_ps(f.v, f.v))}; }
  /// Each lane rounded to the nearest float (CVTPD2PS, in the default rounding mode).
  Float4 to_float() const { return {_mm_movelh_ps(_mm_cvtpd_ps(lo), _mm_cvtpd_ps(hi))}; }
};

inline Double4 operator-(Double4 a, Double4 b) { return {_mm_sub_pd(a.lo, b.lo), _mm_sub_pd(a.hi, b.hi)}; }
inline Double4 operator*(Double4 a, Double4 b) { return {_mm_mul_pd(a.lo, b.lo), _mm_mul_pd(a.hi, b.hi)}; }

}  // namespace sse
using Double4 = sse::Double4;
#else
using Double4 = scalar::Double4;
#endif

RAYLAB_ISA_END
}  // namespace raylab::simd
