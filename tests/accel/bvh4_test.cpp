// The 4-wide BVH's structure: collapse_to_bvh4 must keep every leaf and every box of the binary
// tree it collapses, in well-formed 128-byte nodes, on the random scenes of test_scenes.h and on
// degenerate ones; empty slots must be unreachable; Bvh4::info() must describe what it holds.
// (Its answers against brute force are checked in bvh_vs_brute_test.cpp.)

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "raylab/accel/brute_force.h"
#include "raylab/accel/bvh.h"
#include "raylab/accel/bvh4.h"
#include "raylab/simd/float4.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

static_assert(sizeof(Triangle) == 36, "Bvh4's memory formula assumes 36-byte triangle copies");

constexpr std::uint32_t kPlusInfBits = 0x7f800000u, kMinusInfBits = 0xff800000u;

enum class Slot { kEmpty, kLeaf, kInterior };

// A leaf has a count; an interior child has count 0, a real box and a child index other than 0
// (node 0 is the root, nobody's child); anything else is an empty slot.
Slot slot_kind(const Bvh4Node& n, int i) {
  if (n.count[i] != 0) return Slot::kLeaf;
  const bool real_box = n.lo[0][i] <= n.hi[0][i] && n.lo[1][i] <= n.hi[1][i] && n.lo[2][i] <= n.hi[2][i];
  return real_box && n.child[i] != 0 ? Slot::kInterior : Slot::kEmpty;
}

bool is_empty_sentinel(const Bvh4Node& n, int i) {
  for (int a = 0; a < 3; ++a) {
    if (std::bit_cast<std::uint32_t>(n.lo[a][i]) != kPlusInfBits) return false;
    if (std::bit_cast<std::uint32_t>(n.hi[a][i]) != kMinusInfBits) return false;
  }
  return true;
}

bool same_box_bits(const Bvh4Node& n, int i, const BvhNode& b) {
  for (int a = 0; a < 3; ++a) {
    if (std::bit_cast<std::uint32_t>(n.lo[a][i]) != std::bit_cast<std::uint32_t>(b.lo[a])) return false;
    if (std::bit_cast<std::uint32_t>(n.hi[a][i]) != std::bit_cast<std::uint32_t>(b.hi[a])) return false;
  }
  return true;
}

int used_slots(const Bvh4Node& n) {
  int used = 0;
  for (int i = 0; i < 4; ++i) used += slot_kind(n, i) != Slot::kEmpty ? 1 : 0;
  return used;
}

// A subtree's leaves as (first reference, number of references). Leaf ranges are disjoint, so
// two different subtrees of one tree never share this key: disjoint ones differ in the first
// reference, nested ones in the number.
using Key = std::pair<std::uint32_t, std::uint32_t>;
Key combine(Key a, Key b) { return {std::min(a.first, b.first), a.second + b.second}; }

