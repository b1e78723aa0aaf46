#pragma once
/// \file
/// Three-component float vector used for points, directions and linear RGB colours.

#include <algorithm>
#include <cmath>

namespace raylab {

/// A 2-vector of float: texture coordinates.
struct Vec2 {
  float x = 0.f, y = 0.f;
};

/// A 3-vector of float (12 bytes). Plain data: no invariants, public members.
struct Vec3 {
  float x = 0.f, y = 0.f, z = 0.f;

  constexpr Vec3() = default;
  constexpr Vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
  /// All three components equal to `s`.
  constexpr explicit Vec3(float s) : x(s), y(s), z(s) {}

  /// Component `i` (0, 1, 2); no range check. A direct indexed load (x, y, z are contiguous in
  /// this standard-layout struct): the triangle test indexes with per-ray axis numbers, where a
  /// chain of selects would cost more than the arithmetic.
  float operator[](int i) const { return (&x)[i]; }
  /// Mutable component `i` (0, 1, 2); no range check.
  float& operator[](int i) { return (&x)[i]; }

  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3& operator+=(Vec3 b) {
    x += b.x;
    y += b.y;
    z += b.z;
    return *this;
  }
  constexpr Vec3& operator-=(Vec3 b) {
    x -= b.x;
    y -= b.y;
    z -= b.z;
    return *this;
  }
  constexpr Vec3& operator*=(float s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr Vec3& operator*=(Vec3 b) {
    x *= b.x;
    y *= b.y;
    z *= b.z;
    return *this;
  }
  constexpr Vec3& operator/=(float s) { return *this *= (1.f / s); }
};

/// Linear RGB radiance or reflectance; same layout as Vec3.
using Color = Vec3;

constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
/// Component-wise product (used for colours).
constexpr Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
constexpr Vec3 operator*(Vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
constexpr Vec3 operator*(float s, Vec3 a) { return a * s; }
constexpr Vec3 operator/(Vec3 a, float s) { return a * (1.f / s); }
/// Component-wise quotient.
constexpr Vec3 operator/(Vec3 a, Vec3 b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }
constexpr bool operator==(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/// Dot product.
constexpr float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// Cross product (right-handed).
constexpr Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
/// Euclidean length.
inline float length(Vec3 a) { return std::sqrt(dot(a, a)); }
/// Squared length.
constexpr float length_squared(Vec3 a) { return dot(a, a); }
/// `a` scaled to unit length; the zero vector stays zero-length NaN-free only if caller checks.
inline Vec3 normalize(Vec3 a) { return a * (1.f / length(a)); }
/// Component-wise minimum.
constexpr Vec3 min(Vec3 a, Vec3 b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
/// Component-wise maximum.
constexpr Vec3 max(Vec3 a, Vec3 b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
/// Component-wise absolute value.
inline Vec3 abs(Vec3 a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }
/// Largest component.
constexpr float max_component(Vec3 a) { return std::max(a.x, std::max(a.y, a.z)); }
/// Index (0..2) of the largest component.
constexpr int max_axis(Vec3 a) { return a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2); }
/// True when every component is finite (no NaN, no infinity).
inline bool is_finite(Vec3 a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
/// Linear interpolation: a at t=0, b at t=1.
constexpr Vec3 lerp(Vec3 a, Vec3 b, float t) { return a * (1.f - t) + b * t; }
/// Mirror reflection of incident direction `d` about unit normal `n`.
constexpr Vec3 reflect(Vec3 d, Vec3 n) { return d - n * (2.f * dot(d, n)); }
/// Rec. 709 luminance of a linear colour.
constexpr float luminance(Color c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/// Builds two unit vectors that with unit `n` form a right-handed orthonormal basis
/// (Duff et al. 2017, branch-free and continuous except at one point).
inline void orthonormal_basis(Vec3 n, Vec3& t, Vec3& b) {
  const float sign = std::copysign(1.f, n.z);
  const float a = -1.f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = {1.f + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

}  // namespace raylab
