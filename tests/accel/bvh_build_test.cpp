// The BVH builder's options and promises beyond a valid tree (bvh_tree_test.cpp checks that): the
// same tree whatever the thread count, the leaf-block cost rule, and spatial splits (tighter
// trees whose every reference really overlaps its leaf, and queries equal to brute force).

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "../../src/accel/bvh_build_partition.h"
#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/bvh.h"
#include "raylab/geometry/overlap.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

Box3 box_of(const BvhNode& node) {
  return {{node.lo[0], node.lo[1], node.lo[2]}, {node.hi[0], node.hi[1], node.hi[2]}};
}

bool inside(const Box3& in, const Box3& out) {
  return out.lo.x <= in.lo.x && out.lo.y <= in.lo.y && out.lo.z <= in.lo.z && in.hi.x <= out.hi.x &&
         in.hi.y <= out.hi.y && in.hi.z <= out.hi.z;
}

BvhTree build_with_threads(const Geometry& g, const BvhConfig& config, int threads) {
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  return build_bvh(g, config);
}

void expect_same_tree(const BvhTree& a, const BvhTree& b) {
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    ASSERT_EQ(std::memcmp(&a.nodes[i], &b.nodes[i], sizeof(BvhNode)), 0) << "node " << i;
  EXPECT_EQ(a.prim_ids, b.prim_ids);
  EXPECT_EQ(a.max_depth, b.max_depth);
  EXPECT_EQ(a.leaf_count, b.leaf_count);
}

// `triangles` random triangles of size 0.1 to `max_size`, then `spheres` spheres of radius 0.1 to
// 2, all in [-50, 50]^3 and in no spatial order.
Geometry random_soup(std::uint64_t seed, int triangles, float max_size, int spheres) {
  Sampler s(seed);
  Geometry g;
  for (int i = 0; i < triangles; ++i) {
    g.add(random_triangle(s, s.in_box(Vec3(-50.f), Vec3(50.f)), s.uni(0.1f, max_size)), 0);
  }
  for (int i = 0; i < spheres; ++i) g.add(Sphere{s.in_box(Vec3(-50.f), Vec3(50.f)), s.uni(0.1f, 2.f)}, 1);
  return g;
}

// Enough triangles that the root bins in parallel and subtrees become tasks.
Geometry many_triangles(std::uint64_t seed) { return random_soup(seed, 17000, 4.f, 500); }

// A disk fan of long thin triangles meeting at the centre, a sliver soup, and a few spheres:
// object splits leave heavily overlapping children here, spatial splits do not.
Geometry fan_and_slivers() {
  Geometry g;
  constexpr int kSegments = 600;
  for (int i = 0; i < kSegments; ++i) {
    const float a0 = 2.f * 3.14159265f * static_cast<float>(i) / kSegments;
    const float a1 = 2.f * 3.14159265f * static_cast<float>(i + 1) / kSegments;
    g.add(Triangle{{0.f, 0.f, 0.f},
                   {20.f * std::cos(a0), 20.f * std::sin(a0), 0.3f * std::sin(3.f * a0)},
                   {20.f * std::cos(a1), 20.f * std::sin(a1), 0.3f * std::sin(3.f * a1)}},
          0);
  }
  Sampler s(11);
  const Geometry soup = slivers(s);
  for (const Triangle& t : soup.triangles) g.add(t, 1);
  for (int i = 0; i < 60; ++i) g.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.2f, 1.f)}, 2);
  return g;
}

TEST(BvhBuild, SameTreeWithOneAndTwoThreads) {
  const Geometry g = many_triangles(3);
  for (BvhConfig config : {BvhConfig{}, BvhConfig{32, 4, 1.f, 1.f, 512}}) {
    SCOPED_TRACE(config.bin_count);
    const BvhTree one = build_with_threads(g, config, 1);
    expect_same_tree(build_with_threads(g, config, 2), one);
    config.spatial_splits = true;
    expect_same_tree(build_with_threads(g, config, 2), build_with_threads(g, config, 1));
  }
}

// Enough triangles that the root and the first levels partition in parallel (several chunks of
// bvh_build::kPartitionChunk references, the last one partial), in an order that is not
// spatial (so chunks hold both sides).
Geometry many_more_triangles(std::uint64_t seed) { return random_soup(seed, 80000, 2.f, 300); }

TEST(BvhBuild, SameTreeWithOneTwoAndThreeThreadsOnALargeScene) {
  const Geometry g = many_more_triangles(4);
  BvhConfig config;
  config.leaf_block_size = 4;  // as the wide BVH builds it
  const BvhTree one = build_with_threads(g, config, 1);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    expect_same_tree(build_with_threads(g, config, threads), one);
  }
}

