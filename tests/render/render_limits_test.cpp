// Limits a render keeps whatever it is given: NaN or infinite radiance is counted and replaced by
// black rather than poisoning a pixel (single rays and packets alike); the ray tree stops at
// WhittedIntegrator::kMaxDepth even when the settings ask for more; the memory estimate grows with
// what the render allocates; and through the command line, a render that cannot fit is refused
// with the estimate and the limit before anything is written.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "../cli/cli_fixture.h"
#include "raylab/accel/factory.h"
#include "raylab/render/renderer.h"
#include "raylab/render/whitted.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {
namespace {

// A grey sphere in front of the camera, lit by a point light of infinite intensity: every sample
// that sees the lit side of the sphere comes out infinite (or NaN).
Scene infinitely_bright() {
  Scene scene;
  const std::uint32_t object = scene.add_object("ball", scene.add_material(Material{}));
  scene.geometry.add(Sphere{{0.f, 0.f, 0.f}, 1.f}, object);
  Light light;
  light.position = {0.f, 0.f, 4.f};
  light.intensity = Color{std::numeric_limits<float>::infinity()};
  scene.lights.push_back(light);
  scene.camera.from = {0.f, 0.f, 5.f};
  scene.settings.width = 24;
  scene.settings.height = 16;
  scene.settings.spp = 4;
  return scene;
}

TEST(RenderLimits, NonFiniteRadianceIsCountedAndReplacedByBlack) {
  const Scene scene = infinitely_bright();
  const auto accel = make_accelerator("bvh", scene.geometry);
  std::uint64_t counted[2] = {};
  for (bool packets : {false, true}) {
    Film film(24, 16);
    RenderOptions options;
    options.packets = packets;
    const RenderResult result = render(scene, *accel, film, options);
    counted[packets] = result.stats.nonfinite_samples;
    EXPECT_GT(result.stats.nonfinite_samples, 0u) << "the scene must produce some non-finite samples";
    EXPECT_LT(result.stats.nonfinite_samples, 24u * 16 * 4) << "the background is finite";
    for (const Color& c : film.pixels()) {
      ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
    }
    EXPECT_EQ(film.at(12, 8)[0], 0.f) << "the sphere's centre: every sample there was replaced by black";
  }
  EXPECT_EQ(counted[0], counted[1]) << "packets and single rays count the same samples";
}

TEST(RenderLimits, RayTreesStopAtTheCapWhateverTheSettings) {
  // Two facing mirrors: every bounce makes another; with max_depth far above the cap the render
  // must trace at most kMaxDepth levels (and not overflow the stack).
  Scene scene;
  Material mirror;
  mirror.reflectivity = 1.f;
  const std::uint32_t object = scene.add_object("mirrors", scene.add_material(mirror));
  scene.geometry.add(Quad{{-50.f, -50.f, -1.f}, {100.f, 0.f, 0.f}, {0.f, 100.f, 0.f}}, object);
  scene.geometry.add(Quad{{-50.f, -50.f, 1.f}, {0.f, 100.f, 0.f}, {100.f, 0.f, 0.f}}, object);
  scene.camera.from = {0.f, 0.f, 0.5f};
  scene.camera.at = {0.f, 0.f, -1.f};
  scene.settings.width = 4;
  scene.settings.height = 4;
  scene.settings.max_depth = 1 << 20;
  const auto accel = make_accelerator("bvh", scene.geometry);
  Film film(4, 4);
  RenderOptions options;
  options.threads = 1;
  const RenderResult result = render(scene, *accel, film, options);
  const std::uint64_t reflections = result.stats.rays[static_cast<int>(RayKind::kReflection)];
  EXPECT_EQ(reflections, 16u * (WhittedIntegrator::kMaxDepth - 1)) << "one reflection per level below the first";
}

TEST(RenderLimits, TheMemoryEstimateFollowsTheRender) {
  Scene scene = make_demo_scene();
  scene.settings.width = 1000;
  scene.settings.height = 500;
  scene.settings.spp = 16;
  RenderOptions options;
  const RenderMemoryEstimate box = estimate_render_memory(scene, options);
  EXPECT_EQ(box.samples, 1000u * 500 * 16);
  EXPECT_GE(box.image, 1000u * 500 * sizeof(Color));
  EXPECT_GE(box.sums, 1000u * 500 * sizeof(Color));  // the pixel box: one sum per pixel
  EXPECT_EQ(box.accelerator, scene.primitive_count() * kAccelBytesPerPrimitive);
  scene.settings.filter = "gaussian";  // margins: more sums, and weights
  EXPECT_GT(estimate_render_memory(scene, options).sums, box.sums * 5 / 4);
  options.on_checkpoint = [](const RenderProgress&) {};
  scene.settings.filter = "box";
  EXPECT_EQ(estimate_render_memory(scene, options).sums, box.sums * 3);
  scene.settings.width = 2000;
  EXPECT_GT(estimate_render_memory(scene, RenderOptions{}).total(), box.total() + box.image / 2);
}

class RenderLimitsCli : public cli_test::Cli {};

TEST_F(RenderLimitsCli, ARenderThatCannotFitIsRefusedBeforeAnyWork) {
  const cli_test::CliResult huge = run("render demo --width 32768 --height 32768 -o " + out_file("huge.png"));
  EXPECT_EQ(huge.code, 2) << huge.err;
  EXPECT_NE(huge.err.find("more than the limit of"), std::string::npos) << huge.err;
  EXPECT_NE(huge.err.find("80% of this machine's memory"), std::string::npos) << huge.err;
  const cli_test::CliResult small = run("render demo --width 64 --height 32 --max-memory 100K -o " + out_file("s.png"));
  EXPECT_EQ(small.code, 2);
  EXPECT_NE(small.err.find("(--max-memory)"), std::string::npos) << small.err;
  EXPECT_EQ(run("render demo --width 64 --height 32 --max-memory lots -o " + out_file("s.png")).code, 2);
  expect_out_empty();
  EXPECT_EQ(run("render demo --width 64 --height 32 --max-memory 1G -q -o " + out_file("s.png")).code, 0);
}

}  // namespace
}  // namespace raylab
