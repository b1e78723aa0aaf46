// BVH-only checks ("bvh", the wide one at the native width, "bvh4", "bvh8", "bvh16", and "bvh2",
// the binary one): other build parameters, group queries, a single leaf, and the factory. The
// comparison with brute force on the stress scenes runs for every structure in
// accel_vs_brute_test.cpp; the binary tree's structure is checked in bvh_tree_test.cpp, the wide
// collapse in wide_bvh_test.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "../test_util.h"
#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/bvh.h"
#include "raylab/accel/factory.h"
#include "raylab/accel/wide_bvh.h"
#include "raylab/core/error.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

// The structure under test, by factory name: every test of these suites runs for each of them.
class BvhVsBrute : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<Accelerator> make(const Geometry& g, const BvhConfig& config = {}) const {
    AccelConfig accel;
    accel.bvh = config;
    return make_accelerator(GetParam(), g, accel);
  }
};
class BvhPacket : public BvhVsBrute {};
class BvhEdgeCases : public BvhVsBrute {};

// Build parameters other than the defaults must give the same answers (their trees are checked
// in bvh_tree_test.cpp).
TEST_P(BvhVsBrute, OtherBuildConfigs) {
  for (const BvhConfig config :
       {BvhConfig{2, 1, 1.f, 1.f, 4096}, BvhConfig{64, 32, 0.5f, 2.f, 4096}, BvhConfig{16, 4, 1.f, 1.f, 64}}) {
    Sampler s(7);
    const Geometry g = every_shape_kind(s);
    const BruteForce brute(g);
    compare(g, *make(g, config), brute, random_rays(g, s, 2000), s);
  }
}

TEST_P(BvhPacket, GroupQueriesEqualSingleRays) {
  Sampler s(8);
  const Geometry g = spheres_and_triangles(s);
  const auto bvh = make(g);
  std::vector<Ray> rays = random_rays(g, s, 512);
  std::vector<Ray> singles = rays;
  std::vector<Hit> hits(rays.size()), single_hits(rays.size());
  bvh->intersect(std::span<Ray>(rays), std::span<Hit>(hits));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    bvh->intersect(singles[i], single_hits[i]);
    EXPECT_TRUE(same_hit(hits[i], single_hits[i])) << "ray " << i;
    EXPECT_EQ(rays[i].tmax, singles[i].tmax) << "ray " << i;
  }
  std::vector<std::uint8_t> occ(rays.size(), 7);
  const std::vector<Ray> shadow = random_rays(g, s, 512);
  bvh->occluded(std::span<const Ray>(shadow), std::span<std::uint8_t>(occ));
  for (std::size_t i = 0; i < shadow.size(); ++i) EXPECT_EQ(occ[i], bvh->occluded(shadow[i]) ? 1 : 0) << "ray " << i;
}

// The queries on one primitive are checked for every structure (AccelVsBrute.OnePrimitive);
// here, the tree's own shape: one leaf (the binary tree's shape is checked in bvh_tree_test.cpp).
TEST_P(BvhEdgeCases, SinglePrimitive) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 3);
  EXPECT_EQ(make(g)->info().leaf_count, 1u);
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) { return info.param; }
INSTANTIATE_TEST_SUITE_P(Accel, BvhVsBrute, ::testing::Values("bvh", "bvh2", "bvh4", "bvh8", "bvh16"), param_name);
INSTANTIATE_TEST_SUITE_P(Accel, BvhPacket, ::testing::Values("bvh", "bvh2", "bvh4", "bvh8", "bvh16"), param_name);
INSTANTIATE_TEST_SUITE_P(Accel, BvhEdgeCases, ::testing::Values("bvh", "bvh2", "bvh4", "bvh8", "bvh16"), param_name);

TEST(AccelFactory, NamesAndUnknownName) {
  const auto names = accelerator_names();
  for (const char* name : {"bvh", "bvh2", "brute"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  Geometry g;
  g.add(Sphere{}, 0);
  EXPECT_EQ(make_accelerator("bvh", g)->info().name, "bvh");
  EXPECT_EQ(make_accelerator("bvh2", g)->info().name, "bvh2");
  EXPECT_EQ(make_accelerator("brute", g)->info().name, "brute");
  // "bvh" is the wide tree at the build's native width, "bvh2" the binary one.
  EXPECT_NE(dynamic_cast<const WideBvh<4>*>(make_accelerator("bvh4", g).get()), nullptr);
  EXPECT_NE(dynamic_cast<const WideBvh<16>*>(make_accelerator("bvh16", g).get()), nullptr);
  EXPECT_NE(dynamic_cast<const Bvh*>(make_accelerator("bvh2", g).get()), nullptr);
  test::expect_contains_all(test::thrown_message<UsageError>([&] { make_accelerator("nope", g); }),
                            {"nope", "bvh", "bvh2", "brute"});
}

}  // namespace
}  // namespace raylab