// References with random boxes, in random order.
std::vector<bvh_build::BuildRef> random_refs(std::uint32_t n, std::uint64_t seed) {
  Sampler s(seed);
  std::vector<bvh_build::BuildRef> refs(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec3 lo = s.in_box(Vec3(-10.f), Vec3(10.f));
    const Vec3 hi = lo + s.in_box(Vec3(0.f), Vec3(2.f));
    refs[i].set_box({lo, hi});
    refs[i].id = i;
    refs[i].splittable = 1;
  }
  return refs;
}

std::vector<std::uint32_t> sorted_ids(const bvh_build::BuildRef* refs, std::uint32_t n) {
  std::vector<std::uint32_t> ids(n);
  for (std::uint32_t i = 0; i < n; ++i) ids[i] = refs[i].id;
  std::sort(ids.begin(), ids.end());
  return ids;
}

void expect_same_box(const bvh_build::Box4& a, const bvh_build::Box4& b) {
  const Box3 x = a.box3(), y = b.box3();
  EXPECT_EQ(std::memcmp(&x, &y, sizeof x), 0);
}

TEST(BvhBuild, ParallelPartitionSplitsAsTheSequentialOne) {
  // Sizes below one chunk, exactly two chunks, and several with a partial last chunk.
  for (std::uint32_t n : {1000u, 2 * bvh_build::kPartitionChunk, 5 * bvh_build::kPartitionChunk + 123}) {
    const std::vector<bvh_build::BuildRef> input = random_refs(n, n);
    // Splits on every axis, including ones that send everything to one side.
    for (const std::array<int, 2>& axis_bin :
         {std::array{0, 8}, std::array{1, 3}, std::array{2, 15}, std::array{0, 16}, std::array{1, 0}}) {
      SCOPED_TRACE(testing::Message() << n << " refs, axis " << axis_bin[0] << ", bin " << axis_bin[1]);
      const bvh_build::SplitTest test{axis_bin[0], axis_bin[1], -20.f, 16.f / 44.f, 16, 24.f};
      std::vector<bvh_build::BuildRef> seq = input;
      const bvh_build::PartitionResult a = bvh_build::partition_sequential(seq.data(), n, test);
      std::vector<bvh_build::BuildRef> par;
      bvh_build::PartitionResult b;
      for (int threads : {1, 2, 3}) {
        tbb::global_control cap(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
        std::vector<bvh_build::BuildRef> refs = input;
        const bvh_build::PartitionResult p = bvh_build::partition_parallel(refs.data(), n, test);
        if (threads == 1) {
          par = refs;
          b = p;
        } else {
          // The same order whatever the thread count.
          ASSERT_EQ(p.mid, b.mid);
          ASSERT_EQ(std::memcmp(refs.data(), par.data(), n * sizeof(bvh_build::BuildRef)), 0) << threads;
        }
      }
      ASSERT_EQ(b.mid, a.mid);
      for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(test.goes_left(par[i]), i < b.mid) << "reference " << i;
      EXPECT_EQ(sorted_ids(par.data(), b.mid), sorted_ids(seq.data(), a.mid));
      EXPECT_EQ(sorted_ids(par.data() + b.mid, n - b.mid), sorted_ids(seq.data() + a.mid, n - a.mid));
      if (a.mid > 0) expect_same_box(b.left_centroids, a.left_centroids);
      if (a.mid < n) expect_same_box(b.right_centroids, a.right_centroids);
    }
  }
}

TEST(BvhBuild, SplitThresholdAgreesWithTheBins) {
  Sampler s(9);
  for (int trial = 0; trial < 200; ++trial) {
    // Every fourth node is centred on zero and split in the middle: the threshold falls among
    // the tiny floats, where one rounding step of `lo` spans billions of floats (a search float
    // by float took minutes there).
    const bool around_zero = trial % 4 == 3;
    const float half = s.log_uniform(1e1f, 1e4f);
    const float lo = around_zero ? -half : s.uni(-1e3f, 1e3f);
    const float hi = around_zero ? half : lo + s.log_uniform(1e-3f, 1e3f);
    const int bins = around_zero ? 2 * (1 + trial % 16) : 2 + trial % 31;
    const float scale = static_cast<float>(bins) / (hi - lo);
    const int bin = around_zero ? bins / 2 : 1 + trial % (bins - 1);
    const bvh_build::SplitTest test{0, bin, lo, scale, bins, hi};
    const float t = test.threshold();
    // Random points, the ends, and the floats next to the threshold.
    std::vector<float> points{lo, hi, t, std::nextafter(t, -INFINITY), std::nextafter(t, INFINITY), 0.f, -0.f};
    for (int i = 0; i < 200; ++i) points.push_back(s.uni(lo, hi));
    for (float c : points) {
      if (!(c >= lo && c <= hi)) continue;
      ASSERT_EQ(!(c >= t), test.bin_of(c) < test.bin) << "trial " << trial << " c " << c;
    }
  }
}

TEST(BvhBuild, LeafBlockCostRule) {
  BvhConfig block4;
  block4.leaf_block_size = 4;
  for (std::uint32_t n = 1; n <= 8; ++n) {
    BvhTree leaf;
    leaf.nodes.push_back(BvhNode{{0.f, 0.f, 0.f}, 0, {1.f, 1.f, 1.f}, n});
    EXPECT_DOUBLE_EQ(sah_cost(leaf, block4), n <= 4 ? 4.0 : 8.0) << n << " primitives";
    EXPECT_DOUBLE_EQ(sah_cost(leaf), double(n));
  }
  // A build that knows the rule does better by it than one that does not.
  Sampler s(5);
  const Geometry g = spheres_and_triangles(s);
  const double aware = sah_cost(build_bvh(g, block4), block4);
  const double unaware = sah_cost(build_bvh(g), block4);
  EXPECT_LT(aware, unaware);
}

// Every promise of a tree built with spatial splits.
void check_spatial_tree(const BvhTree& tree, const Geometry& g, const BvhConfig& config) {
  const std::uint32_t n = g.size();
  std::vector<int> referenced(n, 0);
  EXPECT_LE(tree.prim_ids.size(), n + std::size_t(std::floor(config.spatial_split_budget * n)));
  std::vector<std::uint32_t> stack{0u};
  std::size_t leaves = 0, slots = 0;
  while (!stack.empty()) {
    const BvhNode& node = tree.nodes[stack.back()];
    stack.pop_back();
    const Box3 box = box_of(node);
    if (node.is_leaf()) {
      ++leaves;
      ASSERT_LE(node.first + node.count, tree.prim_ids.size());
      slots += node.count;
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const std::uint32_t id = tree.prim_ids[i];
        ASSERT_LT(id, n);
        ++referenced[id];
        if (id < g.triangles.size()) {
          EXPECT_TRUE(triangle_overlaps_box(g.triangles[id], box)) << "triangle " << id << " misses its leaf";
        } else {
          EXPECT_TRUE(inside(g.bounds(id), box)) << "non-triangle " << id << " was clipped";
          EXPECT_EQ(referenced[id], 1) << "non-triangle " << id << " duplicated";
        }
      }
    } else {
      for (std::uint32_t c : {node.first, node.first + 1}) {
        EXPECT_TRUE(inside(box_of(tree.nodes[c]), box)) << "child box outside its parent";
        stack.push_back(c);
      }
    }
  }
  EXPECT_EQ(leaves, tree.leaf_count);
  EXPECT_EQ(slots, tree.prim_ids.size()) << "every reference slot belongs to one leaf";
  for (std::uint32_t i = 0; i < n; ++i) EXPECT_GE(referenced[i], 1) << "primitive " << i << " lost";
}

