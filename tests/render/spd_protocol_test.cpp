// The SPD testing procedure's ray-count invariants depend only on the scene: every accelerator,
// wrapped or not, must report the same counts on all seven SPD scenes.

#include <gtest/gtest.h>

#include <cstring>
#include <ostream>
#include <string>
#include <vector>

#include "raylab/accel/factory.h"
#include "raylab/accel/two_level.h"
#include "raylab/render/camera.h"
#include "raylab/render/spd_protocol.h"
#include "raylab/render/whitted.h"
#include "raylab/scene/spd.h"

namespace raylab {

// How a failed comparison prints counts: each by name (gtest finds this by argument-dependent
// lookup, so it stands in the counts' namespace).
[[maybe_unused]] static void PrintTo(const SpdProtocolCounts& c, std::ostream* os) {
  *os << "{primary " << c.primary << "/" << c.primary_hits << " hits, shadow " << c.shadow << "/" << c.shadow_hits
      << ", reflection " << c.reflection << "/" << c.reflection_hits << ", refraction " << c.refraction << "/"
      << c.refraction_hits << ", total internal reflections " << c.total_internal_reflections << "}";
}

namespace {

SpdProtocolCounts protocol_counts(const std::string& source, const std::string& accel_name,
                                  WrapMode wrap = WrapMode::kNone, ShadowFacing facing = ShadowFacing::kViewer) {
  Scene scene = make_spd_scene(source);
  SceneAccelOptions options_for_accel;
  options_for_accel.top = accel_name;
  options_for_accel.wrap = wrap;
  const auto accel = make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, options_for_accel);
  Film film(kSpdProtocolSize, kSpdProtocolSize);
  RenderOptions options;
  options.threads = 2;
  return render_spd_protocol(scene, *accel, film, options, facing).counts;
}

// Every count, compared by the struct's own field-by-field ==.
void expect_same(const SpdProtocolCounts& a, const SpdProtocolCounts& b) { EXPECT_EQ(a, b); }

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
  EXPECT_LE(brute.reflection_hits, brute.reflection);
  EXPECT_LE(brute.refraction_hits, brute.refraction);
  for (const char* name : {"bvh", "bvh2", "grid", "grid2", "octree", "irregular"}) {
    SCOPED_TRACE(name);
    expect_same(protocol_counts(source, name), brute);
  }
  // Wrapped meshes (each SPD object with several primitives becomes one item behind a volume).
  SCOPED_TRACE("wrapped");
  expect_same(protocol_counts(source, "bvh", WrapMode::kBox), brute);
  expect_same(protocol_counts(source, "octree", WrapMode::kSphere), brute);
}

// The other reading of rule 10 (shadow rays by the primitive's own normal) is as independent of
// the structure; only shadow rays may differ from the default reading. (The BVH stands in for
// brute force, which the test above holds it to, at a fraction of the time.)
TEST_P(SpdProtocol, OutwardFacingCountsAreTheSameForEveryAccelerator) {
  const std::string source = "spd:" + GetParam() + "?size=" + (GetParam() == "teapot" ? "2" : "1");
  const SpdProtocolCounts bvh = protocol_counts(source, "bvh", WrapMode::kNone, ShadowFacing::kOutward);
  for (const char* name : {"bvh2", "grid", "grid2", "octree", "irregular"}) {
    SCOPED_TRACE(name);
    expect_same(protocol_counts(source, name, WrapMode::kNone, ShadowFacing::kOutward), bvh);
  }
  SpdProtocolCounts viewer = protocol_counts(source, "bvh");
  viewer.shadow = bvh.shadow;
  viewer.shadow_hits = bvh.shadow_hits;
  expect_same(viewer, bvh);
}

// At the default size (too big for brute force) every structure must agree with the BVH.
TEST_P(SpdProtocol, CountsAreTheSameForEveryAcceleratorAtDefaultSize) {
  const std::string source = "spd:" + GetParam();
  const SpdProtocolCounts bvh = protocol_counts(source, "bvh");
  for (const char* name : {"bvh2", "grid", "grid2", "octree", "irregular"}) {
    SCOPED_TRACE(name);
    expect_same(protocol_counts(source, name), bvh);
  }
}

// The corners go to the BVH as 4 x 4 packets; a counted render traces the same corners one by
// one through the single-ray kernels. The two must give the same image, bit for bit, and the
// same counts.
TEST_P(SpdProtocol, PacketsGiveTheImageOfSingleRays) {
  const std::string source = "spd:" + GetParam() + "?size=" + (GetParam() == "teapot" ? "2" : "1");
  Scene scene = make_spd_scene(source);
  const auto accel = make_accelerator("bvh", scene.geometry);
  RenderOptions options;
  options.threads = 2;
  Film packets(kSpdProtocolSize, kSpdProtocolSize), single(kSpdProtocolSize, kSpdProtocolSize);
  const SpdProtocolResult by_packets = render_spd_protocol(scene, *accel, packets, options);
  options.count_traversal = true;
  const SpdProtocolResult by_single = render_spd_protocol(scene, *accel, single, options);
  expect_same(by_packets.counts, by_single.counts);
  EXPECT_GT(by_single.stats.traversal.nodes_visited, 0u);  // the single-ray kernels did run
  int differing = 0;
  for (int y = 0; y < kSpdProtocolSize; ++y) {
    for (int x = 0; x < kSpdProtocolSize; ++x) {
      const Color a = packets.at(x, y), b = single.at(x, y);
      differing += std::memcmp(&a, &b, sizeof(Color)) != 0 ? 1 : 0;
    }
  }
  EXPECT_EQ(differing, 0);
}

