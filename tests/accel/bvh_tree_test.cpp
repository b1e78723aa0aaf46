// The binary BVH's tree (BvhTree from build_bvh): every structural promise, on the scenes of
// test_scenes.h and with other build configs; the SAH cost on hand-built trees. Queries of both
// BVHs against brute force are in bvh_vs_brute_test.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "raylab/accel/bvh.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

// Every structural promise of BvhTree, checked by walking it from the root.
void check_tree(const BvhTree& tree, const Geometry& g, const BvhConfig& config) {
  const std::uint32_t n = g.size();
  ASSERT_EQ(tree.prim_ids.size(), n);
  std::vector<int> seen(n, 0), slot_used(n, 0), node_seen(tree.nodes.size(), 0);
  for (std::uint32_t id : tree.prim_ids) {
    ASSERT_LT(id, n);
    ++seen[id];
  }
  for (std::uint32_t i = 0; i < n; ++i) EXPECT_EQ(seen[i], 1) << "prim " << i;
  auto box_of = [](const BvhNode& node) {
    return Box3{{node.lo[0], node.lo[1], node.lo[2]}, {node.hi[0], node.hi[1], node.hi[2]}};
  };
  auto inside = [](const Box3& in, const Box3& out) {
    return out.lo.x <= in.lo.x && out.lo.y <= in.lo.y && out.lo.z <= in.lo.z && in.hi.x <= out.hi.x &&
           in.hi.y <= out.hi.y && in.hi.z <= out.hi.z;
  };
  std::size_t leaves = 0;
  int max_depth = 0;
  std::vector<std::pair<std::uint32_t, int>> stack{{0u, 0}};
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    ASSERT_LT(index, tree.nodes.size());
    ASSERT_EQ(++node_seen[index], 1) << "node reached twice";
    const BvhNode& node = tree.nodes[index];
    const Box3 box = box_of(node);
    if (node.is_leaf()) {
      ++leaves;
      max_depth = std::max(max_depth, depth);
      EXPECT_LE(node.count, static_cast<std::uint32_t>(std::max(1, config.max_leaf_size)));
      ASSERT_LE(node.first + node.count, n);
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        ++slot_used[i];
        EXPECT_TRUE(inside(g.bounds(tree.prim_ids[i]), box)) << "prim outside its leaf";
      }
    } else {
      ASSERT_GT(node.first, index) << "children are laid out after their parent";
      ASSERT_LT(node.first + 1, tree.nodes.size());
      for (std::uint32_t c : {node.first, node.first + 1}) {
        EXPECT_TRUE(inside(box_of(tree.nodes[c]), box)) << "child box outside its parent";
        stack.emplace_back(c, depth + 1);
      }
    }
  }
  for (std::uint32_t i = 0; i < n; ++i) EXPECT_EQ(slot_used[i], 1) << "reference slot " << i;
  EXPECT_EQ(std::count(node_seen.begin(), node_seen.end(), 1), std::ptrdiff_t(tree.nodes.size())) << "orphan nodes";
  EXPECT_EQ(leaves, tree.leaf_count);
  EXPECT_EQ(max_depth, tree.max_depth);
  EXPECT_EQ(leaves * 2 - 1, tree.nodes.size()) << "a binary tree";
  // A SAH build must beat the one-leaf tree (cost n) by far on these scattered scenes.
  EXPECT_LT(sah_cost(tree, config), 0.2 * n);
}

// The Bvh accelerator keeps exactly the tree build_bvh gives, so the checks below (made on
// build_bvh directly) are checks of the binary accelerator's tree too.
void expect_same_tree(const BvhTree& a, const BvhTree& b) {
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)), 0);
  EXPECT_EQ(a.prim_ids, b.prim_ids);
  EXPECT_EQ(a.max_depth, b.max_depth);
  EXPECT_EQ(a.leaf_count, b.leaf_count);
}

TEST(BvhTree, RandomScenes) {
  for (const NamedScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    Sampler s(scene.seed);
    const Geometry g = scene.make(s);
    const BvhTree tree = build_bvh(g, BvhConfig{});
    check_tree(tree, g, BvhConfig{});
    expect_same_tree(Bvh(g).tree(), tree);
  }
}

TEST(BvhTree, OtherBuildConfigs) {
  for (const BvhConfig config :
       {BvhConfig{2, 1, 1.f, 1.f, 4096}, BvhConfig{64, 32, 0.5f, 2.f, 4096}, BvhConfig{16, 4, 1.f, 1.f, 64}}) {
    Sampler s(7);
    const Geometry g = every_shape_kind(s);
    const BvhTree tree = build_bvh(g, config);
    check_tree(tree, g, config);
    expect_same_tree(Bvh(g, config).tree(), tree);
  }
}

TEST(BvhTree, SinglePrimitive) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 3);
  const BvhTree tree = build_bvh(g);
  ASSERT_EQ(tree.nodes.size(), 1u);
  EXPECT_EQ(tree.leaf_count, 1u);
  EXPECT_EQ(tree.nodes[0].count, 1u);
  EXPECT_EQ(Bvh(g).tree().nodes.size(), 1u);
}

TEST(BvhSah, CostOfHandBuiltTrees) {
  BvhTree one_leaf;
  one_leaf.nodes.push_back(BvhNode{{0.f, 0.f, 0.f}, 0, {1.f, 1.f, 1.f}, 10});
  EXPECT_DOUBLE_EQ(sah_cost(one_leaf), 10.0);  // 10 primitive tests, always
  BvhTree split;
  split.nodes = {BvhNode{{0.f, 0.f, 0.f}, 1, {2.f, 1.f, 1.f}, 0},   // root: area 10
                 BvhNode{{0.f, 0.f, 0.f}, 0, {1.f, 1.f, 1.f}, 4},   // area 6, 4 prims
                 BvhNode{{1.f, 0.f, 0.f}, 4, {2.f, 1.f, 1.f}, 6}};  // area 6, 6 prims
  EXPECT_DOUBLE_EQ(sah_cost(split), 1.0 + 0.6 * 4 + 0.6 * 6);
  EXPECT_DOUBLE_EQ(sah_cost(split, BvhConfig{16, 8, 2.f, 0.5f, 4096}), 2.0 + 0.5 * (0.6 * 4 + 0.6 * 6));
}

}  // namespace
}  // namespace raylab
