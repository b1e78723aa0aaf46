// `raylab compare` in the library: the measurements are sane, a wrong structure is caught with
// the rays it gets wrong, brute force is skipped when too slow, and the reports say so.

#include "raylab/lab/accel_compare.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/io/scene_loader.h"

namespace raylab {
namespace {

// A structure that answers like `inner` except that it never reports primitive `dropped`:
// the kind of bug (a lost reference, a skipped cell) the agreement check must catch.
class DroppingAccelerator final : public Accelerator {
 public:
  DroppingAccelerator(std::unique_ptr<Accelerator> inner, std::uint32_t dropped)
      : m_inner(std::move(inner)), m_dropped(dropped) {}
  Box3 bounds() const override { return m_inner->bounds(); }
  bool intersect(Ray& ray, Hit& hit) const override {
    Ray copy = ray;
    Hit h;
    if (!m_inner->intersect(copy, h) || h.prim_id == m_dropped) return false;
    ray = copy;
    hit = h;
    return true;
  }
  bool occluded(const Ray& ray) const override { return m_inner->occluded(ray); }
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const override {
    ++stats.prim_tests;
    return intersect(ray, hit);
  }
  bool occluded_counted(const Ray& ray, TraversalStats& stats) const override {
    ++stats.prim_tests;
    return occluded(ray);
  }
  AccelInfo info() const override {
    AccelInfo i = m_inner->info();
    i.name = "dropper";
    return i;
  }

