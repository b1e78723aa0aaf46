#pragma once
// Shared by the SIMD type tests: float bits, the documented lane rules written out in scalar
// code, and the values where implementations tend to differ.

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "raylab/core/rng.h"

namespace raylab::test {

/// The bits of `x`.
inline std::uint32_t bits(float x) { return std::bit_cast<std::uint32_t>(x); }
/// The float with bits `b`.
inline float from_bits(std::uint32_t b) { return std::bit_cast<float>(b); }

/// Bit for bit, except that of two NaN results only NaN-ness is compared: which NaN an arithmetic
/// operation on two NaNs returns is not specified by C++ (the compiler may commute a * b).
inline bool same_arith(float a, float b) { return std::isnan(a) ? std::isnan(b) : bits(a) == bits(b); }

/// The documented min rule for one lane: the SECOND operand when either is NaN.
inline float rule_min(float a, float b) { return std::isnan(a) || std::isnan(b) ? b : (a < b ? a : b); }
/// The documented max rule for one lane: the SECOND operand when either is NaN.
inline float rule_max(float a, float b) { return std::isnan(a) || std::isnan(b) ? b : (a > b ? a : b); }

/// Values where implementations tend to differ: signed zeros and infinities, NaNs with and
/// without payloads (quiet and signaling), denormals, the extremes, and a few ordinary numbers.
inline const std::vector<float>& special_values() {
  static const std::vector<float> v = {
      0.f,
      -0.f,
      std::numeric_limits<float>::infinity(),
      -std::numeric_limits<float>::infinity(),
      std::numeric_limits<float>::quiet_NaN(),
      -std::numeric_limits<float>::quiet_NaN(),
      from_bits(0x7fc12345u),  // quiet NaN with a payload
      from_bits(0xffd00001u),  // negative quiet NaN with a payload
      from_bits(0x7f800001u),  // signaling NaN
      std::numeric_limits<float>::denorm_min(),
      -std::numeric_limits<float>::denorm_min(),
      from_bits(0x007fffffu),  // largest denormal
      from_bits(0x80400000u),  // a negative denormal
      std::numeric_limits<float>::min(),
      std::numeric_limits<float>::max(),
      -std::numeric_limits<float>::max(),
      1.f,
      -1.f,
      0.5f,
      3.f,
      1e-30f,
      -1e30f,
  };
  return v;
}

/// A lane value: a special value, an arbitrary bit pattern (NaNs, denormals, huge numbers), or an
/// ordinary number, a third of the time each.
inline float random_value(Pcg32& rng) {
  const std::uint32_t kind = rng.next_u32() % 3;
  if (kind == 0) return special_values()[rng.next_u32() % special_values().size()];
  if (kind == 1) return from_bits(rng.next_u32());
  return (rng.next_float() - 0.5f) * 200.f;
}

}  // namespace raylab::test
