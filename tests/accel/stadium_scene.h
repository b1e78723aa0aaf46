#pragma once
// "The teapot in a stadium" (Haines): a small dense mesh inside a huge, sparse scene. A uniform
// grid sized for the whole scene puts the teapot in a cell or two, and every ray that reaches it
// tests most of its triangles; an octree subdivides around the teapot only. For tests and
// benchmarks (the bar: the octree beats the grid here).
//
// Units: z is up. The ground is a 2000 x 2000 quad at z = 0; eight spheres of radius 60 stand
// on it around a circle of radius 800; SPD teapot's triangles (its checkerboard left out), scaled
// by 1/4 to about 1.7 units across, about 1/1000 of the scene, sit on the ground at the centre.

#include <cmath>
#include <string>

#include "raylab/geometry/geometry.h"
#include "raylab/scene/camera_spec.h"
#include "raylab/scene/spd.h"

namespace raylab::test_scenes {

/// The scene with SPD teapot's triangles at size factor `teapot_size` (64 n^2 - 8 n triangles:
/// 2256 at the default 6, 25,440 at 20). Ids: the teapot's triangles, then the spheres, then
/// the ground quad.
inline Geometry teapot_in_stadium(int teapot_size = 6) {
  const Scene teapot = make_spd_scene("spd:teapot?size=" + std::to_string(teapot_size));
  const Geometry& source = teapot.geometry;
  constexpr float kScale = 0.25f;
  Geometry g;
  for (const Triangle& t : source.triangles) {
    if (t.p0.z == 0.f && t.p1.z == 0.f && t.p2.z == 0.f) continue;  // a checker square
    g.add(Triangle{t.p0 * kScale, t.p1 * kScale, t.p2 * kScale}, 0);
  }
  constexpr float kPi = 3.14159265f;
  for (int i = 0; i < 8; ++i) {
    const float a = 2.f * kPi * static_cast<float>(i) / 8.f;
    g.add(Sphere{{800.f * std::cos(a), 800.f * std::sin(a), 60.f}, 60.f}, 1);
  }
  g.add(Quad{{-1000.f, -1000.f, 0.f}, {2000.f, 0.f, 0.f}, {0.f, 2000.f, 0.f}}, 2);
  return g;
}

/// A camera that looks at the teapot from a few of its sizes away, with the ground and some of
/// the far spheres behind it (SPD teapot's own view direction).
inline CameraSpec teapot_in_stadium_camera() {
  CameraSpec camera;
  camera.from = Vec3{4.86f, 7.2f, 5.4f} * 0.25f * 1.5f;
  camera.at = {0.f, 0.f, 0.2f};
  camera.up = {0.f, 0.f, 1.f};
  camera.vfov_degrees = 40.f;
  return camera;
}

}  // namespace raylab::test_scenes
