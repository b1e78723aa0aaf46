// SPD 'balls', the sphereflake (Haines, SPD 3.14 balls.c): a mirrored sphere sprouting nine
// touching spheres of a third its radius, each of which sprouts nine more, `size` levels deep,
// above a square beige floor, lit by three lights.
//
// Why it is built this way: the children of a sphere sit where they touch it (centre distance
// r + r/3) in nine fixed directions about the sphere's own "up" axis, the direction from its
// parent. Six of them ring its equator 60 degrees apart and three sit 35.26 degrees off its
// pole, between them, so the flake keeps growing outward and never back into its parent.
// Spheres come out depth first, parent before children, as SPD writes them.
//
// Spheres: sum over k = 0..size of 9^k = (9^(size+1) - 1) / 8, plus one floor polygon.

#include <array>

#include "spd_generators.h"
#include "spd_lib.h"

namespace raylab::spd {
namespace {

using lib::DVec;
using lib::Rotation;

constexpr double kChildRadiusRatio = 1.0 / 3.0;

// The nine child directions of a sphere whose up axis is +z. Three face diagonals of a cube
// that meet at one corner (60 degrees apart) are tilted about the horizontal axis (1,-1,0) by
// asin(2/sqrt(6)), which lays two of them on the equator and lifts the third 35.26 degrees off
// the pole; copies turned by 120 and 240 degrees about +z complete the set.
std::array<DVec, 9> child_directions() {
  const double d = 1.0 / std::sqrt(2.0);
  std::array<DVec, 3> trio{DVec{d, d, 0.0}, DVec{d, 0.0, -d}, DVec{0.0, d, -d}};
  const Rotation tilt(lib::normalized(DVec{1.0, -1.0, 0.0}), std::asin(2.0 / std::sqrt(6.0)));
  for (DVec& v : trio) v = tilt(v);
  std::array<DVec, 9> directions;
  for (int copy = 0; copy < 3; ++copy) {
    const Rotation turn = Rotation::about_z(copy * 2.0 * lib::kPi / 3.0);
    for (int i = 0; i < 3; ++i) directions[copy * 3 + i] = turn(trio[i]);
  }
  return directions;
}

// The rotation taking +z to the unit vector `up`. Directions within 0.9999 of +z or -z count as
// those axes exactly, as in SPD (the cross product would be too short to normalize reliably).
Rotation rotation_to(DVec up) {
  if (up.z >= 0.9999) return Rotation();
  if (up.z <= -0.9999) return Rotation(DVec{0.0, 1.0, 0.0}, lib::kPi);
  return Rotation(lib::normalized(lib::cross(DVec{0.0, 0.0, 1.0}, up)), std::acos(up.z));
}

// Emits the sphere at `center` and then, `depth` levels down, its descendants.
void bloom(int depth, DVec center, double radius, DVec up, const std::array<DVec, 9>& directions,
           NffSceneBuilder& out) {
  out.sphere(lib::to_float(center), static_cast<float>(radius));
  if (depth == 0) return;
  const Rotation orient = rotation_to(up);
  const double reach = radius * (1.0 + kChildRadiusRatio);  // parent and child touch
  for (const DVec& direction : directions) {
    const DVec child = orient(direction) * reach + center;
    bloom(depth - 1, child, radius * kChildRadiusRatio, (child - center) / reach, directions, out);
  }
}

void generate(int size, NffSceneBuilder& out) {
  out.background(lib::kSkyBlue);
  out.view(lib::view({2.1, 1.3, 1.7}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 0.01));
  out.light({4.f, 3.f, 2.f});
  out.light({1.f, -4.f, 4.f});
  out.light({-3.f, 1.f, 5.f});

  // The flake fits in a sphere of radius 1 about the origin; the floor lies half that below.
  const double radius = 1.0;
  out.fill(lib::surface({1.f, 0.75f, 0.33f}, 0.8, 0.0, 0.0, 0.0, 1.0));
  const float half = static_cast<float>(12.0 * radius), floor_z = static_cast<float>(-radius / 2.0);
  const std::array<Vec3, 4> floor{Vec3{half, half, floor_z}, Vec3{-half, half, floor_z}, Vec3{-half, -half, floor_z},
                                  Vec3{half, -half, floor_z}};
  out.polygon(floor);

  out.fill(lib::surface({1.f, 0.9f, 0.7f}, 0.5, 0.5, 37.0, 0.0, 1.0));
  bloom(size, {0.0, 0.0, 0.0}, radius / 2.0, {0.0, 0.0, 1.0}, child_directions(), out);
}

}  // namespace

SpdGenerator balls() {
  return {"balls", "sphereflake: spheres sprouting 9 spheres of 1/3 their radius, over a floor (size = depth)", 4, 7,
          &generate};
}

}  // namespace raylab::spd