 private:
  std::unique_ptr<Accelerator> m_inner;
  std::uint32_t m_dropped;
};

Scene small_scene() { return load_scene("spd:balls?size=2"); }

CompareOptions small_options(std::vector<std::string> accels) {
  CompareOptions o;
  o.accels = std::move(accels);
  o.rays = {40, 30, 0};
  o.repeat = 1;
  return o;
}

const AccelMeasure& find(const CompareResult& r, const std::string& name) {
  const auto it = std::find_if(r.accels.begin(), r.accels.end(), [&](const AccelMeasure& m) { return m.name == name; });
  EXPECT_NE(it, r.accels.end()) << name;
  return *it;
}

TEST(AccelCompare, StructuresAgreeAndTheirCountsAreSane) {
  const Scene scene = small_scene();
  const CompareResult r = compare_accelerators(scene, small_options({"bvh", "brute", "bvh2"}));
  ASSERT_EQ(r.accels.size(), 3u);
  EXPECT_EQ(r.accels[0].name, "bvh");  // table order is the order asked for
  EXPECT_TRUE(r.agreed());
  EXPECT_EQ(r.reference, "brute");  // brute force is the reference whenever it runs
  EXPECT_TRUE(find(r, "brute").is_reference);
  EXPECT_EQ(r.rays[0], 40u * 30u);
  const AccelMeasure& brute = find(r, "brute");
  // Brute force tests every primitive on every closest-hit query, and visits no node.
  EXPECT_DOUBLE_EQ(brute.kinds[0].tests_per_ray, static_cast<double>(scene.primitive_count()));
  EXPECT_DOUBLE_EQ(brute.kinds[2].tests_per_ray, static_cast<double>(scene.primitive_count()));
  EXPECT_LE(brute.kinds[1].tests_per_ray, static_cast<double>(scene.primitive_count()));
  EXPECT_EQ(brute.kinds[0].nodes_per_ray, 0.0);
  for (const AccelMeasure& m : r.accels) {
    SCOPED_TRACE(m.name);
    EXPECT_FALSE(m.skipped);
    EXPECT_GE(m.builds, 1);
    EXPECT_GT(m.info.memory_bytes, 0u);
    EXPECT_EQ(m.pixel_tests.size(), r.rays[0]);
    for (int k = 0; k < kBenchRayKinds; ++k) {
      EXPECT_EQ(m.kinds[k].rays, r.rays[k]);
      EXPECT_GT(m.kinds[k].mrays_per_second, 0.0);
      EXPECT_EQ(m.kinds[k].hits, brute.kinds[k].hits);
    }
    // The per-pixel counts add up to the average.
    double sum = 0.0;
    for (std::uint32_t v : m.pixel_tests) sum += v;
    EXPECT_NEAR(sum / static_cast<double>(r.rays[0]), m.kinds[0].tests_per_ray, 1e-9);
  }
  // A BVH tests far fewer primitives than brute force, even on a scene this small.
  EXPECT_LT(find(r, "bvh").kinds[0].tests_per_ray, brute.kinds[0].tests_per_ray / 3.0);
  const std::string table = format_compare_table(r, "spd:balls?size=2");
  for (const char* name : {"\nbvh ", "\nbvh2 ", "\nbrute "}) EXPECT_NE(table.find(name), std::string::npos) << table;
  EXPECT_NE(table.find("reference"), std::string::npos);
  EXPECT_TRUE(format_mismatches(r).empty());
}

TEST(AccelCompare, AWrongStructureIsCaughtWithTheRaysItGetsWrong) {
  const Scene scene = small_scene();
  // The primitive most primary rays hit (the ground), so that the error shows on many rays.
  const std::uint32_t dropped = 0;
  const AccelBuilder build = [&](const std::string& name) -> std::unique_ptr<Accelerator> {
    if (name == "dropper")
      return std::make_unique<DroppingAccelerator>(make_accelerator("bvh", scene.geometry), dropped);
    return make_accelerator(name, scene.geometry);
  };
  const CompareResult r = compare_accelerators(scene, small_options({"brute", "dropper", "bvh"}), build);
  EXPECT_FALSE(r.agreed());
  EXPECT_EQ(find(r, "bvh").mismatch_count, 0u);
  const AccelMeasure& bad = find(r, "dropper");
  ASSERT_GT(bad.mismatch_count, 0u);
  ASSERT_EQ(bad.mismatches.size(), std::min<std::size_t>(bad.mismatch_count, 5));
  for (const Mismatch& m : bad.mismatches) {
    EXPECT_NE(m.kind, BenchRayKind::kShadow);  // the dropper answers shadow rays correctly
    EXPECT_EQ(m.expected.prim_id, dropped);
    EXPECT_NE(m.found.prim_id, dropped);
  }
  // Every ray whose reference hit is the dropped primitive is counted, and no other.
  const auto bvh = make_accelerator("bvh", scene.geometry);
  const RaySets sets = make_ray_sets(scene, *bvh, small_options({}).rays);
  const RayAnswers answers = trace_answers(*bvh, sets);
  std::size_t expected = 0;
  for (const Hit& h : answers.primary) expected += h.prim_id == dropped;
  for (const Hit& h : answers.diffuse) expected += h.prim_id == dropped;
  EXPECT_EQ(bad.mismatch_count, expected);
  const std::string report = format_mismatches(r);
  EXPECT_NE(report.find("dropper disagrees with brute"), std::string::npos) << report;
  EXPECT_NE(report.find("origin ("), std::string::npos) << report;
  EXPECT_NE(report.find("prim 0 at t"), std::string::npos) << report;
  EXPECT_NE(format_compare_table(r, "x").find(std::to_string(bad.mismatch_count) + " rays differ"), std::string::npos);
}

TEST(AccelCompare, ShadowDisagreementsAreFound) {
  const Scene scene = small_scene();
  const auto bvh = make_accelerator("bvh", scene.geometry);
  const RaySets sets = make_ray_sets(scene, *bvh, {16, 12, 0});
  const RayAnswers good = trace_answers(*bvh, sets);
  ASSERT_FALSE(good.shadow.empty());
  RayAnswers bad = good;
  bad.shadow[3] ^= 1;
  std::vector<Mismatch> kept;
  EXPECT_EQ(find_mismatches(sets, good, good, 1e-4f, 5, kept), 0u);
  EXPECT_EQ(find_mismatches(sets, good, bad, 1e-4f, 5, kept), 1u);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].kind, BenchRayKind::kShadow);
  EXPECT_EQ(kept[0].index, 3u);
  EXPECT_EQ(kept[0].expected_occluded, good.shadow[3] != 0);
  EXPECT_EQ(kept[0].ray.origin, sets[BenchRayKind::kShadow].rays[3].origin);
}