// Every structural promise of collapse_to_bvh4(tree), with `wide` its result.
void check_collapse(const BvhTree& tree, const std::vector<Bvh4Node>& wide) {
  ASSERT_FALSE(wide.empty());
  if (tree.prim_ids.empty()) {  // empty geometry: one node, nothing in it
    ASSERT_EQ(wide.size(), 1u);
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(wide[0].count[i], 0u);
      EXPECT_TRUE(is_empty_sentinel(wide[0], i)) << "slot " << i;
    }
    return;
  }
  const BvhNode& broot = tree.nodes[0];
  if (broot.is_leaf()) {  // a single leaf: one node with the leaf in one slot
    ASSERT_EQ(wide.size(), 1u);
    EXPECT_EQ(used_slots(wide[0]), 1);
    for (int i = 0; i < 4; ++i) {
      if (slot_kind(wide[0], i) == Slot::kEmpty) {
        EXPECT_TRUE(is_empty_sentinel(wide[0], i)) << "slot " << i;
        continue;
      }
      EXPECT_EQ(slot_kind(wide[0], i), Slot::kLeaf);
      EXPECT_EQ(wide[0].child[i], broot.first);
      EXPECT_EQ(wide[0].count[i], broot.count);
      EXPECT_TRUE(same_box_bits(wide[0], i, broot));
    }
    return;
  }

  // The binary tree: key and parent of every node (children come after their parent).
  const auto bn = static_cast<std::uint32_t>(tree.nodes.size());
  std::vector<Key> bkey(bn);
  std::vector<std::uint32_t> bparent(bn, bn);
  std::map<Key, std::uint32_t> binary_of;
  for (std::uint32_t i = bn; i-- > 0;) {
    const BvhNode& b = tree.nodes[i];
    if (b.is_leaf()) {
      bkey[i] = {b.first, b.count};
    } else {
      ASSERT_GT(b.first, i);
      ASSERT_LT(b.first + 1, bn);
      bkey[i] = combine(bkey[b.first], bkey[b.first + 1]);
      bparent[b.first] = bparent[b.first + 1] = i;
    }
    ASSERT_TRUE(binary_of.emplace(bkey[i], i).second) << "binary node " << i << " shares its leaves with another";
  }

  // Wide slots: kinds, empty sentinels, child indices in range, each node reached once.
  const auto wn = static_cast<std::uint32_t>(wide.size());
  std::vector<int> reached(wn, 0);
  std::size_t leaf_slots = 0;
  for (std::uint32_t w = 0; w < wn && !::testing::Test::HasFailure(); ++w) {  // report the first bad node
    const Bvh4Node& n = wide[w];
    int used = 0, interior = 0;
    for (int i = 0; i < 4; ++i) {
      switch (slot_kind(n, i)) {
        case Slot::kEmpty:
          EXPECT_TRUE(is_empty_sentinel(n, i)) << "node " << w << " slot " << i << ": empty slot without +-inf box";
          break;
        case Slot::kLeaf:
          ++used, ++leaf_slots;
          EXPECT_LE(std::uint64_t(n.child[i]) + n.count[i], tree.prim_ids.size()) << "node " << w;
          break;
        case Slot::kInterior:
          ++used, ++interior;
          ASSERT_LT(n.child[i], wn) << "node " << w << " slot " << i;
          ASSERT_GT(n.child[i], w) << "children are laid out after their parent";
          ++reached[n.child[i]];
          break;
      }
    }
    EXPECT_GE(used, 2) << "node " << w << " (only a root holding a single leaf may have fewer)";
    // The collapse opens interior children until there are four slots, so a node with fewer
    // has nothing left to open.
    if (used < 4) {
      EXPECT_EQ(interior, 0) << "node " << w << " has " << used << " slots but could open one";
    }
  }
  if (::testing::Test::HasFailure()) return;
  EXPECT_EQ(reached[0], 0) << "the root is nobody's child";
  for (std::uint32_t w = 1; w < wn; ++w) EXPECT_EQ(reached[w], 1) << "node " << w << " reached that often";
  EXPECT_EQ(leaf_slots, tree.leaf_count);
  if (::testing::Test::HasFailure()) return;

  // Keys of the wide nodes, bottom up.
  std::vector<Key> wkey(wn, Key{std::numeric_limits<std::uint32_t>::max(), 0});
  for (std::uint32_t w = wn; w-- > 0;) {
    for (int i = 0; i < 4; ++i) {
      const Slot k = slot_kind(wide[w], i);
      if (k == Slot::kLeaf) wkey[w] = combine(wkey[w], {wide[w].child[i], wide[w].count[i]});
      if (k == Slot::kInterior) wkey[w] = combine(wkey[w], wkey[wide[w].child[i]]);
    }
  }

  // Each wide node came from a binary interior node (the root from the root); each of its slots
  // is a distinct binary node 1 to 3 levels below that one, with the same box bit for bit, and
  // together they hold exactly its leaves.
  std::vector<std::uint32_t> origin(wn, bn);
  origin[0] = 0;
  std::vector<int> as_slot(bn, 0);
  for (std::uint32_t w = 0; w < wn && !::testing::Test::HasFailure(); ++w) {
    const Bvh4Node& n = wide[w];
    ASSERT_LT(origin[w], bn) << "node " << w << " not reached from the root";
    EXPECT_EQ(wkey[w], bkey[origin[w]]) << "node " << w << " does not hold exactly its binary node's leaves";
    for (int i = 0; i < 4; ++i) {
      const Slot kind = slot_kind(n, i);
      if (kind == Slot::kEmpty) continue;
      const Key key = kind == Slot::kLeaf ? Key{n.child[i], n.count[i]} : wkey[n.child[i]];
      const auto it = binary_of.find(key);
      ASSERT_NE(it, binary_of.end()) << "node " << w << " slot " << i << " matches no binary node";
      const std::uint32_t b = it->second;
      const BvhNode& bnode = tree.nodes[b];
      EXPECT_EQ(++as_slot[b], 1) << "binary node " << b << " in two slots";
      EXPECT_TRUE(same_box_bits(n, i, bnode)) << "node " << w << " slot " << i << " box differs from binary node";
      EXPECT_EQ(bnode.is_leaf(), kind == Slot::kLeaf);
      if (kind == Slot::kLeaf) {
        EXPECT_EQ(bnode.first, n.child[i]);
        EXPECT_EQ(bnode.count, n.count[i]);
      } else {
        origin[n.child[i]] = b;
        const Bvh4Node& c = wide[n.child[i]];
        for (int j = 0; j < 4; ++j) {
          if (slot_kind(c, j) == Slot::kEmpty) continue;
          for (int a = 0; a < 3; ++a) {
            EXPECT_LE(n.lo[a][i], c.lo[a][j]) << "child box outside its slot, node " << w << " slot " << i;
            EXPECT_GE(n.hi[a][i], c.hi[a][j]) << "child box outside its slot, node " << w << " slot " << i;
          }
        }
      }
      int levels = 0;
      std::uint32_t up = b;
      while (up != origin[w] && up != 0) up = bparent[up], ++levels;
      EXPECT_EQ(up, origin[w]) << "node " << w << " slot " << i << " is not below the node it came from";
      EXPECT_TRUE(levels >= 1 && levels <= 3) << "node " << w << " slot " << i << " is " << levels << " levels down";
    }
  }
  // Every binary leaf is in exactly one leaf slot.
  for (std::uint32_t b = 0; b < bn; ++b) {
    if (tree.nodes[b].is_leaf()) {
      EXPECT_EQ(as_slot[b], 1) << "binary leaf " << b;
    }
  }
}

