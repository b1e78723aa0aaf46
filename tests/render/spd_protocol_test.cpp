// The SPD testing procedure's ray-count invariants depend only on the scene: every accelerator
// must report the same counts on all seven SPD scenes.

#include <gtest/gtest.h>

#include <string>

#include "raylab/accel/factory.h"
#include "raylab/render/spd_protocol.h"
#include "raylab/scene/spd.h"

namespace raylab {
namespace {

SpdProtocolCounts protocol_counts(const std::string& source, const std::string& accel_name) {
  Scene scene = make_spd_scene(source);
  const auto accel = make_accelerator(accel_name, scene.geometry);
  Film film(kSpdProtocolSize, kSpdProtocolSize);
  RenderOptions options;
  options.threads = 2;
  return render_spd_protocol(scene, *accel, film, options).counts;
}

void expect_same(const SpdProtocolCounts& a, const SpdProtocolCounts& b) {
  EXPECT_EQ(a.primary, b.primary);
  EXPECT_EQ(a.primary_hits, b.primary_hits);
  EXPECT_EQ(a.shadow, b.shadow);
  EXPECT_EQ(a.shadow_hits, b.shadow_hits);
  EXPECT_EQ(a.secondary, b.secondary);
  EXPECT_EQ(a.secondary_hits, b.secondary_hits);
}

class SpdProtocol : public ::testing::TestWithParam<std::string> {};

// Brute force is the reference; sizes are small so that it takes seconds, not hours.
TEST_P(SpdProtocol, CountsAreTheSameForEveryAcceleratorAtSmallSize) {
  const std::string source = "spd:" + GetParam() + "?size=" + (GetParam() == "teapot" ? "2" : "1");
  const SpdProtocolCounts brute = protocol_counts(source, "brute");
  // Invariants of the procedure itself.
  EXPECT_EQ(brute.primary, 513u * 513u);
  EXPECT_GT(brute.primary_hits, 0u);
  EXPECT_LE(brute.primary_hits, brute.primary);
  EXPECT_LE(brute.shadow_hits, brute.shadow);
  EXPECT_LE(brute.secondary_hits, brute.secondary);
  for (const char* name : {"bvh", "bvh2"}) {
    SCOPED_TRACE(name);
    expect_same(protocol_counts(source, name), brute);
  }
}

// At the default size the BVH layouts must agree with each other too.
TEST_P(SpdProtocol, CountsAreTheSameForBothBvhLayoutsAtDefaultSize) {
  const std::string source = "spd:" + GetParam();
  expect_same(protocol_counts(source, "bvh2"), protocol_counts(source, "bvh"));
}

INSTANTIATE_TEST_SUITE_P(AllSeven, SpdProtocol,
                         ::testing::Values("balls", "gears", "mount", "rings", "teapot", "tetra", "tree"));

TEST(SpdProtocolImage, PixelsAreTheAverageOfTheirFourCorners) {
  // A one-sphere scene: the corner rays at the image's outer corners lie on the field of view.
  Scene scene = make_spd_scene("spd:balls?size=1");
  const auto accel = make_accelerator("bvh", scene.geometry);
  Film film(kSpdProtocolSize, kSpdProtocolSize);
  const SpdProtocolResult r = render_spd_protocol(scene, *accel, film);
  EXPECT_EQ(scene.settings.width, 512);
  EXPECT_EQ(scene.settings.max_depth, 5);
  EXPECT_EQ(r.counts.primary, 513u * 513u);
}

}  // namespace
}  // namespace raylab
