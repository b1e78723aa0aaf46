// SPD 'rings' (Eric Haines, SPD 3.14): a pyramid of objects, each made of six pentagonal rings of
// cylinders with spheres rounding the joints, seen from the pyramid's apex, with a white wall
// behind for shadows. Three lights.
//
// An object's six rings all pass through its centre, one in each plane parallel to a pair of
// opposite faces of a dodecahedron (the original describes them as connecting the midpoints of a
// dodecahedron's edges), so that they interlock. Level d (0-based) of the pyramid is a
// (d+1) x (d+1) grid of objects, so a size factor n gives n(n+1)(2n+1)/6 objects of 30 cylinders
// and 30 spheres each, every ring with its own material.

#include <array>
#include <cmath>
#include <numbers>

#include "spd_generators.h"
#include "spd_lib.h"

namespace raylab::spd {
namespace {

constexpr double kPi = std::numbers::pi;

/// Double-precision point: the original computes in double and only its output is rounded.
struct P3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

P3 operator+(P3 a, P3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }

Vec3 to_vec3(P3 p) { return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)}; }

/// Radius of the cylinders and of the spheres that round off their joints.
constexpr double kRadius = 0.07412;

/// Rotation of p about the x axis (then z axis) by `angle` radians, counter-clockwise as seen from
/// the positive axis.
P3 rotate_x(P3 p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {p.x, p.y * c - p.z * s, p.y * s + p.z * c};
}
P3 rotate_z(P3 p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {p.x * c - p.y * s, p.x * s + p.y * c, p.z};
}

/// The 30 ring joints of one object, five per ring, scaled so that the object with its tube
/// radius fits in the unit sphere. The first ring lies in the z = 0 plane; the other five are
/// that ring tilted about x by the angle between the normals of adjacent dodecahedron faces
/// (2 acos(cos 60 / sin 36) = 63.4 degrees), then turned about z to odd tenths of a full turn,
/// where the dodecahedron's other faces are.
std::array<P3, 30> ring_joints() {
  std::array<P3, 30> joints;
  const double scale = 1.0 / (1.0 + kRadius);
  for (int v = 0; v < 5; ++v) {
    const double a = v * 2.0 * kPi / 5.0;
    joints[v] = {scale * std::cos(a), scale * std::sin(a), 0.0};
  }
  const double tilt = 2.0 * std::acos(std::cos(kPi / 3.0) / std::sin(kPi / 5.0));
  for (int ring = 1; ring < 6; ++ring) {
    const double turn = kPi * (2.0 * (ring - 1) + 1.0) / 5.0;
    for (int v = 0; v < 5; ++v) joints[5 * ring + v] = rotate_z(rotate_x(joints[v], tilt), turn);
  }
  return joints;
}

/// One object at `offset`: per ring, its colour, then for each joint the cylinder back to the
/// previous joint of the ring followed by the sphere at the joint.
void emit_object(const std::array<P3, 30>& joints, P3 offset, NffSceneBuilder& out) {
  static constexpr std::array<Color, 6> kRingColors{Color{1.f, 0.f, 0.f}, Color{0.f, 1.f, 0.f}, Color{0.f, 0.f, 1.f},
                                                    Color{0.f, 1.f, 1.f}, Color{1.f, 0.f, 1.f}, Color{1.f, 1.f, 0.f}};
  const auto r = static_cast<float>(kRadius);
  for (int ring = 0; ring < 6; ++ring) {
    out.fill(lib::surface(kRingColors[ring], 0.5, 0.2, 37.0, 0.0, 0.0));
    for (int v = 0; v < 5; ++v) {
      const Vec3 joint = to_vec3(joints[5 * ring + v] + offset);
      const Vec3 previous = to_vec3(joints[5 * ring + (v + 4) % 5] + offset);
      out.cone(joint, r, previous, r);
      out.sphere(joint, r);
    }
  }
}

void generate(int size, NffSceneBuilder& out) {
  // The original spaces the levels 1 / sin(22.5 degrees) apart in depth and the objects of a
  // level 2 apart across (its SPREAD_OUT factor is 1); the eye is one level-step before the apex.
  const double spread = 1.0 / std::sin(kPi / 8.0);
  const double y_step = spread;
  const double xz_step = 1.0;

  out.background(lib::kSkyBlue);
  const P3 from{-1.0, -spread, 0.5};
  out.view(lib::view({from.x, from.y, from.z}, {from.x, from.y + 1.0, from.z}, {0.0, 0.0, 1.0}, 1.0));
  out.light(to_vec3({3.0, -spread, 3.0}));
  out.light(to_vec3({-4.0, -spread, 1.0}));
  out.light(to_vec3({2.0, -spread, -4.0}));

  // The wall stands one level behind the last, 1% wider than the view there.
  out.fill(lib::surface({1.f, 1.f, 1.f}, 1.0, 0.0, 0.0, 0.0, 0.0));
  const double wall_y = y_step * (size + 1);
  const double half = 1.01 * (wall_y - from.y) * std::tan(kPi / 8.0);
  const std::array<Vec3, 4> wall{
      to_vec3({half + from.x, wall_y, half + from.z}), to_vec3({-half + from.x, wall_y, half + from.z}),
      to_vec3({-half + from.x, wall_y, -half + from.z}), to_vec3({half + from.x, wall_y, -half + from.z})};
  out.polygon(wall);

  const std::array<P3, 30> joints = ring_joints();
  for (int level = 0; level < size; ++level) {
    for (int iz = 0; iz <= level; ++iz) {
      for (int ix = 0; ix <= level; ++ix) {
        const P3 offset{xz_step * (2 * ix - level), y_step * (level + 1), xz_step * (2 * iz - level)};
        emit_object(joints, offset, out);
      }
    }
  }
}

}  // namespace

SpdGenerator rings() {
  // Size 100 gives 338,350 objects, 20.3M primitives and 2M materials: about as much as fits.
  return {"rings", "pyramid of dodecahedral rings of cylinders and spheres before a wall (SPD rings)", 7, 100,
          generate};
}

}  // namespace raylab::spd
