#pragma once
/// \file
/// The floats next to a float, as std::nextafter gives them toward +inf or -inf, but inline: a
/// float's neighbour is one unit of its bit pattern away, and libm's nextafterf is a call that
/// hot paths (the tie rule, called per primitive test) should not make.

#include <bit>
#include <cstdint>
#include <limits>

namespace raylab {

/// The smallest float above `x` (std::nextafter(x, +inf)): +inf stays +inf, NaN stays NaN, both
/// zeros give the smallest denormal.
inline float next_float_up(float x) {
  if (!(x < std::numeric_limits<float>::infinity())) return x;  // +inf or NaN
  if (x == 0.f) return std::numeric_limits<float>::denorm_min();
  const auto bits = std::bit_cast<std::uint32_t>(x);
  return std::bit_cast<float>(x > 0.f ? bits + 1 : bits - 1);
}

/// The largest float below `x` (std::nextafter(x, -inf)): -inf stays -inf, NaN stays NaN, both
/// zeros give the negative smallest denormal.
inline float next_float_down(float x) {
  if (!(x > -std::numeric_limits<float>::infinity())) return x;  // -inf or NaN
  if (x == 0.f) return -std::numeric_limits<float>::denorm_min();
  const auto bits = std::bit_cast<std::uint32_t>(x);
  return std::bit_cast<float>(x > 0.f ? bits - 1 : bits + 1);
}

}  // namespace raylab
