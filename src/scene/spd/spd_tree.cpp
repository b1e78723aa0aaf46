// SPD 'tree' (Eric Haines, SPD 3.14): a binary tree grown by Aono and Kunii's method (IEEE CG&A,
// May 1984) from cones with a sphere at each joint, standing on a green square field, lit by
// seven lights.
//
// Every branch is the unit segment from (0,0,0) to (0,0,1) carried into place by the product of
// its ancestors' branching transforms; each branching transform rotates by a branching angle
// about x, turns by a divergence angle about z, shrinks by a contraction ratio and moves to the
// parent's tip. The two children of a branch use different angles and ratios, which is what makes
// the tree asymmetric. A size factor n gives 2^(n+1) - 1 branches, each one cone and one sphere.

#include <array>
#include <cmath>
#include <numbers>

#include "spd_generators.h"
#include "spd_lib.h"

namespace raylab::spd {
namespace {

constexpr double kPi = std::numbers::pi;

constexpr double kBranchAngle[2] = {40.0, 25.0};  // degrees, from the parent's axis
constexpr double kDivergence[2] = {90.0, 230.0};  // degrees about the parent's axis
constexpr double kContraction[2] = {0.65, 0.70};  // child length / parent length
constexpr double kRadiusRatio = 0.67;             // tip radius / base radius, and child / parent
constexpr double kWidthHeightRatio = 0.15;        // trunk base radius / trunk length

/// An affine map of row vectors, p' = p * M, as the SPD library composes its transforms: the
/// last row is the translation.
struct Affine {
  std::array<std::array<double, 4>, 4> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
};

/// a * b: apply a first, then b.
Affine operator*(const Affine& a, const Affine& b) {
  Affine r;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j] + a.m[i][3] * b.m[3][j];
    }
  }
  return r;
}

Affine rotation(int axis, double radians) {
  Affine r;
  const double c = std::cos(radians), s = std::sin(radians);
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  r.m[a][a] = c;
  r.m[b][b] = c;
  r.m[a][b] = s;
  r.m[b][a] = -s;
  return r;
}

/// The point (0, 0, z) carried by `t`.
Vec3 on_axis(const Affine& t, double z) {
  return {static_cast<float>(z * t.m[2][0] + t.m[3][0]), static_cast<float>(z * t.m[2][1] + t.m[3][1]),
          static_cast<float>(z * t.m[2][2] + t.m[3][2])};
}

/// The transform from a parent branch's frame to child `i`'s frame.
Affine branching(int i) {
  Affine shrink_and_lift;
  for (int k = 0; k < 3; ++k) shrink_and_lift.m[k][k] = kContraction[i];
  shrink_and_lift.m[3][2] = 1.0;
  return rotation(0, kBranchAngle[i] * kPi / 180.0) * rotation(2, kDivergence[i] * kPi / 180.0) * shrink_and_lift;
}

/// Depth first, child 0 before child 1, as the original recursion: a branch's cone, the sphere
/// at its tip, then its subtrees. `scale` is the branch's width relative to the trunk's.
void grow(const std::array<Affine, 2>& children, const Affine& frame, double scale, int depth, NffSceneBuilder& out) {
  const double base_radius = scale * kWidthHeightRatio;
  const double tip_radius = base_radius * kRadiusRatio;
  const Vec3 base = on_axis(frame, 0.0);
  const Vec3 tip = on_axis(frame, 1.0);
  out.cone(base, static_cast<float>(base_radius), tip, static_cast<float>(tip_radius));
  out.sphere(tip, static_cast<float>(tip_radius));
  if (depth == 0) return;
  for (const Affine& child : children) grow(children, child * frame, scale * kRadiusRatio, depth - 1, out);
}

void generate(int size, NffSceneBuilder& out) {
  out.background(lib::kSkyBlue);
  out.view(lib::view({4.5, 0.4, 2.0}, {0.0, 0.0, 1.5}, {0.0, 0.0, 1.0}, 1.0));
  for (const Vec3 l : {Vec3{-5, 5, 50}, Vec3{30, -30, 30}, Vec3{-40, -30, 20}, Vec3{10, 30, 40}, Vec3{-30, 40, 10},
                       Vec3{50, 25, 20}, Vec3{-10, -60, 30}}) {
    out.light(l);
  }

  // Matte surfaces: the original asks for no highlight, which its library writes as exponent 1e5.
  out.fill(lib::surface({0.2f, 0.7f, 0.2f}, 1.0, 0.0, 0.0, 0.0, 0.0));
  const std::array<Vec3, 4> field{Vec3{50, 50, 0}, Vec3{-50, 50, 0}, Vec3{-50, -50, 0}, Vec3{50, -50, 0}};
  out.polygon(field);

  out.fill(lib::surface({0.55f, 0.4f, 0.2f}, 1.0, 0.0, 0.0, 0.0, 0.0));
  grow({branching(0), branching(1)}, Affine{}, 1.0, size, out);
}

}  // namespace

SpdGenerator tree() {
  // Size 22 gives 8.4M cones and 8.4M spheres; each step doubles it.
  return {"tree", "binary tree of cones and spheres on a field, Aono and Kunii's method (SPD tree)", 11, 22, generate};
}

}  // namespace raylab::spd