TEST(BvhBuild, SpatialSplitsLowerTheCostAndKeepEveryPromise) {
  const Geometry g = fan_and_slivers();
  BvhConfig spatial;
  spatial.spatial_splits = true;
  const BvhTree with = build_bvh(g, spatial);
  const BvhTree without = build_bvh(g);
  check_spatial_tree(with, g, spatial);
  EXPECT_GT(with.prim_ids.size(), g.size()) << "some triangles were split";
  EXPECT_LT(sah_cost(with), sah_cost(without));
  // A larger budget buys more splits where every wedge of the fan would need one.
  BvhConfig generous = spatial;
  generous.spatial_split_budget = 2.f;
  const BvhTree more = build_bvh(g, generous);
  check_spatial_tree(more, g, generous);
  EXPECT_LT(sah_cost(more), 0.95 * sah_cost(without));
}

TEST(BvhBuild, SpatialSplitsOnOtherScenes) {
  for (const NamedScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    Sampler s(scene.seed);
    const Geometry g = scene.make(s);
    BvhConfig spatial;
    spatial.spatial_splits = true;
    check_spatial_tree(build_bvh(g, spatial), g, spatial);
  }
}

TEST(BvhBuild, SpatialSplitQueriesEqualBruteForce) {
  const Geometry g = fan_and_slivers();
  BvhConfig spatial;
  spatial.spatial_splits = true;
  const Bvh bvh(g, spatial);
  ASSERT_GT(bvh.tree().prim_ids.size(), g.size());
  const BruteForce brute(g);
  Sampler s(21);
  compare(g, bvh, brute, random_rays(g, s, 4000), s);
}

}  // namespace
}  // namespace raylab
