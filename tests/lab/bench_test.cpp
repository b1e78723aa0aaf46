// `raylab bench` in the library: the ray sets it traces (4x4 tiles, shadow rays ending at the
// light), agreement with Embree on every kind (when built with it), the counts, the JSON, and a
// planted wrong answer that must make it fail.

#include "raylab/lab/bench.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "raylab/accel/brute_force.h"
#include "raylab/accel/embree_reference.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/camera.h"

namespace raylab {
namespace {

BenchOptions small_options() {
  BenchOptions o;
  o.width = 24;
  o.height = 18;
  o.repeats = 1;
  o.threads = 2;
  return o;
}

// Every ray of a set is accounted for exactly once.
void expect_accounted(const BenchAgreement& a, std::size_t rays, const std::string& what) {
  EXPECT_EQ(a.disagreements, 0u) << what;
  EXPECT_EQ(a.same + a.ties + a.embree_cracks, rays) << what;
}

TEST(Bench, PrimaryRaysComeInFourByFourTilesThroughPixelCentres) {
  const Scene scene = load_scene("spd:balls?size=1");
  const int w = 10, h = 7;  // partial tiles at the right and bottom
  std::vector<std::uint32_t> pixel;
  const std::vector<Ray> rays = tiled_primary_rays(scene, w, h, &pixel);
  ASSERT_EQ(rays.size(), std::size_t(w * h));
  ASSERT_EQ(pixel.size(), rays.size());
  // The expected order, written out independently: tiles row-major, pixels row-major inside.
  std::vector<std::uint32_t> expected;
  for (int ty = 0; ty < h; ty += 4)
    for (int tx = 0; tx < w; tx += 4)
      for (int y = ty; y < std::min(h, ty + 4); ++y)
        for (int x = tx; x < std::min(w, tx + 4); ++x) expected.push_back(std::uint32_t(y * w + x));
  EXPECT_EQ(pixel, expected);
  // Where each ray lands on the image, through the camera: the centre of its pixel.
  const Camera camera(scene.camera, w, h);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    float x = 0.f, y = 0.f;
    ASSERT_TRUE(camera.project(rays[i].at(1.f), x, y)) << i;
    EXPECT_NEAR(x, float(expected[i] % w) + 0.5f, 1e-3f) << i;
    EXPECT_NEAR(y, float(expected[i] / w) + 0.5f, 1e-3f) << i;
  }
  // At a multiple of 4 the first 16 rays are exactly the top-left 4x4 block.
  const std::vector<Ray> full = tiled_primary_rays(scene, 8, 8, &pixel);
  for (int k = 0; k < 16; ++k) EXPECT_EQ(pixel[k], std::uint32_t((k / 4) * 8 + k % 4)) << k;
  EXPECT_THROW(tiled_primary_rays(scene, 0, 4), UsageError);
}

TEST(Bench, ShadowRaysEndAtTheLightAndDiffuseRaysStartAtTheHits) {
  const Scene scene = load_scene("spd:balls?size=1");
  const auto brute = make_accelerator("brute", scene.geometry);
  bool from_scene = false;
  const Light light = bench_light(scene, from_scene);
  EXPECT_TRUE(from_scene);
  EXPECT_EQ(light.position, scene.lights.front().position);  // the first light of spd:balls is a point light
  const RaySets sets = make_bench_rays(scene, *brute, light, 20, 16, 7);
  const std::vector<Ray>& primary = sets[BenchRayKind::kPrimary].rays;
  std::size_t hits = 0;
  for (Ray r : primary) {
    Hit h;
    hits += brute->intersect(r, h) ? 1 : 0;
  }
  EXPECT_EQ(sets[BenchRayKind::kDiffuse].rays.size(), hits);  // one bounce per primary hit
  const std::vector<Ray>& shadow = sets[BenchRayKind::kShadow].rays;
  ASSERT_GT(shadow.size(), 0u);
  EXPECT_LE(shadow.size(), hits);
  for (const Ray& s : shadow) {
    // Stopped 0.1% short of the light (the Whitted integrator's margin), on the line to it.
    const Vec3 end = s.at(s.tmax / (1.f - 1e-3f));
    EXPECT_LT(length(end - light.position), 1e-3f * (1.f + length(light.position - s.origin))) << s.tmax;
  }
}

TEST(Bench, WithoutAPointLightOneIsPlacedAboveTheScene) {
  Scene scene = load_scene("spd:balls?size=1");
  scene.lights.clear();
  bool from_scene = true;
  const Light light = bench_light(scene, from_scene);
  EXPECT_FALSE(from_scene);
  EXPECT_EQ(light.kind, Light::Kind::kPoint);
  const Box3 b = scene.geometry.bounds();
  const Vec3 up = normalize(scene.camera.up);
  float top = -INFINITY;  // highest corner of the bounds along `up`
  for (int c = 0; c < 8; ++c) {
    const Vec3 p{c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z};
    top = std::max(top, dot(p, up));
  }
  EXPECT_NEAR(dot(light.position, up), top + length(b.hi - b.lo), 1e-3f * length(b.hi - b.lo));
}

TEST(Bench, EveryKindAgreesWithEmbreeAndTheCountsAreRight) {
  const Scene scene = load_scene("spd:balls?size=1");  // spheres: Embree user geometry
  const BenchOptions o = small_options();
  const BenchReport r = run_bench(scene, o);
  const bool embree = embree_reference_available();
  EXPECT_EQ(r.embree, embree);
  EXPECT_EQ(r.primitives, scene.geometry.size());
  ASSERT_EQ(r.sets.size(), 3u);
  EXPECT_EQ(r.sets[0].name, "primary");
  EXPECT_EQ(r.sets[1].name, "shadow");
  EXPECT_EQ(r.sets[2].name, "diffuse");
  EXPECT_EQ(r.sets[0].rays, std::size_t(o.width * o.height));
  EXPECT_EQ(r.sets[2].rays, r.sets[0].answered);  // a bounce per primary hit
  EXPECT_LE(r.sets[1].rays, r.sets[0].answered);
  EXPECT_FALSE(r.sets[2].packets);
  for (const BenchSetReport& s : r.sets) {
    if (embree) expect_accounted(s.single, s.rays, s.name + " single");
    if (s.packets) expect_accounted(s.packet, s.rays, s.name + " packets");
    EXPECT_GT(s.single_mrays.ours, 0.0) << s.name;
    EXPECT_EQ(s.single_mrays.embree > 0.0, embree) << s.name;
  }
  EXPECT_GT(r.build_ms.ours, 0.0);
  EXPECT_GT(r.bytes_per_triangle.ours, 0.0);
  EXPECT_GT(r.sah_cost.ours, 1.0);  // at least the root's traversal plus a primitive test
  if (embree) {
    EXPECT_EQ(r.user_primitives, scene.geometry.size() - scene.geometry.triangles.size());
    EXPECT_GT(r.bytes_per_triangle.embree, 0.0);
    // Both binned SAH builders on the same boxes: the costs are of one magnitude.
    EXPECT_GT(r.sah_cost.embree, 0.5 * r.sah_cost.ours);
    EXPECT_LT(r.sah_cost.embree, 2.0 * r.sah_cost.ours);
  }
  EXPECT_EQ(r.last_set, "diffuse");
  EXPECT_EQ(r.last_hits.size(), r.sets[2].rays);
}

TEST(Bench, ATriangleMeshWithoutPointLightsAgreesToo) {
  Scene scene = load_scene("spd:tetra?size=2");
  scene.lights.clear();
  BenchOptions o = small_options();
  o.kinds = {BenchRayKind::kShadow, BenchRayKind::kPrimary};
  o.accel = "bvh2";
  const BenchReport r = run_bench(scene, o);
  ASSERT_EQ(r.sets.size(), 2u);
  EXPECT_EQ(r.sets[0].name, "shadow");
  EXPECT_GT(r.sets[0].rays, 0u);
  EXPECT_FALSE(r.light_from_scene);
  if (r.embree) {
    EXPECT_EQ(r.user_primitives, 0u);
    for (const BenchSetReport& s : r.sets) expect_accounted(s.single, s.rays, s.name);
  }
  EXPECT_EQ(r.accel, "bvh2");
}

// Embree restricted to AVX2 kernels (to compare with raylab's AVX2 build like with like) answers
// as its default kernels do, and the report says which kernels ran.
TEST(Bench, EmbreeRestrictedToAvx2AgreesToo) {
  if (!embree_reference_available()) GTEST_SKIP() << "built without Embree";
  Scene scene = load_scene("spd:tetra?size=2");
  BenchOptions o = small_options();
  o.kinds = {BenchRayKind::kPrimary, BenchRayKind::kShadow};
  o.embree_isa = "avx2";
  const BenchReport r = run_bench(scene, o);
  ASSERT_TRUE(r.embree);
  for (const BenchSetReport& s : r.sets) expect_accounted(s.single, s.rays, s.name);
  bool named = false;
  for (const std::string& note : r.notes) named = named || note.find("kernels: avx2") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST(Bench, FileRaysAreTracedAndTheirHitsMatchBruteForce) {
  const Scene scene = load_scene("spd:balls?size=1");
  BenchOptions o = small_options();
  o.use_file_rays = true;
  o.file_rays = tiled_primary_rays(scene, 9, 5);
  o.file_rays_name = "test.rays";
  o.against_embree = false;
  const BenchReport r = run_bench(scene, o);
  EXPECT_FALSE(r.embree);
  ASSERT_EQ(r.sets.size(), 1u);
  EXPECT_EQ(r.sets[0].name, "file");
  EXPECT_EQ(r.sets[0].rays, 45u);
  expect_accounted(r.sets[0].packet, 45, "packets vs singles");
  const auto brute = make_accelerator("brute", scene.geometry);
  ASSERT_EQ(r.last_hits.size(), 45u);
  for (std::size_t i = 0; i < 45; ++i) {
    Ray ray = o.file_rays[i];
    Hit h;
    brute->intersect(ray, h);
    EXPECT_EQ(r.last_hits[i].prim_id, h.prim_id) << i;
    if (h.valid()) {
      EXPECT_FLOAT_EQ(r.last_hits[i].t, h.t) << i;
    }
  }
}

// Forgets every hit on one primitive: a wrong answer the check must catch.
class BlindAccel final : public Accelerator {
 public:
  BlindAccel(const Geometry& g, std::uint32_t blind) : m_inner(make_accelerator("bvh", g)), m_blind(blind) {}
  Box3 bounds() const override { return m_inner->bounds(); }
  bool intersect(Ray& ray, Hit& hit) const override {
    Ray r = ray;
    Hit h = hit;
    if (!m_inner->intersect(r, h) || h.prim_id == m_blind) return false;
    ray = r, hit = h;
    return true;
  }
  bool occluded(const Ray& ray) const override { return m_inner->occluded(ray); }
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats&) const override { return intersect(ray, hit); }
  bool occluded_counted(const Ray& ray, TraversalStats&) const override { return occluded(ray); }
  using Accelerator::intersect;
  using Accelerator::occluded;
  AccelInfo info() const override { return m_inner->info(); }

 private:
  std::unique_ptr<Accelerator> m_inner;
  std::uint32_t m_blind;
};

TEST(Bench, AWrongAnswerFailsLoudlyWithTheRays) {
  if (!embree_reference_available()) GTEST_SKIP() << "built without Embree";
  const Scene scene = load_scene("spd:balls?size=1");
  BenchOptions o = small_options();
  o.kinds = {BenchRayKind::kPrimary};
  // The primitive seen by the centre ray, so that many rays hit it.
  const auto brute = make_accelerator("brute", scene.geometry);
  Ray centre = Camera(scene.camera, 1, 1).generate(0.5f, 0.5f);
  Hit h;
  ASSERT_TRUE(brute->intersect(centre, h));
  try {
    run_bench(scene, o, [&](const Geometry& g) { return std::make_unique<BlindAccel>(g, h.prim_id); });
    FAIL() << "no disagreement reported";
  } catch (const BenchDisagreement& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("disagree"), std::string::npos) << what;
    EXPECT_NE(what.find("primary single rays"), std::string::npos) << what;
    EXPECT_NE(what.find("ray "), std::string::npos) << what;  // the first rays are listed
  }
}

