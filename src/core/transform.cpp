#include "raylab/core/transform.h"

#include <cmath>
#include <numbers>

namespace raylab {

Transform Transform::translate(double x, double y, double z) { return {{{{1, 0, 0, x}, {0, 1, 0, y}, {0, 0, 1, z}}}}; }

Transform Transform::scale(double x, double y, double z) { return {{{{x, 0, 0, 0}, {0, y, 0, 0}, {0, 0, z, 0}}}}; }

Transform Transform::rotate(double degrees, Vec3 axis) {
  const double len = std::sqrt(double(axis.x) * axis.x + double(axis.y) * axis.y + double(axis.z) * axis.z);
  Transform t;
  if (!(len > 0.0)) return t;
  const double x = axis.x / len, y = axis.y / len, z = axis.z / len;
  const double a = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(a), s = std::sin(a), k = 1.0 - c;
  // Rodrigues' rotation formula as a matrix.
  t.m[0] = {c + x * x * k, x * y * k - z * s, x * z * k + y * s, 0.0};
  t.m[1] = {y * x * k + z * s, c + y * y * k, y * z * k - x * s, 0.0};
  t.m[2] = {z * x * k - y * s, z * y * k + x * s, c + z * z * k, 0.0};
  return t;
}

Transform Transform::from_rows(const std::array<double, 12>& rows) {
  Transform t;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) t.m[r][c] = rows[4 * r + c];
  return t;
}

Transform Transform::from_column_major(const double* m16) {
  Transform t;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) t.m[r][c] = m16[4 * c + r];
  return t;
}

Transform operator*(const Transform& a, const Transform& b) {
  Transform out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      double v = c == 3 ? a.m[r][3] : 0.0;
      for (int k = 0; k < 3; ++k) v += a.m[r][k] * b.m[k][c];
      out.m[r][c] = v;
    }
  }
  return out;
}

Vec3 Transform::point(Vec3 p) const {
  Vec3 out;
  for (int r = 0; r < 3; ++r) out[r] = static_cast<float>(m[r][0] * p.x + m[r][1] * p.y + m[r][2] * p.z + m[r][3]);
  return out;
}

Vec3 Transform::vector(Vec3 d) const {
  Vec3 out;
  for (int r = 0; r < 3; ++r) out[r] = static_cast<float>(m[r][0] * d.x + m[r][1] * d.y + m[r][2] * d.z);
  return out;
}

Vec3 Transform::normal(Vec3 n) const {
  // The inverse transpose is the cofactor matrix divided by the determinant; the scale does not
  // matter for a normal, only the sign, which keeps the normal on the outside after a mirror.
  const auto& a = m;
  const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  const double c10 = a[0][2] * a[2][1] - a[0][1] * a[2][2];
  const double c11 = a[0][0] * a[2][2] - a[0][2] * a[2][0];
  const double c12 = a[0][1] * a[2][0] - a[0][0] * a[2][1];
  const double c20 = a[0][1] * a[1][2] - a[0][2] * a[1][1];
  const double c21 = a[0][2] * a[1][0] - a[0][0] * a[1][2];
  const double c22 = a[0][0] * a[1][1] - a[0][1] * a[1][0];
  const double sign = determinant() < 0.0 ? -1.0 : 1.0;
  return Vec3{static_cast<float>(sign * (c00 * n.x + c01 * n.y + c02 * n.z)),
              static_cast<float>(sign * (c10 * n.x + c11 * n.y + c12 * n.z)),
              static_cast<float>(sign * (c20 * n.x + c21 * n.y + c22 * n.z))};
}

Transform Transform::inverse() const {
  const auto& a = m;
  // Cofactors C[i][j]; the inverse of the linear part is C transposed over the determinant.
  double c[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      c[i][j] = a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1];
    }
  const double inv_det = 1.0 / determinant();
  Transform out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.m[i][j] = c[j][i] * inv_det;
  for (int i = 0; i < 3; ++i) {
    out.m[i][3] = -(out.m[i][0] * a[0][3] + out.m[i][1] * a[1][3] + out.m[i][2] * a[2][3]);
  }
  return out;
}

double Transform::determinant() const {
  const auto& a = m;
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

bool Transform::valid() const {
  for (const auto& row : m)
    for (const double v : row)
      if (!std::isfinite(v)) return false;
  const double d = determinant();
  return std::isfinite(d) && d != 0.0;
}

}  // namespace raylab
