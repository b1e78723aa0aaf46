#pragma once
/// \file
/// Float helpers shared by the samplers: turning hashed bits into [0, 1) and keeping a float
/// inside the interval it was computed for, so that stratification survives float rounding.

#include <cmath>
#include <cstdint>

namespace raylab {

/// The largest float below 1: every sample coordinate is at most this.
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

/// The top 24 bits of `bits` as a float in [0, 1) (exact: 24 bits fit the mantissa).
constexpr float bits_to_unit_float(std::uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

/// `f` moved by the fewest float steps into the interval [k / n, (k + 1) / n) (0 <= k < n). A
/// value like (k + u) / n computed in float can round onto the next interval's edge (even onto
/// 1.0 for the last one); this puts it back without touching values that are already inside.
/// The comparisons f * n against k are exact in double for n < 2^29.
inline float clamp_to_interval(float f, int k, int n) {
  const double dn = static_cast<double>(n);
  while (f > 0.f && static_cast<double>(f) * dn >= static_cast<double>(k) + 1.0) f = std::nextafter(f, 0.f);
  while (static_cast<double>(f) * dn < static_cast<double>(k) && f < kOneMinusEpsilon) f = std::nextafter(f, 1.f);
  return f < kOneMinusEpsilon ? f : kOneMinusEpsilon;
}

/// The float nearest to (k + u) / n, kept inside [k / n, (k + 1) / n): u in [0, 1) is the
/// position within interval k of n.
inline float point_in_interval(int k, float u, int n) {
  const double exact = (static_cast<double>(k) + static_cast<double>(u)) / static_cast<double>(n);
  return clamp_to_interval(static_cast<float>(exact), k, n);
}

}  // namespace raylab
