#pragma once
/// \file
/// Affine transforms of points, directions and normals (scene-file placements, glTF nodes).

#include <array>

#include "raylab/core/vec3.h"

namespace raylab {

/// An affine map p -> M p + t, stored as a row-major 3x4 matrix in double (composition of long
/// node chains keeps its precision; the result is applied to floats).
struct Transform {
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

  /// The identity.
  static Transform identity() { return {}; }
  /// Translation by `t`.
  static Transform translate(double x, double y, double z);
  /// Non-uniform scale.
  static Transform scale(double x, double y, double z);
  /// Rotation by `degrees` about `axis` (any length > 0), right-handed.
  static Transform rotate(double degrees, Vec3 axis);
  /// From a row-major 4x4 matrix whose last row is 0 0 0 1 (callers check that row).
  static Transform from_rows(const std::array<double, 12>& rows);
  /// From a column-major 4x4 matrix (glTF's `matrix`); the last row is ignored.
  static Transform from_column_major(const double* m16);

  /// This transform after `inner`: (a * b)(p) = a(b(p)).
  friend Transform operator*(const Transform& a, const Transform& b);

  /// The image of point `p`.
  Vec3 point(Vec3 p) const;
  /// The image of direction `d` (no translation).
  Vec3 vector(Vec3 d) const;
  /// The image of normal `n` (inverse transpose, not normalised). Requires an invertible map.
  Vec3 normal(Vec3 n) const;
  /// The inverse map. Requires an invertible map (see valid()).
  Transform inverse() const;
  /// Determinant of the linear part (negative: the map mirrors, and windings flip).
  double determinant() const;
  /// True when every entry is finite and the linear part is invertible.
  bool valid() const;
};

}  // namespace raylab
