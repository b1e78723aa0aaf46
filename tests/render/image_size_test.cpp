// The image-size rule: one side given, the other follows the scene's shape; both given in another
// shape, the camera's view widens so that the corners of the scene's own frame stay in the image.

#include <gtest/gtest.h>

#include "raylab/render/camera.h"
#include "raylab/render/image_size.h"

namespace raylab {
namespace {

Scene framed_scene(int width, int height) {
  Scene scene;
  scene.settings.width = width;
  scene.settings.height = height;
  scene.camera.vfov_degrees = 50.f;
  return scene;
}

TEST(ImageSize, OneSideGivenTheOtherFollowsTheScenesShape) {
  EXPECT_EQ(image_size_for(640, 400, 320, std::nullopt).height, 200);
  EXPECT_EQ(image_size_for(640, 400, std::nullopt, 50).width, 80);
  EXPECT_EQ(image_size_for(640, 400, 33, std::nullopt).height, 21);  // 20.625, rounded
  EXPECT_EQ(image_size_for(640, 400, 1, std::nullopt).height, 1);    // at least one row
  EXPECT_EQ(image_size_for(1, 32768, std::nullopt, 1).width, 1);
  const ImageSize both = image_size_for(640, 400, 10, 30);
  EXPECT_EQ(both.width, 10);
  EXPECT_EQ(both.height, 30);
  const ImageSize neither = image_size_for(640, 400, std::nullopt, std::nullopt);
  EXPECT_EQ(neither.width, 640);
  EXPECT_EQ(neither.height, 400);
}

TEST(ImageSize, TheScenesOwnSizeKeepsTheCameraAsItIs) {
  Scene scene = framed_scene(640, 400);
  set_image_size(scene, 640, std::nullopt);
  EXPECT_EQ(scene.camera.framed_aspect, 0.f);
  set_image_size(scene, 320, std::nullopt);
  EXPECT_EQ(scene.settings.height, 200);
  EXPECT_EQ(scene.camera.framed_aspect, 1.6f);
}

// The four corners of the scene's own frame, projected with the camera of the new size, land
// inside the new image, on its border along the side that did not widen.
TEST(ImageSize, EveryShapeContainsTheScenesFrame) {
  for (const ImageSize size : {ImageSize{100, 300}, ImageSize{300, 100}, ImageSize{64, 40}, ImageSize{7, 1}}) {
    SCOPED_TRACE(std::to_string(size.width) + "x" + std::to_string(size.height));
    Scene scene = framed_scene(64, 40);
    const Camera own(scene.camera, 64, 40);
    set_image_size(scene, size.width, size.height);
    const Camera now(scene.camera, scene.settings.width, scene.settings.height);
    float min_x = 1e9f, max_x = -1e9f, min_y = 1e9f, max_y = -1e9f;
    for (const float cx : {0.f, 64.f}) {
      for (const float cy : {0.f, 40.f}) {
        const Ray r = own.generate(cx, cy);
        float x = 0.f, y = 0.f;
        ASSERT_TRUE(now.project(r.origin + r.direction * 3.f, x, y));
        min_x = std::min(min_x, x), max_x = std::max(max_x, x);
        min_y = std::min(min_y, y), max_y = std::max(max_y, y);
      }
    }
    const float w = static_cast<float>(size.width), h = static_cast<float>(size.height), eps = 1e-3f * (w + h);
    EXPECT_GE(min_x, -eps);
    EXPECT_LE(max_x, w + eps);
    EXPECT_GE(min_y, -eps);
    EXPECT_LE(max_y, h + eps);
    // Centred, and touching the border on one side or the other: widened, not shrunk.
    EXPECT_NEAR(min_x + max_x, w, eps);
    EXPECT_NEAR(min_y + max_y, h, eps);
    EXPECT_TRUE(std::fabs(min_x) < eps || std::fabs(min_y) < eps);
  }
}

TEST(ImageSize, EveryKeyOfACameraPathIsFramedAlike) {
  Scene scene = framed_scene(64, 40);
  scene.camera_path.keys = {CameraKey{0, scene.camera}, CameraKey{10, scene.camera}};
  set_image_size(scene, 40, 40);
  for (const CameraKey& key : scene.camera_path.keys) EXPECT_EQ(key.camera.framed_aspect, 1.6f);
  EXPECT_EQ(scene.camera_path.at(5).framed_aspect, 1.6f);
}

}  // namespace
}  // namespace raylab