TEST(AccelCompare, HitsAgreeOnTheSamePrimitiveOrTheSameDistance) {
  const Hit miss;
  const Hit a{2.f, 7, 0.f, 0.f};
  EXPECT_TRUE(hits_agree(miss, miss, 1e-4f));
  EXPECT_FALSE(hits_agree(miss, a, 1e-4f));
  EXPECT_FALSE(hits_agree(a, miss, 1e-4f));
  EXPECT_TRUE(hits_agree(a, Hit{2.0001f, 7, 0.f, 0.f}, 1e-6f));  // same primitive: t may differ
  EXPECT_TRUE(hits_agree(a, Hit{2.f, 9, 0.f, 0.f}, 1e-4f));      // a tie between two primitives
  EXPECT_TRUE(hits_agree(a, Hit{2.0001f, 9, 0.f, 0.f}, 1e-4f));  // within 1e-4 relative
  EXPECT_FALSE(hits_agree(a, Hit{2.001f, 9, 0.f, 0.f}, 1e-4f));
}

TEST(AccelCompare, BruteForceIsSkippedAboveTheTimeLimit) {
  const Scene scene = small_scene();
  CompareOptions o = small_options({"brute", "bvh", "bvh2"});
  o.brute_limit_seconds = 0.0;
  const CompareResult r = compare_accelerators(scene, o);
  const AccelMeasure& brute = find(r, "brute");
  EXPECT_TRUE(brute.skipped);
  EXPECT_GT(brute.estimated_seconds, 0.0);
  EXPECT_EQ(r.reference, "bvh");  // then the first structure listed is the reference
  EXPECT_TRUE(r.agreed());
  const std::string table = format_compare_table(r, "s");
  EXPECT_NE(table.find("skipped (estimated"), std::string::npos) << table;
  const std::string csv = format_compare_csv(r);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);  // header + three rows
  // Every line has the same number of fields, skipped row included.
  std::size_t start = 0, fields = 0;
  while (start < csv.size()) {
    const std::size_t end = csv.find('\n', start);
    const auto n = static_cast<std::size_t>(std::count(csv.begin() + start, csv.begin() + end, ','));
    if (start == 0) fields = n;
    EXPECT_EQ(n, fields) << csv.substr(start, end - start);
    start = end + 1;
  }
  const std::string json = format_compare_json(r, "s");
  EXPECT_NE(json.find("\"skipped\": true"), std::string::npos) << json;
  EXPECT_NE(json.find("\"reference\": \"bvh\""), std::string::npos) << json;
  // With the default limit, the estimate of a scene this small is far below it and brute runs.
  EXPECT_FALSE(find(compare_accelerators(scene, small_options({"brute"})), "brute").skipped);
}

TEST(AccelCompare, BadListsAreUsageErrors) {
  const Scene scene = small_scene();
  EXPECT_THROW(compare_accelerators(scene, small_options({"bvh", "kd-tree"})), UsageError);
  EXPECT_THROW(compare_accelerators(scene, small_options({"bvh", "bvh"})), UsageError);
  EXPECT_THROW(compare_accelerators(scene, small_options({})), UsageError);
  CompareOptions o = small_options({"bvh"});
  o.repeat = 0;
  EXPECT_THROW(compare_accelerators(scene, o), UsageError);
  try {
    compare_accelerators(scene, small_options({"kd-tree"}));
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("bvh, bvh2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raylab
