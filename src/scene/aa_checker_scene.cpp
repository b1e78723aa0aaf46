// aa-checker: the classic checkerboard to the horizon, unlit, for moire and convergence.

#include <cmath>
#include <numbers>

#include "aa_common.h"
#include "raylab/scene/aa_scenes.h"

namespace raylab {

Scene make_aa_checker_scene() {
  Scene scene = aa_detail::unlit_chart(kAaCheckerSky);

  // A disk rather than a huge quad: its texture coordinates are measured from its centre, right
  // under the eye, so the near cells (the ones wide enough to judge) keep full float precision.
  // With normal +y the disk's (u, v) is (x, -z).
  Material floor;
  floor.name = "checker";
  floor.color = {1.f, 1.f, 1.f};
  floor.kd = 1.f;
  floor.texture = {Texture::Kind::kChecker, {0.f, 0.f, 0.f}, kAaCheckerCell};
  const auto floor_obj = scene.add_object("checker floor", scene.add_material(floor));
  scene.geometry.add(Disk{{0.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, kAaCheckerFloorRadius}, floor_obj);

  // The horizon is kAaCheckerHorizonRow above the centre row: for a pitch theta below the
  // horizontal and a half-height tan(vfov / 2) of the image plane, tan(theta) = tan(vfov / 2) *
  // (240 - row) / 240. The yaw of 30 degrees keeps both edge families oblique.
  const double half_height = std::tan(double(kAaCheckerVfov) * std::numbers::pi / 360.0);
  const double rows_above = 0.5 * kAaHeight - double(kAaCheckerHorizonRow);
  const double tan_pitch = half_height * rows_above / (0.5 * kAaHeight);
  const double yaw = 30.0 * std::numbers::pi / 180.0;
  scene.camera.from = {0.f, kAaCheckerEyeHeight, 0.f};
  scene.camera.at = {static_cast<float>(std::sin(yaw)), static_cast<float>(kAaCheckerEyeHeight - tan_pitch),
                     static_cast<float>(-std::cos(yaw))};
  scene.camera.up = {0.f, 1.f, 0.f};
  scene.camera.vfov_degrees = kAaCheckerVfov;
  return scene;
}

}  // namespace raylab