INSTANTIATE_TEST_SUITE_P(AllSeven, SpdProtocol,
                         ::testing::Values("balls", "gears", "mount", "rings", "teapot", "tetra", "tree"));

TEST(SpdProtocolImage, PixelsAreTheAverageOfTheirFourCorners) {
  // A one-sphere scene: the corner rays at the image's outer corners lie on the field of view.
  Scene scene = make_spd_scene("spd:balls?size=1");
  const auto accel = make_accelerator("bvh", scene.geometry);
  Film film(0, 0);  // replaced by the image, whatever its size
  RenderOptions options;
  options.threads = 2;
  const SpdProtocolResult r = render_spd_protocol(scene, *accel, film, options);
  EXPECT_EQ(scene.settings.width, 512);
  EXPECT_EQ(scene.settings.max_depth, 5);
  EXPECT_EQ(r.counts.primary, 513u * 513u);
  ASSERT_EQ(film.width(), kSpdProtocolSize);
  ASSERT_EQ(film.height(), kSpdProtocolSize);

  // The corners traced one by one, as a single ray through the Whitted integrator, and each
  // pixel of some rows (the first, the last, the middle and a few more) held to the average of
  // its four, bit for bit: the image is averaged in place over the corners' memory.
  CameraSpec spec = scene.camera;
  spec.fov_span = CameraSpec::FovSpan::kImageEdges;
  const Camera camera(spec, kSpdProtocolSize, kSpdProtocolSize);
  RenderStats stats;
  const TraceContext ctx{scene, *accel, stats};
  const auto corner = [&](int x, int y) {
    Pcg32 rng(0);  // point lights draw no numbers
    return WhittedIntegrator::trace(ctx, camera.generate(static_cast<float>(x), static_cast<float>(y)), 1,
                                    RayKind::kPrimary, rng);
  };
  int differing = 0, hit_pixels = 0;
  for (int y : {0, 1, 130, 255, 256, 383, 510, 511}) {
    std::vector<Color> top(kSpdProtocolSize + 1), bottom(kSpdProtocolSize + 1);
    for (int x = 0; x <= kSpdProtocolSize; ++x) {
      top[x] = corner(x, y);
      bottom[x] = corner(x, y + 1);
    }
    for (int x = 0; x < kSpdProtocolSize; ++x) {
      const Color want = (top[x] + top[x + 1] + bottom[x] + bottom[x + 1]) * 0.25f;
      const Color got = film.at(x, y);
      differing += std::memcmp(&want, &got, sizeof(Color)) != 0 ? 1 : 0;
      hit_pixels += want != WhittedIntegrator::background(scene.settings, Vec3{0, 0, 1}) ? 1 : 0;
    }
  }
  EXPECT_EQ(differing, 0);
  EXPECT_GT(hit_pixels, 100);  // the rows cross the sphere, not only the background
}

// Each corner's generator is seeded (from the render's seed and the corner) only when a light
// draws random numbers. With an area light the seed must reach the samples, so two seeds give
// two images; with the point lights of an SPD scene no number is drawn and the seed is moot.
TEST(SpdProtocolImage, TheSeedReachesAreaLightsAndOnlyThem) {
  const auto render_with_seed = [](Scene scene, std::uint64_t seed) {
    scene.settings.seed = seed;
    const auto accel = make_accelerator("bvh", scene.geometry);
    Film film(kSpdProtocolSize, kSpdProtocolSize);
    RenderOptions options;
    options.threads = 2;
    render_spd_protocol(scene, *accel, film, options);
    return film;
  };
  const auto differing_pixels = [](const Film& a, const Film& b) {
    int differing = 0;
    for (int y = 0; y < kSpdProtocolSize; ++y) {
      for (int x = 0; x < kSpdProtocolSize; ++x) {
        differing += std::memcmp(&a.at(x, y), &b.at(x, y), sizeof(Color)) != 0 ? 1 : 0;
      }
    }
    return differing;
  };
  Scene points = make_spd_scene("spd:balls?size=1");
  ASSERT_FALSE(points.lights.empty());
  EXPECT_EQ(differing_pixels(render_with_seed(points, 1), render_with_seed(points, 2)), 0);

  Scene area = points;
  area.lights[0].kind = Light::Kind::kSphere;
  area.lights[0].radius = 0.5f;
  area.lights[0].samples = 4;
  ASSERT_FALSE(WhittedIntegrator::is_single_sample(area.lights[0]));
  const Film first = render_with_seed(area, 1);
  EXPECT_EQ(differing_pixels(first, render_with_seed(area, 1)), 0);  // the same seed, the same bits
  EXPECT_GT(differing_pixels(first, render_with_seed(area, 2)), 100);
}

}  // namespace
}  // namespace raylab