TEST(Bench, JsonParsesAndHoldsTheFigures) {
  const Scene scene = load_scene("spd:balls?size=1");
  BenchOptions o = small_options();
  o.kinds = {BenchRayKind::kPrimary, BenchRayKind::kShadow};
  const BenchReport r = run_bench(scene, o);
  const nlohmann::json j = nlohmann::json::parse(format_bench_json(r, "spd:balls?size=1"));
  EXPECT_EQ(j["scene"], "spd:balls?size=1");
  EXPECT_EQ(j["accel"], "bvh");
  EXPECT_EQ(j["primitives"], r.primitives);
  EXPECT_EQ(j["width"], 24);
  EXPECT_EQ(j["threads"], 2);
  EXPECT_EQ(j["embree"], r.embree);
  for (const char* key : {"build_ms", "build_mprims_per_s", "bytes_per_triangle", "sah_cost"}) {
    ASSERT_TRUE(j[key].is_object()) << key;
    EXPECT_GT(j[key]["ours"].get<double>(), 0.0) << key;
    EXPECT_EQ(j[key]["ratio"].is_number(), r.embree) << key;
  }
  ASSERT_EQ(j["sets"].size(), 2u);
  EXPECT_EQ(j["sets"][0]["name"], "primary");
  EXPECT_EQ(j["sets"][0]["query"], "closest");
  EXPECT_EQ(j["sets"][1]["query"], "any");
  EXPECT_EQ(j["sets"][0]["rays"], 24 * 18);
  EXPECT_GT(j["sets"][1]["packet16"]["mrays_per_s"]["ours"].get<double>(), 0.0);
  if (r.embree) {
    EXPECT_EQ(j["sets"][0]["single"]["agreement"]["disagreements"], 0);
  }
  EXPECT_TRUE(j["notes"].is_array());
  const std::string table = format_bench_table(r, "spd:balls?size=1");
  EXPECT_NE(table.find("primary packet16 Mrays/s"), std::string::npos) << table;
  EXPECT_NE(table.find("SAH cost"), std::string::npos) << table;
}

TEST(Bench, BadOptionsAreUsageErrors) {
  const Scene scene = load_scene("spd:balls?size=1");
  BenchOptions o = small_options();
  o.repeats = 0;
  EXPECT_THROW(run_bench(scene, o), UsageError);
  o = small_options();
  o.accel = "kdtree";
  EXPECT_THROW(run_bench(scene, o), UsageError);
  o = small_options();
  o.width = 0;
  EXPECT_THROW(run_bench(scene, o), UsageError);
}

}  // namespace
}  // namespace raylab
