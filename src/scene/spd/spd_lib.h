#pragma once
// Internal, header-only: what the seven SPD generators need of the SPD support library
// support library (Haines' lib*.c): double-precision vectors and rotations, the camera, the
// background, and the mapping from SPD's surface description to an NFF fill. The SPD programs
// compute in double and round only when printing, so these helpers do the same and round to
// float once, when an entity reaches the NffSceneBuilder.

#include <cmath>
#include <numbers>

#include "raylab/scene/nff_builder.h"

namespace raylab::spd::lib {

inline constexpr double kPi = std::numbers::pi;

/// A point or direction in double precision.
struct DVec {
  double x = 0.0, y = 0.0, z = 0.0;
};

inline DVec operator+(DVec a, DVec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline DVec operator-(DVec a, DVec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline DVec operator*(DVec a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline DVec operator/(DVec a, double s) { return {a.x / s, a.y / s, a.z / s}; }
inline double dot(DVec a, DVec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline DVec cross(DVec a, DVec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
/// `v` scaled to unit length; a zero vector stays zero.
inline DVec normalized(DVec v) {
  const double length = std::sqrt(dot(v, v));
  return length > 0.0 ? v / length : v;
}
/// The single rounding from the generators' double precision to the scene's float.
inline Vec3 to_float(DVec v) { return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)}; }

/// A rotation by a right-handed angle about a unit axis, kept as a 3x3 matrix so that the many
/// points rotated by one rotation pay for its sines and cosines once.
class Rotation {
 public:
  /// The identity.
  Rotation() = default;
  /// Rotation by `angle` radians about the unit vector `axis` (Rodrigues:
  /// R = cos(a) I + sin(a) [axis]x + (1 - cos(a)) axis axis^T).
  Rotation(DVec axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
    const double k[3] = {axis.x, axis.y, axis.z};
    const double skew[3][3] = {{0.0, -axis.z, axis.y}, {axis.z, 0.0, -axis.x}, {-axis.y, axis.x, 0.0}};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] = (i == j ? c : 0.0) + s * skew[i][j] + t * k[i] * k[j];
    }
  }
  /// Rotation by `angle` radians about +z.
  static Rotation about_z(double angle) { return Rotation(DVec{0.0, 0.0, 1.0}, angle); }

  DVec operator()(DVec v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }

 private:
  double m[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
};

/// The Phong exponent of a highlight that falls to half its peak `half_angle_degrees` away from
/// the mirror direction: cos(angle)^n = 1/2. SPD describes highlights by that angle; an angle of
/// zero means no visible highlight (an exponent so large the highlight vanishes) and a right
/// angle or more a flat one.
inline double phong_exponent(double half_angle_degrees) {
  const double angle = kPi * half_angle_degrees / 180.0;
  if (angle <= 0.0) return 100000.0;
  if (angle >= kPi / 2.0) return 1.0;
  return std::log(0.5) / std::log(std::cos(angle));
}

/// An NFF fill from SPD's surface description: colour, diffuse weight, specular (mirror) weight,
/// highlight half angle in degrees, transmitted weight and index of refraction. SPD's ambient and
/// highlight-strength terms do not reach NFF, so they are not parameters.
inline NffFill surface(Color color, double kd, double ks, double highlight_degrees, double kt, double ior) {
  NffFill f;
  f.color = color;
  f.kd = static_cast<float>(kd);
  f.ks = static_cast<float>(ks);
  f.shine = static_cast<float>(phong_exponent(highlight_degrees));
  f.transmittance = static_cast<float>(kt);
  f.ior = static_cast<float>(ior);
  return f;
}

/// "UNC sky blue", the background of every SPD scene.
inline constexpr Color kSkyBlue{0.078f, 0.361f, 0.753f};

/// The SPD camera: a 45 degree field of view and a 512 x 512 image, only the eye, target, up
/// vector and hither distance vary.
inline NffView view(DVec from, DVec at, DVec up, double hither) {
  NffView v;
  v.from = to_float(from);
  v.at = to_float(at);
  v.up = to_float(up);
  v.angle = 45.0;
  v.hither = hither;
  v.xres = 512;
  v.yres = 512;
  return v;
}

}  // namespace raylab::spd::lib
