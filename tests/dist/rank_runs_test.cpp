// The library calls a program makes on each rank: one image (render_image_on_ranks) and an
// animation (render_animation), here over a one-rank channel, give the bits of render() in one
// process; the agreement hash follows every setting.

#include <gtest/gtest.h>

#include <map>
#include <memory>

#include "raylab/accel/factory.h"
#include "raylab/dist/animation.h"
#include "raylab/dist/image_on_ranks.h"
#include "raylab/dist/local_channel.h"
#include "raylab/dist/render_agreement.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab::dist {
namespace {

Scene small_scene() {
  Scene s = make_demo_scene();
  s.settings.width = 29;
  s.settings.height = 17;
  s.settings.spp = 2;
  s.settings.sampler = "jittered";
  return s;
}

Film render_here(const Scene& scene, const Accelerator& accel) {
  Film film(scene.settings.width, scene.settings.height);
  RenderOptions o;
  o.threads = 2;
  render(scene, accel, film, o);
  return film;
}

void expect_same_pixels(const Film& a, const Film& b) {
  ASSERT_EQ(a.width(), b.width());
  ASSERT_EQ(a.height(), b.height());
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      ASSERT_EQ(a.at(x, y).x, b.at(x, y).x) << x << "," << y;
      ASSERT_EQ(a.at(x, y).y, b.at(x, y).y) << x << "," << y;
      ASSERT_EQ(a.at(x, y).z, b.at(x, y).z) << x << "," << y;
    }
  }
}

TEST(RankRuns, OneImageOnOneRankIsTheLocalImage) {
  const Scene scene = small_scene();
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  auto channels = make_local_channels(1);
  RenderProgress progress;
  int checkpoints = 0;
  DistributedOptions options;
  options.render.threads = 2;
  options.render.progress = &progress;
  options.render.on_checkpoint = [&checkpoints](const RenderProgress&) { ++checkpoints; };
  const ImageOnRanks run = render_image_on_ranks(*channels[0], scene, *accel, options);
  EXPECT_EQ(run.result.outcome, DistributedOutcome::kComplete);
  EXPECT_EQ(run.exit_status, 0);
  EXPECT_EQ(checkpoints, 0);
  expect_same_pixels(run.film, render_here(scene, *accel));
}

TEST(RankRuns, AnAnimationOnOneRankRendersEachFrameWithItsCamera) {
  Scene scene = small_scene();
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  CameraSpec moved = scene.camera;
  moved.from = moved.from + Vec3{0.5f, 0.f, 0.f};
  scene.camera_path.keys = {CameraKey{0, scene.camera}, CameraKey{1, moved}};
  auto channels = make_local_channels(1);
  std::map<int, Film> frames;
  AnimationOptions options;
  options.first = 0;
  options.last = 1;
  options.render.threads = 2;
  options.on_frame = [&frames](const RenderedFrame& f) { frames.emplace(f.frame, f.film); };
  const Animation run = render_animation(*channels[0], scene, *accel, options);
  EXPECT_EQ(run.result.outcome, DistributedOutcome::kComplete);
  EXPECT_EQ(run.exit_status, 0);
  ASSERT_EQ(frames.size(), 2u);
  for (int f = 0; f < 2; ++f) {
    Scene alone = small_scene();
    alone.camera = scene.camera_path.at(f);
    expect_same_pixels(frames.at(f), render_here(alone, *accel));
  }
}

TEST(RankRuns, TheAgreementFollowsEverySetting) {
  RenderCheckpoint a{"demo", 1, {{"spp", "4"}, {"width", "8"}}, {}};
  RenderCheckpoint b = a;
  EXPECT_EQ(render_agreement(a), render_agreement(b));
  b.settings[0].second = "5";
  EXPECT_NE(render_agreement(a), render_agreement(b));
  b = a;
  b.scene_fingerprint = 2;
  EXPECT_NE(render_agreement(a), render_agreement(b));
}

}  // namespace
}  // namespace raylab::dist