// The box test of Bvh4's traversal (bvh4.cpp), computed the same way with the same operations:
// bit i of the result is set when the ray enters slot i.
int entered_mask(const Bvh4Node& node, const Ray& ray) {
  using simd::Float4;
  constexpr float kSlabWiden = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
  const float o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const float d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  Float4 t_near = Float4::broadcast(ray.tmin), t_far = Float4::broadcast(INFINITY);
  for (int a = 0; a < 3; ++a) {
    const bool negative = std::signbit(d[a]);
    const Float4 origin = Float4::broadcast(o[a]), inv = Float4::broadcast(1.f / d[a]);
    t_near = max((Float4::load(negative ? node.hi[a] : node.lo[a]) - origin) * inv, t_near);
    t_far = min((Float4::load(negative ? node.lo[a] : node.hi[a]) - origin) * inv, t_far);
  }
  return less_equal_mask(t_near, min(t_far * Float4::broadcast(kSlabWiden), Float4::broadcast(ray.tmax)));
}

// The scene's random rays plus awkward ones: zero, denormal and huge direction components of
// either sign, origins on the scene box's planes, tmin of -inf, short tmax.
std::vector<Ray> awkward_rays(const Geometry& g, Sampler& s, int count) {
  std::vector<Ray> rays = g.size() > 0 ? random_rays(g, s, count) : std::vector<Ray>{};
  const Box3 box = g.size() > 0 ? g.bounds() : Box3{Vec3(-1.f), Vec3(1.f)};
  const float comps[] = {0.f, -0.f, 1e-45f, -1e-45f, 1.f, -1.f, 1e30f, -1e30f, 0.3f, -0.7f};
  for (int i = 0; i < count / 4; ++i) {
    Ray r;
    r.origin = s.in_box(box.lo - box.extent(), box.hi + box.extent());
    const int axis = static_cast<int>(s.rng.next_u32() % 3);
    r.origin[axis] = s.rng.next_float() < 0.5f ? box.lo[axis] : box.hi[axis];
    for (int a = 0; a < 3; ++a) r.direction[a] = comps[s.rng.next_u32() % std::size(comps)];
    if (i % 3 == 0) r.tmin = -kInf;
    if (i % 5 == 0) r.tmax = 1e-3f;
    rays.push_back(r);
  }
  return rays;
}

