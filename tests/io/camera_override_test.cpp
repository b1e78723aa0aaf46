// The camera override: vectors read back bit for bit, each part replaces the scene's, --orbit
// turns about the up direction, --up places a fitted camera again, and the usage errors; and
// the parts a checkpoint records, filled back by --resume.

#include <gtest/gtest.h>

#include "raylab/core/error.h"
#include "raylab/io/camera_override.h"
#include "raylab/io/checkpoint_resume.h"
#include "raylab/io/scene_loader.h"

namespace raylab {
namespace {

TEST(CameraOverride, VectorsReadBackBitForBit) {
  for (const Vec3 v : {Vec3{0.1f, -2.5e-7f, 3e8f}, Vec3{1.f / 3.f, 0.f, -0.f}}) {
    EXPECT_EQ(parse_vec3(format_vec3(v)), std::optional<Vec3>(v));
  }
  EXPECT_EQ(parse_vec3(" 1, 2 ,+3"), std::optional<Vec3>(Vec3{1.f, 2.f, 3.f}));
  for (const char* bad : {"", "1,2", "1,2,3,4", "1,,3", "a,b,c", "1,2,inf", "1,2,nan", "1 2 3", "1,2,3x"}) {
    EXPECT_FALSE(parse_vec3(bad).has_value()) << bad;
  }
}

TEST(CameraOverride, EachPartReplacesTheScenesAndTheRestStays) {
  Scene scene = load_scene("demo");
  const CameraSpec before = scene.camera;
  CameraOverride over;
  over.at = Vec3{0.f, 0.5f, 0.f};
  over.fov_degrees = 30.f;
  apply_camera_override(scene, over);
  EXPECT_EQ(scene.camera.from, before.from);
  EXPECT_EQ(scene.camera.at, *over.at);
  EXPECT_EQ(scene.camera.up, before.up);
  EXPECT_EQ(scene.camera.vfov_degrees, 30.f);
}

TEST(CameraOverride, OrbitTurnsTheEyeAboutTheUpDirection) {
  Scene scene;
  scene.camera.from = {0.f, 2.f, 5.f};
  scene.camera.at = {1.f, 0.f, 0.f};
  CameraOverride over;
  over.orbit_degrees = 90.f;
  apply_camera_override(scene, over);
  // Counter-clockwise seen from +Y: +Z goes to +X, -X to +Z; from - at = (-1, 2, 5) -> (5, 2, 1).
  EXPECT_NEAR(scene.camera.from.x, 6.f, 1e-5f);
  EXPECT_NEAR(scene.camera.from.y, 2.f, 1e-6f);
  EXPECT_NEAR(scene.camera.from.z, 1.f, 1e-5f);
  over.orbit_degrees = -720.f;  // whole turns: the same eye, bit for bit
  const Vec3 eye = scene.camera.from;
  apply_camera_override(scene, over);
  EXPECT_EQ(scene.camera.from, eye);
}

TEST(CameraOverride, UpPlacesTheFittedCameraAgainAndKeepsGivenLights) {
  Scene mesh;  // a tetrahedron: no flat base, so +Y
  const Vec3 a{1.f, 1.f, 1.f}, b{-1.f, -1.f, 1.f}, c{-1.f, 1.f, -1.f}, d{1.f, -1.f, -1.f};
  mesh.geometry.triangles = {{a, b, c}, {a, c, d}, {a, d, b}, {b, d, c}};
  fit_camera_and_lights(mesh);
  EXPECT_EQ(mesh.camera.up, Vec3(0.f, 1.f, 0.f));
  mesh.settings.spp = 9;  // settings given after the fit stay
  const Light given{.kind = Light::Kind::kPoint, .position = {7.f, 7.f, 7.f}};
  mesh.lights = {given};
  mesh.lights_fitted = false;
  CameraOverride over;
  over.up_axis = Vec3{0.f, 0.f, 1.f};
  apply_camera_override(mesh, over);
  EXPECT_EQ(mesh.camera.up, Vec3(0.f, 0.f, 1.f));
  EXPECT_EQ(mesh.settings.spp, 9);
  ASSERT_EQ(mesh.lights.size(), 1u);
  EXPECT_EQ(mesh.lights[0].position, given.position);
  // A camera the scene gave is not the fitted one's to replace.
  Scene demo = load_scene("demo");
  EXPECT_THROW(apply_camera_override(demo, over), UsageError);
}

TEST(CameraOverride, CamerasThatCannotRenderAreUsageErrors) {
  const auto refused = [](CameraOverride over) {
    Scene scene = load_scene("demo");
    try {
      apply_camera_override(scene, over);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CameraOverride same;
  same.from = same.at = Vec3{1.f, 2.f, 3.f};
  EXPECT_NE(refused(same).find("--camera-from and --camera-at are the same point"), std::string::npos);
  CameraOverride parallel;
  parallel.from = Vec3{0.f, 5.f, 0.f};
  parallel.at = Vec3{0.f, 0.f, 0.f};
  parallel.up = Vec3{0.f, 2.f, 0.f};
  EXPECT_NE(refused(parallel).find("--camera-up 0,2,0 is parallel"), std::string::npos);
  for (const float fov : {0.f, 180.f, -1.f}) {
    CameraOverride bad;
    bad.fov_degrees = fov;
    EXPECT_NE(refused(bad).find("--fov"), std::string::npos) << fov;
  }
}

TEST(CameraOverride, ACheckpointRecordsTheGivenPartsAndResumeFillsThem) {
  CameraOverride given;
  given.up_axis = Vec3{0.f, 0.f, -1.f};
  given.from = Vec3{0.1f, 0.2f, 0.3f};
  given.orbit_degrees = 12.5f;
  RenderCheckpoint saved;
  saved.scene = "x.obj";
  saved.settings = camera_settings(given);
  EXPECT_EQ(saved.settings.size(), 3u);  // only the parts given
  ResumableRequest request;
  request.camera.fov_degrees = 20.f;  // given on the command line: stays
  fill_from_checkpoint(request, saved, "x.ckpt");
  EXPECT_EQ(request.camera.up_axis, given.up_axis);
  EXPECT_EQ(request.camera.from, given.from);
  EXPECT_EQ(request.camera.orbit_degrees, given.orbit_degrees);
  EXPECT_FALSE(request.camera.at.has_value());
  EXPECT_EQ(request.camera.fov_degrees, 20.f);
  // The filled request records what the checkpoint did, plus the new part: refused.
  RenderCheckpoint now = saved;
  now.settings = camera_settings(request.camera);
  EXPECT_THROW(check_resumable(saved, now, "x.ckpt"), InputError);
}

}  // namespace
}  // namespace raylab