// Empty slots are entered by no ray; used ones (a control on entered_mask) by a ray from inside.
void check_empty_slots_unreachable(const std::vector<Bvh4Node>& wide, const std::vector<Ray>& rays) {
  int failures = 0;
  for (std::size_t w = 0; w < wide.size(); ++w) {
    const Bvh4Node& n = wide[w];
    int empty = 0;
    for (int i = 0; i < 4; ++i) {
      if (slot_kind(n, i) == Slot::kEmpty) {
        empty |= 1 << i;
        continue;
      }
      Ray inside;
      inside.origin = {0.5f * (n.lo[0][i] + n.hi[0][i]), 0.5f * (n.lo[1][i] + n.hi[1][i]),
                       0.5f * (n.lo[2][i] + n.hi[2][i])};
      inside.direction = {0.3f, -0.5f, 0.8f};
      EXPECT_TRUE(entered_mask(n, inside) & (1 << i)) << "a ray from inside misses node " << w << " slot " << i;
    }
    if (empty == 0) continue;
    for (const Ray& r : rays) {
      if ((entered_mask(n, r) & empty) != 0 && ++failures <= 5) {
        ADD_FAILURE() << "a ray enters an empty slot of node " << w << ": o=(" << r.origin.x << ", " << r.origin.y
                      << ", " << r.origin.z << ") d=(" << r.direction.x << ", " << r.direction.y << ", "
                      << r.direction.z << ")";
      }
    }
  }
  EXPECT_EQ(failures, 0);
}

// Bvh4 holds exactly collapse_to_bvh4(build_bvh(g, config)) and reports it; its traversal visits
// each node at most once (an entered empty slot would revisit node 0).
void check_accelerator(const Geometry& g, const BvhConfig& config, const BvhTree& tree,
                       const std::vector<Bvh4Node>& wide, const std::vector<Ray>& rays) {
  const Bvh4 accel(g, config);
  ASSERT_EQ(accel.nodes().size(), wide.size());
  EXPECT_EQ(std::memcmp(accel.nodes().data(), wide.data(), wide.size() * sizeof(Bvh4Node)), 0);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(accel.nodes().data()) % 64, 0u) << "nodes not cache-line aligned";
  const AccelInfo info = accel.info();
  std::size_t leaf_slots = 0, deepest = 0;
  std::vector<std::size_t> depth(wide.size(), 0);
  for (std::size_t w = 0; w < wide.size(); ++w) {
    for (int i = 0; i < 4; ++i) {
      const Slot k = slot_kind(wide[w], i);
      if (k == Slot::kLeaf) ++leaf_slots;
      if (k == Slot::kInterior) depth[wide[w].child[i]] = depth[w] + 1;  // children follow parents
    }
    deepest = std::max(deepest, depth[w]);
  }
  EXPECT_EQ(info.name, "bvh");
  EXPECT_EQ(info.node_count, wide.size());
  EXPECT_EQ(info.leaf_count, leaf_slots);
  EXPECT_EQ(info.leaf_count, tree.leaf_count);
  EXPECT_EQ(info.primitive_count, g.size());
  EXPECT_EQ(info.primitive_count, tree.prim_ids.size());
  EXPECT_EQ(info.memory_bytes, info.node_count * 128 + info.primitive_count * 4 + info.primitive_count * 36);
  // Depth counted in wide nodes: the deepest node (which holds only leaves), root = 0.
  EXPECT_EQ(std::size_t(info.max_depth), deepest);
  EXPECT_GE(info.build_seconds, 0.0);
  int failures = 0;
  for (const Ray& ray : rays) {
    Ray r = ray;
    Hit h;
    TraversalStats si, so;
    accel.intersect_counted(r, h, si);
    accel.occluded_counted(ray, so);
    if ((si.nodes_visited > wide.size() || so.nodes_visited > wide.size() || si.prim_tests > g.size()) &&
        ++failures <= 5) {
      ADD_FAILURE() << "visited " << si.nodes_visited << " / " << so.nodes_visited << " of " << wide.size()
                    << " nodes, " << si.prim_tests << " tests";
    }
  }
  EXPECT_EQ(failures, 0);
}

void check_all(const Geometry& g, const BvhConfig& config, std::uint64_t seed, int ray_count) {
  const BvhTree tree = build_bvh(g, config);
  const std::vector<Bvh4Node> wide = collapse_to_bvh4(tree);
  check_collapse(tree, wide);
  Sampler s(seed);
  const std::vector<Ray> rays = awkward_rays(g, s, ray_count);
  check_empty_slots_unreachable(wide, rays);
  // A broken tree can send the traversal round in circles: only a sound one is traversed.
  if (::testing::Test::HasFailure()) return;
  check_accelerator(g, config, tree, wide, rays);
}

TEST(Bvh4Collapse, RandomScenes) {
  for (const NamedScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    Sampler s(scene.seed);
    check_all(scene.make(s), BvhConfig{}, scene.seed + 100, 2000);
  }
}

TEST(Bvh4Collapse, OtherBuildConfigs) {
  for (const BvhConfig config :
       {BvhConfig{2, 1, 1.f, 1.f, 4096}, BvhConfig{64, 32, 0.5f, 2.f, 4096}, BvhConfig{16, 4, 1.f, 1.f, 64}}) {
    SCOPED_TRACE("max_leaf_size " + std::to_string(config.max_leaf_size));
    Sampler s(7);
    check_all(every_shape_kind(s), config, 107, 1000);
  }
}

// Small and degenerate inputs, under the default build and under one that splits down to single
// primitives; their queries are also compared with brute force.
Geometry degenerate(int which) {
  Geometry g;
  const Triangle tri{{-1.f, -1.f, 3.f}, {1.f, -1.f, 3.f}, {0.f, 1.f, 3.f}};
  switch (which) {
    case 0:
      break;  // empty
    case 1:
      g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 0);
      break;
    case 2:
      g.add(Sphere{{-3.f, 0.f, 5.f}, 1.f}, 0);
      g.add(tri, 1);
      break;
    case 3:
      g.add(tri, 0);
      g.add(Sphere{{3.f, 0.f, 4.f}, 1.f}, 1);
      g.add(Quad{{-4.f, -4.f, 8.f}, {8.f, 0.f, 0.f}, {0.f, 8.f, 0.f}}, 2);
      g.add(Disk{{0.f, 3.f, 2.f}, {0.f, 0.f, 1.f}, 1.f}, 3);
      g.add(Cylinder{{-3.f, -3.f, 2.f}, 0.5f, {-3.f, -3.f, 4.f}, 0.5f}, 4);
      break;
    case 4:
      for (int i = 0; i < 40; ++i) g.add(tri, 0);  // all coincident
      break;
    default:
      for (int i = 0; i < 33; ++i) g.add(Quad{{-1.f, -1.f, 6.f}, {2.f, 0.f, 0.f}, {0.f, 2.f, 0.f}}, 0);  // flat too
      break;
  }
  return g;
}

TEST(Bvh4Collapse, DegenerateGeometry) {
  const char* names[] = {"empty",
                         "one sphere",
                         "two primitives",
                         "five primitives",
                         "40 coincident triangles",
                         "33 coincident flat quads"};
  for (int which = 0; which < 6; ++which) {
    for (const BvhConfig config : {BvhConfig{}, BvhConfig{16, 1, 1.f, 1.f, 4096}, BvhConfig{2, 2, 1.f, 1.f, 4}}) {
      SCOPED_TRACE(std::string(names[which]) + ", max_leaf_size " + std::to_string(config.max_leaf_size));
      const Geometry g = degenerate(which);
      check_all(g, config, 200 + which, 400);
      // Every ray from near the origin towards the scene: the same answer as brute force.
      const Bvh4 accel(g, config);
      const BruteForce brute(g);
      Sampler s(300 + which);
      for (int i = 0; i < 300; ++i) {
        const Vec3 o = s.in_box(Vec3(-0.5f), Vec3(0.5f));
        Ray rb{o, 0.f, s.in_box(Vec3(-4.f, -4.f, 1.f), Vec3(4.f, 4.f, 8.f)) - o}, rv = rb;
        Hit hb, hv;
        TraversalStats st;
        const bool fb = brute.intersect(rb, hb), fv = accel.intersect_counted(rv, hv, st);
        ASSERT_EQ(fv, fb) << "ray " << i;
        EXPECT_EQ(accel.occluded(Ray{rb.origin, 0.f, rb.direction}), fb) << "ray " << i;
        if (fb) {
          EXPECT_EQ(hv.t, hb.t) << "ray " << i;  // coincident primitives tie exactly
        }
        if (accel.nodes().size() == 1) {
          EXPECT_LE(st.nodes_visited, 1u) << "ray " << i;
        }
      }
    }
  }
}

}  // namespace
}  // namespace raylab
