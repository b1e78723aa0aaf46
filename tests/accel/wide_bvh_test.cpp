// The wide BVH at every width (4, 8, 16). Its structure: collapse_to_wide keeps every leaf and
// every box of the binary tree, each wide node takes binary nodes 1 to W - 1 levels below the
// one it came from, empty slots are +-inf boxes no ray enters, leaves pack their triangles four
// to a block with unused lanes marked and list the other kinds by id (spheres only, leaves
// holding both kinds, leaves listing many), every primitive is referenced exactly once, the
// "others" flag is set exactly when a leaf lists ids, and info() describes what it holds. Its
// answers: bit for bit those of the binary Bvh and of BruteForce (t, prim_id, u, v, ray.tmax),
// any-hit equal to brute force, counted equal to uncounted, packets of 1 to 40 rays equal to
// single rays; empty, single and coincident geometry; rays with NaN, infinite or zero
// components neither crash nor hit.

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "raylab/accel/brute_force.h"
#include "raylab/accel/bvh.h"
#include "raylab/accel/wide_bvh.h"
#include "raylab/core/isa.h"
#include "raylab/simd/wide_float.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr std::uint32_t kPlusInfBits = 0x7f800000u, kMinusInfBits = 0xff800000u;
constexpr std::uint32_t kNone = TriangleBlock4::kNoPrimitive;

std::uint32_t bits(float x) { return std::bit_cast<std::uint32_t>(x); }

// ---------------------------------------------------------------------------------------------
// Structure

enum class Slot { kEmpty, kLeaf, kInterior };

// A leaf has a block count; an interior child has count 0, a real box and a child index other
// than 0 (node 0 is the root, nobody's child); anything else is an empty slot.
template <int W>
Slot slot_kind(const WideBvhNode<W>& n, int i) {
  if (n.count[i] != 0) return Slot::kLeaf;
  const bool real_box = n.lo[0][i] <= n.hi[0][i] && n.lo[1][i] <= n.hi[1][i] && n.lo[2][i] <= n.hi[2][i];
  return real_box && n.child[i] != 0 ? Slot::kInterior : Slot::kEmpty;
}

template <int W>
bool is_empty_sentinel(const WideBvhNode<W>& n, int i) {
  for (int a = 0; a < 3; ++a) {
    if (bits(n.lo[a][i]) != kPlusInfBits || bits(n.hi[a][i]) != kMinusInfBits) return false;
  }
  return n.count[i] == 0;
}

template <int W>
bool same_box_bits(const WideBvhNode<W>& n, int i, const BvhNode& b) {
  for (int a = 0; a < 3; ++a) {
    if (bits(n.lo[a][i]) != bits(b.lo[a]) || bits(n.hi[a][i]) != bits(b.hi[a])) return false;
  }
  return true;
}

template <int W>
bool box_contains(const WideBvhNode<W>& n, int i, const Box3& box) {
  for (int a = 0; a < 3; ++a) {
    if (!(n.lo[a][i] <= box.lo[a] && box.hi[a] <= n.hi[a][i])) return false;
  }
  return true;
}

// Which leaf owns each block and each entry of `others`, and where the entries of the leaves
// holding both triangles and other kinds end (they come first in `others`).
struct LeafOwners {
  std::vector<int> block, other;
  std::size_t mixed_end = 0, pure_start = std::numeric_limits<std::size_t>::max();
};

// Marks entries [first, first + count) of `owner` as `leaf`'s; false (with a failure) if out of range.
bool claim(std::vector<int>& owner, std::size_t first, std::size_t count, int leaf, const char* what) {
  EXPECT_LE(first + count, owner.size()) << what << " out of range";
  if (first + count > owner.size()) return false;
  for (std::size_t k = first; k < first + count; ++k) {
    EXPECT_EQ(owner[k], -1) << what << " " << k << " belongs to two leaves";
    owner[k] = leaf;
  }
  return true;
}

// The ids of a leaf slot, its blocks' lanes then its listed ids, and whether they are well
// formed: used lanes first, only the last block partly filled, unused lanes kNoPrimitive with all
// vertices zero, lanes holding only triangles, bit for bit; kLeafHasOthers set exactly when the
// leaf lists ids, which are other kinds or, in a leaf holding both whose blocks are all full, the
// triangles beyond them; the encoding of WideBvhLeaves.
template <int W>
std::vector<std::uint32_t> leaf_ids(const Geometry& g, const WideBvhTree<W>& wide, const WideBvhNode<W>& n, int i,
                                    LeafOwners& owners, int owner) {
  std::vector<std::uint32_t> ids;
  const WideBvhLeaves& leaves = wide.leaves;
  const std::uint32_t count = WideBvhLeaves::block_count(n.count[i]);
  const std::uint32_t first = n.child[i];
  const bool flagged = (n.count[i] & WideBvhNode<W>::kLeafHasOthers) != 0;
  const auto triangle_count = static_cast<std::uint32_t>(g.triangles.size());
  EXPECT_EQ(leaves.triangle_count, triangle_count);
  if (!flagged) {
    EXPECT_GE(count, 1u) << "a leaf with nothing in it";
  } else {
    EXPECT_LE(count, WideBvhLeaves::kMaxMixedBlocks);
  }
  if (count != 0 && !claim(owners.block, first, count, owner, "block")) return ids;
  for (std::uint32_t b = first; b < first + count; ++b) {
    const TriangleBlock4& block = leaves.blocks[b];
    bool seen_unused = false;
    for (int lane = 0; lane < 4; ++lane) {
      const std::uint32_t id = block.id[lane];
      if (id == kNone) {
        seen_unused = true;
        EXPECT_EQ(b, first + count - 1) << "a block other than a leaf's last is not full";
        for (int k = 0; k < 3; ++k)
          for (int a = 0; a < 3; ++a)
            EXPECT_EQ(bits(block.p[k][a][lane]), bits(block.p[k][a][0])) << "unused lane not repeating lane 0";
        continue;
      }
      EXPECT_FALSE(seen_unused) << "block " << b << ": a used lane after an unused one";
      EXPECT_LT(id, triangle_count) << "block " << b << " lane " << lane << ": not a triangle";
      if (id >= triangle_count) continue;
      ids.push_back(id);
      const Triangle t = block.triangle(lane);
      EXPECT_EQ(std::memcmp(&t, &g.triangles[id], sizeof(Triangle)), 0) << "block " << b << " lane " << lane;
    }
  }
  EXPECT_EQ(count, (ids.size() + 3) / 4) << "a leaf with a wasted block";
  const std::span<const std::uint32_t> listed = leaves.others_of(first, n.count[i]);
  EXPECT_EQ(flagged, !listed.empty()) << "kLeafHasOthers must be set exactly when the leaf lists ids";
  if (!flagged) return ids;
  const auto start = static_cast<std::size_t>(listed.data() - leaves.others.data());
  if (count != 0) {  // a header, then the ids; these leaves first
    EXPECT_GE(start, 1u);
    if (!claim(owners.other, start - 1, listed.size() + 1, owner, "header or id")) return ids;
    owners.mixed_end = std::max(owners.mixed_end, start + listed.size());
  } else {
    if (!claim(owners.other, start, listed.size(), owner, "id")) return ids;
    owners.pure_start = std::min(owners.pure_start, start);
  }
  for (const std::uint32_t id : listed) {
    EXPECT_LT(id, g.size());
    if (id < triangle_count) {
      EXPECT_EQ(ids.size(), WideBvhLeaves::kMaxMixedBlocks * 4) << "a triangle listed while the blocks have room";
    }
  }
  ids.insert(ids.end(), listed.begin(), listed.end());
  return ids;
}

// The order in which a wide leaf holds a binary leaf's references: the triangles in the blocks
// (at most kMaxMixedBlocks blocks' worth when the leaf holds other kinds), then the rest.
std::vector<std::uint32_t> wide_leaf_order(const Geometry& g, const BvhTree& tree, const BvhNode& b) {
  const auto triangle_count = static_cast<std::uint32_t>(g.triangles.size());
  const auto refs = std::span(tree.prim_ids).subspan(b.first, b.count);
  const bool others = std::any_of(refs.begin(), refs.end(), [&](std::uint32_t id) { return id >= triangle_count; });
  const std::size_t room = others ? WideBvhLeaves::kMaxMixedBlocks * 4 : refs.size();
  std::vector<std::uint32_t> blocks, listed;
  for (const std::uint32_t id : refs) (id < triangle_count && blocks.size() < room ? blocks : listed).push_back(id);
  // The listed ids put the spheres first, then the cylinders, each part in leaf order.
  const auto first_cylinder = triangle_count + static_cast<std::uint32_t>(g.spheres.size());
  const auto spheres_end = std::stable_partition(
      listed.begin(), listed.end(), [&](std::uint32_t id) { return id - triangle_count < g.spheres.size(); });
  std::stable_partition(spheres_end, listed.end(),
                        [&](std::uint32_t id) { return id - first_cylinder < g.cylinders.size(); });
  blocks.insert(blocks.end(), listed.begin(), listed.end());
  return blocks;
}

// A subtree as (its first binary leaf, number of binary leaves); binary leaves are numbered in
// index order, so two different binary subtrees never share a key.
using Key = std::pair<std::uint32_t, std::uint32_t>;
Key combine(Key a, Key b) { return {std::min(a.first, b.first), a.second + b.second}; }

// The layout is depth first: a node, then the subtrees of its interior slots in slot order;
// leaves' blocks follow one another in the same order (leaf by leaf, slot by slot), whatever
// the number of tasks that collapsed the tree.
template <int W>
void check_depth_first_layout(const WideBvhTree<W>& wide) {
  std::uint32_t next_node = 0, next_block = 0;
  auto visit = [&](auto&& self, std::uint32_t w) -> void {
    EXPECT_EQ(w, next_node) << "node " << w << " is not where a depth-first layout puts it";
    ++next_node;
    const WideBvhNode<W>& n = wide.nodes[w];
    for (int i = 0; i < W && !::testing::Test::HasFailure(); ++i) {
      const Slot kind = slot_kind(n, i);
      if (kind == Slot::kInterior) self(self, n.child[i]);
      if (kind != Slot::kLeaf) continue;
      const std::uint32_t blocks = WideBvhLeaves::block_count(n.count[i]);
      if (blocks == 0) continue;
      EXPECT_EQ(n.child[i], next_block) << "node " << w << " slot " << i << ": blocks out of depth-first order";
      next_block += blocks;
    }
  };
  visit(visit, 0);
  EXPECT_EQ(next_node, wide.nodes.size());
  EXPECT_EQ(next_block, wide.leaves.blocks.size());
}

// Every structural promise of collapse_to_wide<W>(tree, g), with `wide` its result, and of the
// traversal's depth and info.
// With spatial splits a triangle may sit in several leaves, clipped: then only the promises that
// survive clipping are checked (each reference once per leaf, at least once overall), not the box
// of the whole primitive nor the leaf-by-leaf correspondence.
template <int W>
void check_collapse(const Geometry& g, const BvhTree& tree, const WideBvhTree<W>& wide, bool spatial = false) {
  ASSERT_FALSE(wide.nodes.empty());
  const auto wn = static_cast<std::uint32_t>(wide.nodes.size());
  if (tree.prim_ids.empty()) {  // empty geometry: one node, nothing in it
    ASSERT_EQ(wn, 1u);
    for (int i = 0; i < W; ++i) EXPECT_TRUE(is_empty_sentinel(wide.nodes[0], i)) << "slot " << i;
    EXPECT_TRUE(wide.leaves.blocks.empty());
    EXPECT_TRUE(wide.leaves.others.empty());
    EXPECT_TRUE(wide.leaves.empty());
    EXPECT_EQ(wide.leaf_count, 0u);
    return;
  }

  // The binary tree: leaf numbers, keys and parents (children come after their parent).
  const auto bn = static_cast<std::uint32_t>(tree.nodes.size());
  std::vector<Key> bkey(bn);
  std::vector<std::uint32_t> bparent(bn, bn), leaf_number(bn, bn);
  std::map<Key, std::uint32_t> binary_of;
  std::map<std::uint32_t, std::uint32_t> leaf_of_first_id;  // first id in wide leaf order -> binary leaf
  std::uint32_t leaves = 0;
  for (std::uint32_t i = 0; i < bn; ++i) {
    if (tree.nodes[i].is_leaf()) {
      leaf_number[i] = leaves++;
      leaf_of_first_id[wide_leaf_order(g, tree, tree.nodes[i])[0]] = i;
    }
  }
  for (std::uint32_t i = bn; i-- > 0;) {
    const BvhNode& b = tree.nodes[i];
    if (b.is_leaf()) {
      bkey[i] = {leaf_number[i], 1};
    } else {
      ASSERT_GT(b.first, i);
      ASSERT_LT(b.first + 1, bn);
      bkey[i] = combine(bkey[b.first], bkey[b.first + 1]);
      bparent[b.first] = bparent[b.first + 1] = i;
    }
    binary_of.emplace(bkey[i], i);
  }

  // Wide slots: kinds, sentinels, indices, each node reached once, leaves well formed.
  std::vector<int> reached(wn, 0);
  LeafOwners owners{std::vector<int>(wide.leaves.blocks.size(), -1), std::vector<int>(wide.leaves.others.size(), -1)};
  std::vector<int> ref_count(g.size(), 0);
  std::vector<std::vector<std::uint32_t>> slot_ids(std::size_t(wn) * W);
  std::size_t leaf_slots = 0;
  for (std::uint32_t w = 0; w < wn && !::testing::Test::HasFailure(); ++w) {  // report the first bad node
    const WideBvhNode<W>& n = wide.nodes[w];
    int used = 0, interior = 0;
    for (int i = 0; i < W; ++i) {
      switch (slot_kind(n, i)) {
        case Slot::kEmpty:
          EXPECT_TRUE(is_empty_sentinel(n, i)) << "node " << w << " slot " << i << ": empty slot without +-inf box";
          break;
        case Slot::kLeaf: {
          ++used, ++leaf_slots;
          slot_ids[std::size_t(w) * W + std::size_t(i)] = leaf_ids(g, wide, n, i, owners, int(w * W + i));
          std::vector<std::uint32_t> sorted = slot_ids[std::size_t(w) * W + std::size_t(i)];
          std::sort(sorted.begin(), sorted.end());
          EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a leaf lists a primitive twice";
          for (std::uint32_t id : sorted) {
            ++ref_count[id];
            if (!spatial) {
              EXPECT_TRUE(box_contains(n, i, g.bounds(id))) << "node " << w << " slot " << i << " misses prim " << id;
            }
          }
          break;
        }
        case Slot::kInterior:
          ++used, ++interior;
          ASSERT_LT(n.child[i], wn) << "node " << w << " slot " << i;
          ASSERT_GT(n.child[i], w) << "children are laid out after their parent";
          ++reached[n.child[i]];
          break;
      }
    }
    if (wn > 1 || !tree.nodes[0].is_leaf()) {
      EXPECT_GE(used, 2) << "node " << w << " (only a root holding a single leaf may have fewer)";
    }
    // The collapse opens interior children until there are W slots, so a node with fewer has
    // nothing left to open.
    if (used < W) {
      EXPECT_EQ(interior, 0) << "node " << w << " has " << used << " slots but could open one";
    }
  }
  if (::testing::Test::HasFailure()) return;
  EXPECT_EQ(reached[0], 0) << "the root is nobody's child";
  for (std::uint32_t w = 1; w < wn; ++w) EXPECT_EQ(reached[w], 1) << "node " << w << " reached that often";
  if (::testing::Test::HasFailure()) return;
  check_depth_first_layout<W>(wide);
  EXPECT_EQ(leaf_slots, tree.leaf_count);
  EXPECT_EQ(wide.leaf_count, tree.leaf_count);
  for (std::size_t b = 0; b < owners.block.size(); ++b) EXPECT_NE(owners.block[b], -1) << "block " << b << " unused";
  for (std::size_t k = 0; k < owners.other.size(); ++k) EXPECT_NE(owners.other[k], -1) << "others " << k << " unused";
  EXPECT_LE(owners.mixed_end, owners.pure_start) << "leaves holding both kinds list their ids first";
  EXPECT_FALSE(wide.leaves.empty());
  // Without spatial splits, every primitive built over is referenced exactly once.
  std::vector<int> expected_refs(g.size(), 0);
  for (std::uint32_t id : tree.prim_ids) ++expected_refs[id];
  for (std::uint32_t id = 0; id < g.size(); ++id) {
    EXPECT_EQ(ref_count[id], expected_refs[id]) << "primitive " << id;
    if (!spatial) {
      EXPECT_LE(ref_count[id], 1) << "primitive " << id;
    } else {
      EXPECT_GE(ref_count[id], 1) << "primitive " << id;
    }
  }
  if (::testing::Test::HasFailure() || spatial) return;

  // Keys and depths of the wide nodes; every child box inside its slot's box.
  std::vector<Key> wkey(wn, Key{std::numeric_limits<std::uint32_t>::max(), 0});
  std::vector<int> wdepth(wn, 0);
  int deepest_leaf_node = 0;
  for (std::uint32_t w = 0; w < wn; ++w) {
    for (int i = 0; i < W; ++i) {
      if (slot_kind(wide.nodes[w], i) == Slot::kInterior) wdepth[wide.nodes[w].child[i]] = wdepth[w] + 1;
      if (slot_kind(wide.nodes[w], i) == Slot::kLeaf) deepest_leaf_node = std::max(deepest_leaf_node, wdepth[w]);
    }
  }
  EXPECT_EQ(wide.max_depth, deepest_leaf_node) << "max_depth: the deepest node holding a leaf, root = 0";
  std::vector<Key> leaf_key(std::size_t(wn) * W);
  for (std::uint32_t w = wn; w-- > 0;) {
    const WideBvhNode<W>& n = wide.nodes[w];
    for (int i = 0; i < W; ++i) {
      const Slot k = slot_kind(n, i);
      if (k == Slot::kLeaf) {
        const auto& ids = slot_ids[std::size_t(w) * W + std::size_t(i)];
        ASSERT_FALSE(ids.empty());
        const auto it = leaf_of_first_id.find(ids[0]);
        ASSERT_NE(it, leaf_of_first_id.end()) << "node " << w << " slot " << i << " starts no binary leaf";
        const BvhNode& b = tree.nodes[it->second];
        EXPECT_EQ(ids, wide_leaf_order(g, tree, b))
            << "node " << w << " slot " << i << ": not the binary leaf's references in order";
        leaf_key[std::size_t(w) * W + std::size_t(i)] = bkey[it->second];
        wkey[w] = combine(wkey[w], bkey[it->second]);
      }
      if (k == Slot::kInterior) {
        wkey[w] = combine(wkey[w], wkey[n.child[i]]);
        const WideBvhNode<W>& c = wide.nodes[n.child[i]];
        for (int j = 0; j < W; ++j) {
          if (slot_kind(c, j) == Slot::kEmpty) continue;
          for (int a = 0; a < 3; ++a) {
            EXPECT_LE(n.lo[a][i], c.lo[a][j]) << "child box outside its slot, node " << w << " slot " << i;
            EXPECT_GE(n.hi[a][i], c.hi[a][j]) << "child box outside its slot, node " << w << " slot " << i;
          }
        }
      }
    }
  }
  if (::testing::Test::HasFailure()) return;

  // Each wide node came from a binary interior node (the root from the root, unless the root is
  // a leaf); each slot is a distinct binary node 1 to W - 1 levels below it with the same box
  // bit for bit, and together they hold exactly its leaves. Opening the child of largest area can go
  // down one path, so a slot may be as many as W - 1 levels down.
  std::vector<std::uint32_t> origin(wn, bn);
  origin[0] = 0;
  std::vector<int> as_slot(bn, 0);
  const bool root_is_leaf = tree.nodes[0].is_leaf();
  for (std::uint32_t w = 0; w < wn && !::testing::Test::HasFailure(); ++w) {
    const WideBvhNode<W>& n = wide.nodes[w];
    ASSERT_LT(origin[w], bn) << "node " << w << " not reached from the root";
    EXPECT_EQ(wkey[w], bkey[origin[w]]) << "node " << w << " does not hold exactly its binary node's leaves";
    for (int i = 0; i < W; ++i) {
      const Slot kind = slot_kind(n, i);
      if (kind == Slot::kEmpty) continue;
      const Key key = kind == Slot::kLeaf ? leaf_key[std::size_t(w) * W + std::size_t(i)] : wkey[n.child[i]];
      const auto it = binary_of.find(key);
      ASSERT_NE(it, binary_of.end()) << "node " << w << " slot " << i << " matches no binary node";
      const std::uint32_t b = it->second;
      EXPECT_EQ(++as_slot[b], 1) << "binary node " << b << " in two slots";
      EXPECT_TRUE(same_box_bits(n, i, tree.nodes[b])) << "node " << w << " slot " << i << " box differs";
      EXPECT_EQ(tree.nodes[b].is_leaf(), kind == Slot::kLeaf);
      if (kind == Slot::kInterior) origin[n.child[i]] = b;
      if (root_is_leaf) continue;
      int levels = 0;
      std::uint32_t up = b;
      while (up != origin[w] && up != 0) up = bparent[up], ++levels;
      EXPECT_EQ(up, origin[w]) << "node " << w << " slot " << i << " is not below the node it came from";
      EXPECT_TRUE(levels >= 1 && levels <= W - 1)
          << "node " << w << " slot " << i << " is " << levels << " levels down";
    }
  }
  if (::testing::Test::HasFailure()) return;
  for (std::uint32_t b = 0; b < bn; ++b) {
    if (tree.nodes[b].is_leaf()) {
      EXPECT_EQ(as_slot[b], 1) << "binary leaf " << b;
    }
  }
}

// The box test of the traversal (wide_bvh_leaf.h), lane by lane in scalar code with the same
// operations: bit i is set when the ray enters slot i. A NaN slab distance is dropped (min and max
// keep the running value, their second operand).
template <int W>
unsigned entered_mask(const WideBvhNode<W>& node, const Ray& ray) {
  constexpr float kSlabWiden = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
  unsigned mask = 0;
  for (int i = 0; i < W; ++i) {
    float t_near = ray.tmin, t_far = kInf;
    for (int a = 0; a < 3; ++a) {
      const bool negative = std::signbit(ray.direction[a]);
      const float inv = 1.f / ray.direction[a];
      const float t0 = ((negative ? node.hi[a][i] : node.lo[a][i]) - ray.origin[a]) * inv;
      const float t1 = ((negative ? node.lo[a][i] : node.hi[a][i]) - ray.origin[a]) * inv;
      t_near = t0 > t_near ? t0 : t_near;
      t_far = t1 < t_far ? t1 : t_far;
    }
    t_far = t_far < ray.tmax ? t_far : ray.tmax;
    t_far = std::max(t_far * kSlabWiden, t_far * (2.0f - kSlabWiden));  // away from zero for either sign
    mask |= (t_near <= t_far ? 1u : 0u) << i;
  }
  return mask;
}

// The scene's random rays plus awkward finite ones: zero, denormal and huge direction components
// of either sign, origins on the scene box's planes, tmin of -inf, short tmax.
// For the structure checks, tmin of -inf too; not for comparisons of answers, where it lets the
// non-triangle shapes report hits at t = -inf from denormal directions, which structures cull
// (and brute force does not) depending on their boxes.
std::vector<Ray> awkward_rays(const Geometry& g, Sampler& s, int count, bool negative_tmin = true) {
  std::vector<Ray> rays = g.size() > 0 ? random_rays(g, s, count) : std::vector<Ray>{};
  const Box3 box = g.size() > 0 ? g.bounds() : Box3{Vec3(-1.f), Vec3(1.f)};
  const float comps[] = {0.f, -0.f, 1e-45f, -1e-45f, 1.f, -1.f, 1e30f, -1e30f, 0.3f, -0.7f};
  for (int i = 0; i < count / 4; ++i) {
    Ray r;
    r.origin = s.in_box(box.lo - box.extent(), box.hi + box.extent());
    const int axis = static_cast<int>(s.rng.next_u32() % 3);
    r.origin[axis] = s.rng.next_float() < 0.5f ? box.lo[axis] : box.hi[axis];
    for (int a = 0; a < 3; ++a) r.direction[a] = comps[s.rng.next_u32() % std::size(comps)];
    if (i % 3 == 0 && negative_tmin) r.tmin = -kInf;
    if (i % 5 == 0) r.tmax = 1e-3f;
    rays.push_back(r);
  }
  return rays;
}

// Empty slots are entered by no ray; used ones (a control on entered_mask) by a ray from inside.
template <int W>
void check_empty_slots_unreachable(const WideBvhTree<W>& wide, const std::vector<Ray>& rays) {
  int failures = 0;
  for (std::size_t w = 0; w < wide.nodes.size(); ++w) {
    const WideBvhNode<W>& n = wide.nodes[w];
    unsigned empty = 0;
    for (int i = 0; i < W; ++i) {
      if (slot_kind(n, i) == Slot::kEmpty) {
        empty |= 1u << i;
        continue;
      }
      Ray inside;
      inside.origin = {0.5f * (n.lo[0][i] + n.hi[0][i]), 0.5f * (n.lo[1][i] + n.hi[1][i]),
                       0.5f * (n.lo[2][i] + n.hi[2][i])};
      inside.direction = {0.3f, -0.5f, 0.8f};
      EXPECT_TRUE(entered_mask(n, inside) & (1u << i)) << "a ray from inside misses node " << w << " slot " << i;
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

// The accelerator holds exactly collapse_to_wide(build_bvh(g, build_config(config))) and reports it; its
// traversal visits each node at most once and tests each reference at most once.
template <int W>
void check_accelerator(const Geometry& g, const BvhConfig& config, const BvhTree& tree, const WideBvhTree<W>& wide,
                       const std::vector<Ray>& rays) {
  const WideBvh<W> accel(g, config);
  const WideBvhTree<W>& held = accel.tree();
  ASSERT_EQ(held.nodes.size(), wide.nodes.size());
  ASSERT_EQ(held.leaves.blocks.size(), wide.leaves.blocks.size());
  EXPECT_EQ(std::memcmp(held.nodes.data(), wide.nodes.data(), wide.nodes.size() * sizeof(WideBvhNode<W>)), 0);
  if (!wide.leaves.blocks.empty()) {  // memcmp must not be given the null data() of an empty vector
    EXPECT_EQ(std::memcmp(held.leaves.blocks.data(), wide.leaves.blocks.data(),
                          wide.leaves.blocks.size() * sizeof(TriangleBlock4)),
              0);
  }
  EXPECT_EQ(held.leaves.others, wide.leaves.others);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(held.nodes.data()) % 64, 0u) << "nodes not cache-line aligned";
  const AccelInfo info = accel.info();
  EXPECT_EQ(info.name, W == native_box_width(active_isa()) ? std::string("bvh") : "bvh" + std::to_string(W));
  EXPECT_EQ(info.node_count, wide.nodes.size());
  EXPECT_EQ(info.leaf_count, tree.leaf_count);
  EXPECT_EQ(info.primitive_count, tree.prim_ids.size());
  // The sphere lanes: 16 bytes per position of `others` and 3 of padding, when a leaf holds a sphere.
  const std::size_t sphere_lane_bytes = wide.leaves.sphere_radius.empty() ? 0 : (wide.leaves.others.size() + 3) * 16;
  EXPECT_EQ(info.memory_bytes, info.node_count * W * 32 + wide.leaves.blocks.size() * 160 +
                                   wide.leaves.others.size() * 4 + held.leaves.cylinder_frames.frames.size() * 72 +
                                   sphere_lane_bytes + wide.leaves.cylinder_lanes.bytes() +
                                   wide.leaves.leaf_kinds.size() * 2);
  EXPECT_EQ(wide.leaves.leaf_kinds.size(), wide.leaves.others.size());
  // The cylinder lanes: 28 bytes per position of `others` and 3 of padding, when the scene has a
  // cylinder and a leaf lists ids.
  EXPECT_EQ(wide.leaves.cylinder_lanes.bytes(),
            g.cylinders.empty() || wide.leaves.others.empty() ? 0 : (wide.leaves.others.size() + 3) * 28);
  EXPECT_EQ(held.leaves.sphere_radius, wide.leaves.sphere_radius);
  EXPECT_EQ(held.leaves.sphere_x, wide.leaves.sphere_x);
  // Every listed sphere sits in the lanes at its id's position, every other position has radius 0;
  // every listed cylinder's rejection data sit in the cylinder lanes at its position. A leaf lists
  // its spheres, then its cylinders, then the rest.
  const auto first_sphere = static_cast<std::uint32_t>(g.triangles.size());
  const auto first_cylinder = first_sphere + static_cast<std::uint32_t>(g.spheres.size());
  auto kind_rank = [&](std::uint32_t id) {
    return id - first_sphere < g.spheres.size() ? 0 : id - first_cylinder < g.cylinders.size() ? 1 : 2;
  };
  for (const WideBvhNode<W>& node : wide.nodes) {
    for (int slot = 0; slot < W; ++slot) {
      const auto ids = wide.leaves.others_of(node.child[slot], node.count[slot]);
      if (!ids.empty()) {  // the leaf's counts of spheres and cylinders, saturated at 255
        std::size_t spheres = 0, cylinders = 0;
        for (const std::uint32_t id : ids) {
          spheres += kind_rank(id) == 0 ? 1 : 0;
          cylinders += kind_rank(id) == 1 ? 1 : 0;
        }
        const WideBvhLeaves::LeafKinds kinds =
            wide.leaves.leaf_kinds[static_cast<std::size_t>(ids.data() - wide.leaves.others.data())];
        EXPECT_EQ(kinds.spheres, std::min<std::size_t>(spheres, 255));
        EXPECT_EQ(kinds.cylinders, std::min<std::size_t>(cylinders, 255));
      }
      for (std::size_t k = 0; k < ids.size(); ++k) {
        const std::size_t at = static_cast<std::size_t>(ids.data() - wide.leaves.others.data()) + k;
        if (k > 0) {
          EXPECT_LE(kind_rank(ids[k - 1]), kind_rank(ids[k])) << "leaf list out of kind order at " << at;
        }
        const std::uint32_t cylinder = ids[k] - first_cylinder;
        if (cylinder < g.cylinders.size()) {
          EXPECT_TRUE(wide.leaves.cylinder_lanes.holds(at, cylinder_frame(g.cylinders[cylinder])))
              << "cylinder " << ids[k] << " at position " << at;
        }
        const std::uint32_t sphere = ids[k] - first_sphere;
        if (sphere >= g.spheres.size()) {
          if (!wide.leaves.sphere_radius.empty()) {
            EXPECT_EQ(wide.leaves.sphere_radius[at], 0.f);
          }
          continue;
        }
        ASSERT_EQ(wide.leaves.sphere_radius.size(), wide.leaves.others.size() + 3);
        const Sphere& s = g.spheres[sphere];
        EXPECT_TRUE(wide.leaves.sphere_x[at] == s.center.x && wide.leaves.sphere_y[at] == s.center.y &&
                    wide.leaves.sphere_z[at] == s.center.z && wide.leaves.sphere_radius[at] == s.radius)
            << "sphere " << ids[k] << " at position " << at;
      }
    }
  }
  EXPECT_EQ(!wide.leaves.sphere_radius.empty(), !g.spheres.empty() && !wide.leaves.others.empty());
  EXPECT_EQ(info.max_depth, wide.max_depth);
  EXPECT_GE(info.build_seconds, 0.0);
  if (!tree.prim_ids.empty()) {
    const Box3 b = accel.bounds();
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(b.lo[a], tree.nodes[0].lo[a]);
      EXPECT_EQ(b.hi[a], tree.nodes[0].hi[a]);
    }
  }
  int failures = 0;
  for (const Ray& ray : rays) {
    Ray r = ray;
    Hit h;
    TraversalStats si, so;
    accel.intersect_counted(r, h, si);
    accel.occluded_counted(ray, so);
    if ((si.nodes_visited > wide.nodes.size() || so.nodes_visited > wide.nodes.size() ||
         si.prim_tests > tree.prim_ids.size() || so.prim_tests > tree.prim_ids.size()) &&
        ++failures <= 5) {
      ADD_FAILURE() << "visited " << si.nodes_visited << " / " << so.nodes_visited << " of " << wide.nodes.size()
                    << " nodes, " << si.prim_tests << " / " << so.prim_tests << " tests";
    }
  }
  EXPECT_EQ(failures, 0);
}

template <int W>
void check_all(const Geometry& g, const BvhConfig& config, std::uint64_t seed, int ray_count) {
  // The binary tree the accelerator collapses: built with leaves priced per block.
  const BvhTree tree = build_bvh(g, WideBvh<W>::build_config(config));
  const WideBvhTree<W> wide = collapse_to_wide<W>(tree, g);
  check_collapse<W>(g, tree, wide, config.spatial_splits);
  Sampler s(seed);
  const std::vector<Ray> rays = awkward_rays(g, s, ray_count);
  check_empty_slots_unreachable<W>(wide, rays);
  // A broken tree can send the traversal round in circles: only a sound one is traversed.
  if (::testing::Test::HasFailure()) return;
  check_accelerator<W>(g, config, tree, wide, rays);
}

// ---------------------------------------------------------------------------------------------
// Answers

bool same_bits(const Hit& a, const Hit& b) {
  return bits(a.t) == bits(b.t) && a.prim_id == b.prim_id && bits(a.u) == bits(b.u) && bits(a.v) == bits(b.v);
}
bool same_bits(const Ray& a, const Ray& b) { return std::memcmp(&a, &b, sizeof(Ray)) == 0; }

std::string describe(const Ray& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "o=(%a, %a, %a) d=(%a, %a, %a) tmin=%a tmax=%a", r.origin.x, r.origin.y, r.origin.z,
                r.direction.x, r.direction.y, r.direction.z, r.tmin, r.tmax);
  return buf;
}
std::string describe(const Hit& h) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "t=%a prim=%u u=%a v=%a", h.t, h.prim_id, h.u, h.v);
  return buf;
}

// Every query of `wide` answers bit for bit as `reference` does: closest hit (t, prim_id, u, v
// and the shrunk tmax, or nothing changed on a miss), counted closest hit, any-hit with the ray's
// own tmax and with a tmax around the closest hit, counted any-hit.
void compare_bitwise(const Accelerator& wide, const Accelerator& reference, const std::vector<Ray>& rays,
                     const char* what, Sampler& s, int* hits_out = nullptr) {
  int failures = 0, hits = 0;
  auto fail = [&](const std::string& msg, const Ray& r) {
    if (++failures <= 5) ADD_FAILURE() << what << ": " << msg << " for ray " << describe(r);
  };
  for (const Ray& ray : rays) {
    Ray rr = ray, rw = ray, rc = ray;
    Hit hr, hw, hc;
    const bool fr = reference.intersect(rr, hr);
    const bool fw = wide.intersect(rw, hw);
    if (fr != fw || !same_bits(hr, hw) || !same_bits(rr, rw)) {
      fail("closest hit " + describe(hw) + (fw ? "" : " (miss)") + " vs " + describe(hr) + (fr ? "" : " (miss)"), ray);
    }
    hits += fr ? 1 : 0;
    if (!fw && (!same_bits(rw, ray) || hw.valid())) fail("a miss changed the ray or the hit", ray);
    TraversalStats st;
    const bool fc = wide.intersect_counted(rc, hc, st);
    if (fc != fw || !same_bits(hc, hw) || !same_bits(rc, rw)) fail("intersect_counted differs from intersect", ray);
    if (st.hits != (fc ? 1u : 0u)) fail("counted hits", ray);

    Ray ro = ray;
    if (fr && s.rng.next_float() < 0.7f) {
      const float pick = s.rng.next_float();
      ro.tmax = pick < 0.2f ? hr.t : (pick < 0.4f ? std::nextafter(hr.t, kInf) : hr.t * s.uni(0.5f, 1.5f));
    }
    const bool oref = reference.occluded(ro);
    if (wide.occluded(ro) != oref) fail(oref ? "occluded missed" : "occluded phantom", ro);
    TraversalStats so;
    if (wide.occluded_counted(ro, so) != oref) fail("occluded_counted differs", ro);
  }
  EXPECT_EQ(failures, 0) << what << ", of " << rays.size() << " rays";
  if (hits_out != nullptr) *hits_out = hits;
}

// ---------------------------------------------------------------------------------------------
// Packets

// Rays for the packet tests: coherent (one origin through a 4x4 pixel grid), incoherent
// (random), mixed octants from one point, and some with tmax already small or a carried-over
// hit. Each ray comes with the Hit it is traced with.
struct RaySet {
  std::vector<Ray> rays;
  std::vector<Hit> hits;
};

RaySet packet_rays(const Geometry& g, const Accelerator& reference, Sampler& s, int count, bool coherent_only = false) {
  RaySet set;
  const Box3 box = g.bounds();
  const Vec3 centre = (box.lo + box.hi) * 0.5f, ext = box.extent();
  const std::vector<Ray> random = random_rays(g, s, count);
  for (int i = 0; int(set.rays.size()) < count; ++i) {
    const int kind = coherent_only ? 0 : (i / 16) % 4;
    Ray r;
    if (kind == 0) {  // a 4x4 tile of a camera outside the box looking at its centre
      const int tile = i / 64;
      const Vec3 eye = centre + Vec3{ext.x * 1.5f, ext.y * 0.7f, -ext.z * 1.2f} * (1.f + 0.1f * float(tile % 3));
      const float px = float(tile % 5) * 4.f + float(i % 4), py = float(tile / 5 % 5) * 4.f + float(i / 4 % 4);
      r.origin = eye;
      r.direction = centre - eye + Vec3{ext.x * (px / 20.f - 0.5f), ext.y * (py / 20.f - 0.5f), 0.f};
    } else if (kind == 1) {  // random
      r = random[std::size_t(i) % random.size()];
    } else if (kind == 2) {  // from one point, all eight octants in turn
      r.origin = centre + ext * 0.1f;
      const Vec3 d = s.unit();
      r.direction = {i & 1 ? -std::fabs(d.x) : std::fabs(d.x), i & 2 ? -std::fabs(d.y) : std::fabs(d.y),
                     i & 4 ? -std::fabs(d.z) : std::fabs(d.z)};
    } else {  // axis-aligned and zero components within a coherent group
      r.origin = centre - ext * 0.45f + Vec3{ext.x * 0.05f * float(i % 4), ext.y * 0.05f * float(i / 4 % 4), 0.f};
      r.direction = i % 3 == 0 ? Vec3{0.f, -0.f, 1.f} : Vec3{0.2f, 0.3f, 1.f};
    }
    Hit h;
    const int twist = static_cast<int>(s.rng.next_u32() % 8);
    if (twist == 0) {  // tmax already small
      Ray probe = r;
      Hit ph;
      r.tmax = reference.intersect(probe, ph) ? ph.t * 0.5f : 1e-3f;
    } else if (twist == 1) {  // carried over from an earlier query: tmax at that hit
      Ray probe = r;
      if (reference.intersect(probe, h)) r.tmax = probe.tmax;
    } else if (twist == 2) {
      r.tmin = s.uni(0.f, 0.5f);
    }
    set.rays.push_back(r);
    set.hits.push_back(h);
  }
  return set;
}

// Packets of every size from 1 to 40, cut from `set` at shifting offsets, answer bit for bit as
// the single-ray queries of the same structure do.
void check_packets(const Accelerator& accel, const RaySet& set, const char* what) {
  int failures = 0;
  std::size_t start = 0;
  for (int n = 1; n <= 40; ++n) {
    if (start + std::size_t(n) > set.rays.size()) start = 0;
    const std::span<const Ray> group(set.rays.data() + start, std::size_t(n));
    const std::span<const Hit> group_hits(set.hits.data() + start, std::size_t(n));
    start += std::size_t(n) * 3 / 2 + 1;
    std::vector<Ray> rays(group.begin(), group.end()), singles = rays;
    std::vector<Hit> hits(group_hits.begin(), group_hits.end()), single_hits = hits;
    accel.intersect(std::span<Ray>(rays), std::span<Hit>(hits));
    std::vector<std::uint8_t> occ(std::size_t(n), 7);
    accel.occluded(group, std::span<std::uint8_t>(occ));
    for (int i = 0; i < n; ++i) {
      accel.intersect(singles[std::size_t(i)], single_hits[std::size_t(i)]);
      const bool single_occ = accel.occluded(group[std::size_t(i)]);
      if ((!same_bits(hits[std::size_t(i)], single_hits[std::size_t(i)]) ||
           !same_bits(rays[std::size_t(i)], singles[std::size_t(i)])) &&
          ++failures <= 5) {
        ADD_FAILURE() << what << ": packet of " << n << ", lane " << i << ": " << describe(hits[std::size_t(i)])
                      << " vs single " << describe(single_hits[std::size_t(i)]) << " for ray "
                      << describe(group[std::size_t(i)]);
      }
      if (occ[std::size_t(i)] != (single_occ ? 1 : 0) && ++failures <= 5) {
        ADD_FAILURE() << what << ": packet of " << n << ", lane " << i << ": occluded " << int(occ[std::size_t(i)])
                      << " vs single " << single_occ << " for ray " << describe(group[std::size_t(i)]);
      }
    }
  }
  EXPECT_EQ(failures, 0) << what;
}

// ---------------------------------------------------------------------------------------------
// Tests, for each width

template <class T>
class WideBvhTest : public ::testing::Test {};
template <class T>
class WideBvhDeathTest : public ::testing::Test {};

template <int W>
using Width = std::integral_constant<int, W>;
using Widths = ::testing::Types<Width<4>, Width<8>, Width<16>>;
class WidthNames {
 public:
  template <class T>
  static std::string GetName(int) {
    return "W" + std::to_string(T::value);
  }
};
TYPED_TEST_SUITE(WideBvhTest, Widths, WidthNames);
TYPED_TEST_SUITE(WideBvhDeathTest, Widths, WidthNames);

static_assert(sizeof(WideBvhNode<4>) == 128 && sizeof(WideBvhNode<8>) == 256 && sizeof(WideBvhNode<16>) == 512,
              "a wide node is 32 bytes per slot");
static_assert(alignof(WideBvhNode<4>) == 64);

TYPED_TEST(WideBvhTest, StructureOnRandomScenes) {
  constexpr int W = TypeParam::value;
  for (const NamedScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    Sampler s(scene.seed);
    check_all<W>(scene.make(s), BvhConfig{}, scene.seed + 100, 1200);
  }
}

TYPED_TEST(WideBvhTest, StructureUnderOtherBuildConfigs) {
  constexpr int W = TypeParam::value;
  for (const BvhConfig config :
       {BvhConfig{2, 1, 1.f, 1.f, 4096}, BvhConfig{64, 32, 0.5f, 2.f, 4096}, BvhConfig{16, 4, 1.f, 1.f, 64}}) {
    SCOPED_TRACE("max_leaf_size " + std::to_string(config.max_leaf_size));
    Sampler s(7);
    check_all<W>(every_shape_kind(s), config, 107, 600);
  }
}

// A scene large enough that the collapse cuts it into fragments collapsed by separate tasks
// (subtrees of a few thousand blocks and ids), with leaves of every form: the same structure
// and layout as on small scenes, and the same tree with one thread as with several.
TYPED_TEST(WideBvhTest, LargeSceneCollapsedInParallel) {
  constexpr int W = TypeParam::value;
  Sampler s(31);
  Geometry g;
  for (int i = 0; i < 40000; ++i) g.add(random_triangle(s, s.in_box(Vec3(-40.f), Vec3(40.f)), s.uni(0.2f, 1.5f)), 0);
  for (int i = 0; i < 6000; ++i) g.add(Sphere{s.in_box(Vec3(-40.f), Vec3(40.f)), s.uni(0.1f, 1.f)}, 1);
  check_all<W>(g, BvhConfig{}, 131, 400);
  const BvhTree tree = build_bvh(g, WideBvh<W>::build_config(BvhConfig{}));
  const WideBvhTree<W> parallel = collapse_to_wide<W>(tree, g);
  WideBvhTree<W> single;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    single = collapse_to_wide<W>(tree, g);
  }
  ASSERT_EQ(single.nodes.size(), parallel.nodes.size());
  ASSERT_EQ(single.leaves.blocks.size(), parallel.leaves.blocks.size());
  EXPECT_EQ(std::memcmp(single.nodes.data(), parallel.nodes.data(), parallel.nodes.size() * sizeof(WideBvhNode<W>)), 0);
  EXPECT_EQ(std::memcmp(single.leaves.blocks.data(), parallel.leaves.blocks.data(),
                        parallel.leaves.blocks.size() * sizeof(TriangleBlock4)),
            0);
  EXPECT_EQ(single.leaves.others, parallel.leaves.others);
  EXPECT_EQ(single.max_depth, parallel.max_depth);
  EXPECT_GT(parallel.leaves.blocks.size(), 8000u) << "too small to be cut into fragments";
}

// Spatial splits (clipped triangle references in several leaves) and leaf costs per block: a
// sound structure and the same bits as brute force.
TYPED_TEST(WideBvhTest, SpatialSplitsAndBlockCosts) {
  constexpr int W = TypeParam::value;
  BvhConfig spatial;
  spatial.spatial_splits = true;
  spatial.spatial_split_alpha = 0.f;  // try them everywhere
  BvhConfig blocks;
  blocks.leaf_block_size = 4;
  for (const BvhConfig& config : {spatial, blocks}) {
    for (const NamedScene& scene : kScenes) {
      SCOPED_TRACE(std::string(scene.name) + (config.spatial_splits ? ", spatial splits" : ", block costs"));
      Sampler s(scene.seed + 20);
      const Geometry g = scene.make(s);
      check_all<W>(g, config, scene.seed + 120, 200);
      // Against the binary tree of the same build on many rays, against brute force (slow) on a few.
      const WideBvh<W> wide(g, config);
      const Bvh binary(g, config);
      const BruteForce brute(g);
      const std::vector<Ray> rays = awkward_rays(g, s, 800, false);
      compare_bitwise(wide, binary, rays, "vs binary BVH", s);
      compare_bitwise(wide, brute, std::vector<Ray>(rays.begin(), rays.begin() + 150), "vs brute force", s);
      if (::testing::Test::HasFailure()) return;
    }
  }
}

// The six scenes: the same bits as the binary BVH and as brute force, for every query.
TYPED_TEST(WideBvhTest, BitIdenticalToBinaryBvhAndBruteForce) {
  constexpr int W = TypeParam::value;
  for (const NamedScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    Sampler s(scene.seed);
    const Geometry g = scene.make(s);
    const WideBvh<W> wide(g);
    const Bvh binary(g);
    const BruteForce brute(g);
    // Brute force is slow (most of this test's time): all the rays against the binary tree, a
    // share of them against brute force.
    const std::vector<Ray> rays = awkward_rays(g, s, 2000, false);
    int hits = 0;
    compare_bitwise(wide, binary, rays, "vs binary BVH", s, &hits);
    compare_bitwise(wide, brute, std::vector<Ray>(rays.begin(), rays.begin() + 300), "vs brute force", s);
    compare_bitwise(wide, brute, std::vector<Ray>(rays.end() - 100, rays.end()), "vs brute force (awkward)", s);
    EXPECT_GT(hits, int(rays.size()) / 10) << "too few hits for a meaningful comparison";
    if (::testing::Test::HasFailure()) return;
  }
}

TYPED_TEST(WideBvhTest, PacketsEqualSingleRays) {
  constexpr int W = TypeParam::value;
  for (const NamedScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    Sampler s(scene.seed + 50);
    const Geometry g = scene.make(s);
    const WideBvh<W> wide(g);
    const RaySet set = packet_rays(g, wide, s, 700);
    check_packets(wide, set, scene.name);
    // Camera tiles only, so that whole packets share an octant and use the interval test.
    check_packets(wide, packet_rays(g, wide, s, 400, true), scene.name);
    // The packet results also equal brute force (through the single rays), spot-checked.
    const BruteForce brute(g);
    std::vector<Ray> rays(set.rays.begin(), set.rays.begin() + 64);
    std::vector<Hit> hits(set.hits.begin(), set.hits.begin() + 64);
    wide.intersect(std::span<Ray>(rays), std::span<Hit>(hits));
    for (std::size_t i = 0; i < rays.size(); ++i) {
      Ray r = set.rays[i];
      Hit h = set.hits[i];
      brute.intersect(r, h);
      EXPECT_TRUE(same_bits(h, hits[i]) && same_bits(r, rays[i])) << "ray " << i << ": " << describe(set.rays[i]);
    }
    if (::testing::Test::HasFailure()) return;
  }
}

// Small and degenerate inputs, under the default build and one that splits down to single
// primitives.
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
      g.add(tri, 0);
      break;
    case 3:
      g.add(Sphere{{-3.f, 0.f, 5.f}, 1.f}, 0);
      g.add(tri, 1);
      break;
    case 4:
      g.add(tri, 0);
      g.add(Sphere{{3.f, 0.f, 4.f}, 1.f}, 1);
      g.add(Quad{{-4.f, -4.f, 8.f}, {8.f, 0.f, 0.f}, {0.f, 8.f, 0.f}}, 2);
      g.add(Disk{{0.f, 3.f, 2.f}, {0.f, 0.f, 1.f}, 1.f}, 3);
      g.add(Cylinder{{-3.f, -3.f, 2.f}, 0.5f, {-3.f, -3.f, 4.f}, 0.5f}, 4);
      break;
    case 5:
      for (int i = 0; i < 40; ++i) g.add(tri, 0);  // all coincident
      break;
    default:
      for (int i = 0; i < 33; ++i) g.add(Quad{{-1.f, -1.f, 6.f}, {2.f, 0.f, 0.f}, {0.f, 2.f, 0.f}}, 0);  // flat too
      break;
  }
  return g;
}

// The leaves keep a frame for each cylinder id in the range the tree holds, equal to the one
// the test computes from the Cylinder (so the tree's answers stay Geometry::intersect's, which
// BitIdenticalToBinaryBvhAndBruteForce checks); a tree over part of the scene covers only the
// range of its own cylinders, and a scene without cylinders keeps none.
TYPED_TEST(WideBvhTest, CylinderFramesCoverTheTreesCylinders) {
  constexpr int W = TypeParam::value;
  Sampler s(61);
  const Geometry g = every_shape_kind(s);
  ASSERT_GT(g.cylinders.size(), 4u);
  const auto first = static_cast<std::uint32_t>(g.triangles.size() + g.spheres.size());
  const auto same = [](const CylinderFrame& a, const CylinderFrame& b) {
    return a.base == b.base && a.base_radius == b.base_radius && a.wx == b.wx && a.wy == b.wy && a.wz == b.wz &&
           a.h == b.h && a.k == b.k && a.axis == b.axis && a.reject_radius == b.reject_radius;
  };
  const WideBvh<W> whole(g);
  const WideBvhLeaves& leaves = whole.tree().leaves;
  EXPECT_EQ(leaves.cylinder_frames.begin, first);
  ASSERT_EQ(leaves.cylinder_frames.frames.size(), g.cylinders.size());
  for (std::size_t i = 0; i < g.cylinders.size(); ++i) {
    EXPECT_TRUE(same(leaves.cylinder_frames.frames[i], cylinder_frame(g.cylinders[i]))) << i;
  }
  EXPECT_EQ(leaves.cylinder_frame_of(first - 1), nullptr);
  EXPECT_EQ(leaves.cylinder_frame_of(first + static_cast<std::uint32_t>(g.cylinders.size())), nullptr);
  const std::uint32_t part[] = {0, first + 2, first + 3, first + 4};
  const WideBvh<W> subset(g, part);
  EXPECT_EQ(subset.tree().leaves.cylinder_frames.begin, first + 2);
  EXPECT_EQ(subset.tree().leaves.cylinder_frames.frames.size(), 3u);
  Geometry no_cylinders;
  no_cylinders.add(Sphere{}, 0);
  EXPECT_TRUE(WideBvh<W>(no_cylinders).tree().leaves.cylinder_frames.frames.empty());
}

TYPED_TEST(WideBvhTest, DegenerateGeometry) {
  constexpr int W = TypeParam::value;
  const char* names[] = {"empty",
                         "one sphere",
                         "one triangle",
                         "two primitives",
                         "five primitives",
                         "40 coincident triangles",
                         "33 coincident flat quads"};
  for (int which = 0; which < 7; ++which) {
    for (const BvhConfig config : {BvhConfig{}, BvhConfig{16, 1, 1.f, 1.f, 4096}, BvhConfig{2, 2, 1.f, 1.f, 4}}) {
      SCOPED_TRACE(std::string(names[which]) + ", max_leaf_size " + std::to_string(config.max_leaf_size));
      const Geometry g = degenerate(which);
      check_all<W>(g, config, 200 + std::uint64_t(which), 400);
      if (::testing::Test::HasFailure()) return;
      // Rays from near the origin towards the scene: the same bits as brute force.
      const WideBvh<W> accel(g, config);
      const BruteForce brute(g);
      Sampler s(300 + std::uint64_t(which));
      std::vector<Ray> rays;
      for (int i = 0; i < 300; ++i) {
        const Vec3 o = s.in_box(Vec3(-0.5f), Vec3(0.5f));
        rays.push_back(Ray{o, 0.f, s.in_box(Vec3(-4.f, -4.f, 1.f), Vec3(4.f, 4.f, 8.f)) - o});
      }
      int hits = 0;
      compare_bitwise(accel, brute, rays, names[which], s, &hits);
      if (which != 0) {
        EXPECT_GT(hits, 0);
      }
      if (which == 5) {
        // Coincident triangles tie exactly; the lowest id wins, whatever the leaf order.
        for (const Ray& ray : rays) {
          Ray r = ray;
          Hit h;
          if (accel.intersect(r, h)) {
            EXPECT_EQ(h.prim_id, 0u);
          }
        }
      }
      const AccelInfo info = accel.info();
      EXPECT_EQ(info.primitive_count, g.size());
      if (which <= 2) {
        EXPECT_EQ(info.node_count, 1u);
        EXPECT_EQ(info.leaf_count, which == 0 ? 0u : 1u);
        EXPECT_EQ(info.max_depth, 0);
      }
      if (which == 0) {
        EXPECT_EQ(info.memory_bytes, sizeof(WideBvhNode<W>));
        std::vector<Ray> none(5, Ray{Vec3(0.f), 0.f, {0.f, 0.f, 1.f}});
        std::vector<Hit> nohits(5);
        accel.intersect(std::span<Ray>(none), std::span<Hit>(nohits));
        for (const Hit& h : nohits) EXPECT_FALSE(h.valid());
        std::vector<std::uint8_t> occ(5, 7);
        accel.occluded(std::span<const Ray>(none), std::span<std::uint8_t>(occ));
        for (std::uint8_t o : occ) EXPECT_EQ(o, 0);
      }
      check_packets(accel, packet_rays(g.size() > 0 ? g : degenerate(2), accel, s, 200), names[which]);
    }
  }
}

// Scenes for the leaf layout: spheres only (leaves list ids, no blocks at all); triangles with a
// sphere around each (leaves holding both kinds); a pile of coincident spheres that no split
// separates (a leaf listing many ids); a pile of coincident triangles and spheres (a leaf holding
// both, with more triangles than kMaxMixedBlocks blocks take), each pile among scattered shapes.
Geometry leaf_layout_scene(int which) {
  Sampler s(400 + std::uint64_t(which));
  Geometry g;
  // The same centroid, (0, 0, 5), whether a builder takes the box centre or the vertex mean.
  const Triangle pile_triangle{{-1.f, -1.f, 5.f}, {1.f, 0.f, 5.f}, {0.f, 1.f, 5.f}};
  const Sphere pile_sphere{{0.f, 0.f, 5.f}, 0.5f};
  switch (which) {
    case 0:
      for (int i = 0; i < 600; ++i) g.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.05f, 1.5f)}, 0);
      break;
    case 1:
      for (int i = 0; i < 400; ++i) {
        const Vec3 c = s.in_box(Vec3(-10.f), Vec3(10.f));
        g.add(random_triangle(s, c, 0.4f), 0);
        g.add(Sphere{c + s.unit() * 0.1f, 0.15f}, 1);
      }
      break;
    case 2:
      for (int i = 0; i < 100; ++i) g.add(pile_sphere, 0);
      for (int i = 0; i < 60; ++i) g.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.1f, 1.f)}, 1);
      break;
    default:
      for (int i = 0; i < 70; ++i) g.add(pile_triangle, 0);
      for (int i = 0; i < 30; ++i) g.add(pile_sphere, 1);
      for (int i = 0; i < 60; ++i) g.add(random_triangle(s, s.in_box(Vec3(-10.f), Vec3(10.f)), 0.5f), 2);
      for (int i = 0; i < 20; ++i) g.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.1f, 1.f)}, 3);
      break;
  }
  return g;
}

// What the leaves of a tree look like: the most ids a leaf without blocks lists, the number of
// leaves holding both kinds, and whether one of them lists triangles.
struct LeafShapes {
  std::size_t most_listed = 0, mixed = 0;
  bool triangles_listed = false;
};

template <int W>
LeafShapes leaf_shapes(const WideBvhTree<W>& wide) {
  LeafShapes shapes;
  for (const WideBvhNode<W>& n : wide.nodes) {
    for (int i = 0; i < W; ++i) {
      if (n.count[i] == 0) continue;
      const std::span<const std::uint32_t> listed = wide.leaves.others_of(n.child[i], n.count[i]);
      if (WideBvhLeaves::block_count(n.count[i]) == 0) {
        shapes.most_listed = std::max(shapes.most_listed, listed.size());
      } else if (!listed.empty()) {
        ++shapes.mixed;
        for (const std::uint32_t id : listed) shapes.triangles_listed |= id < wide.leaves.triangle_count;
      }
    }
  }
  return shapes;
}

TYPED_TEST(WideBvhTest, LeavesListingOtherKinds) {
  constexpr int W = TypeParam::value;
  const char* names[] = {"spheres only", "a sphere around each triangle", "coincident spheres",
                         "coincident triangles and spheres"};
  // The default build, and one that keeps the coincident piles in one leaf.
  for (const BvhConfig config : {BvhConfig{}, BvhConfig{16, 256, 1.f, 1.f, 4096}}) {
    for (int which = 0; which < 4; ++which) {
      SCOPED_TRACE(std::string(names[which]) + ", max_leaf_size " + std::to_string(config.max_leaf_size));
      const Geometry g = leaf_layout_scene(which);
      check_all<W>(g, config, 500 + std::uint64_t(which), 400);
      if (::testing::Test::HasFailure()) return;
      const WideBvh<W> accel(g, config);
      const WideBvhTree<W>& wide = accel.tree();
      const LeafShapes shapes = leaf_shapes(wide);
      if (which == 0) {
        EXPECT_TRUE(wide.leaves.blocks.empty());
        EXPECT_EQ(wide.leaves.others.size(), g.size()) << "spheres only: one id each, no headers";
        // 4 bytes of id, 16 of sphere lanes and 2 of leaf kind counts per sphere, and the lanes'
        // 3 positions of padding.
        EXPECT_EQ(accel.info().memory_bytes, wide.nodes.size() * sizeof(WideBvhNode<W>) + g.size() * 22 + 3 * 16);
      }
      if (which == 1) {
        EXPECT_GT(shapes.mixed, 0u) << "no leaf holds both kinds";
      }
      if (which == 2 && config.max_leaf_size == 256) {
        EXPECT_GE(shapes.most_listed, 100u) << "the pile is not one leaf";
      }
      if (which == 3 && config.max_leaf_size == 256) {
        EXPECT_TRUE(shapes.triangles_listed) << "no leaf lists the triangles its blocks cannot take";
      }
      // Answers: as the binary tree and brute force, bit for bit, single rays and packets; the
      // rays start near the origin and cross the piles.
      const Bvh binary(g, config);
      const BruteForce brute(g);
      Sampler s(600 + std::uint64_t(which));
      std::vector<Ray> rays = awkward_rays(g, s, 400, false);
      for (int i = 0; i < 200; ++i) {
        const Vec3 o = s.in_box(Vec3(-0.5f), Vec3(0.5f));
        rays.push_back(Ray{o, 0.f, s.in_box(Vec3(-1.5f, -1.5f, 4.f), Vec3(1.5f, 1.5f, 6.f)) - o});
      }
      int hits = 0;
      compare_bitwise(accel, binary, rays, "vs binary BVH", s, &hits);
      compare_bitwise(accel, brute, rays, "vs brute force", s);
      EXPECT_GT(hits, 100);
      check_packets(accel, packet_rays(g, accel, s, 300), names[which]);
      if (::testing::Test::HasFailure()) return;
    }
  }
}

// A leaf listing more spheres and more cylinders than its kind counts hold (255): the traversal
// counts them from the ids, and answers as brute force does. Piles of coincident shapes cannot
// be split, so with a large enough max_leaf_size each pile is one leaf.
TYPED_TEST(WideBvhTest, LeavesListingMoreThan255OfAKind) {
  constexpr int W = TypeParam::value;
  Sampler s(71);
  Geometry g;
  for (int i = 0; i < 300; ++i) g.add(Sphere{{0.f, 0.f, 5.f}, 0.2f + 0.001f * float(i)}, 0);
  for (int i = 0; i < 40; ++i) g.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.1f, 1.f)}, 1);
  for (int i = 0; i < 300; ++i) {
    const float r = 0.1f + 0.002f * float(i);
    g.add(Cylinder{{0.f, -0.5f, 5.f}, r, {0.f, 0.5f, 5.f}, r}, 2);
  }
  for (int i = 0; i < 40; ++i) {
    const Vec3 b = s.in_box(Vec3(-10.f), Vec3(10.f));
    g.add(Cylinder{b, 0.3f, b + s.unit(), 0.2f}, 3);
  }
  for (int i = 0; i < 20; ++i) g.add(random_triangle(s, s.in_box(Vec3(-10.f), Vec3(10.f)), 0.5f), 4);
  const BvhConfig config{16, 1024, 1.f, 1.f, 4096};
  check_all<W>(g, config, 72, 300);
  if (::testing::Test::HasFailure()) return;
  const WideBvh<W> accel(g, config);
  bool saturated = false;
  for (const WideBvhLeaves::LeafKinds& k : accel.tree().leaves.leaf_kinds) {
    saturated |= k.spheres == WideBvhLeaves::kKindCountSaturated && k.cylinders == WideBvhLeaves::kKindCountSaturated;
  }
  EXPECT_TRUE(saturated) << "no leaf holds 255 spheres and 255 cylinders";
  const BruteForce brute(g);
  std::vector<Ray> rays = awkward_rays(g, s, 200, false);
  for (int i = 0; i < 300; ++i) {  // through the piles, from all around
    const Vec3 o = Vec3{0.f, 0.f, 5.f} + s.unit() * s.uni(2.f, 20.f);
    rays.push_back(Ray{o, 0.f, Vec3{0.f, 0.f, 5.f} + s.in_box(Vec3(-0.8f), Vec3(0.8f)) - o});
  }
  int hits = 0;
  compare_bitwise(accel, brute, rays, "vs brute force", s, &hits);
  EXPECT_GT(hits, 250);
  check_packets(accel, packet_rays(g, accel, s, 300), "piles past 255");
}

// Rays with NaN, infinite or zero components (in the direction or the origin): every query
// answers as brute force does, bit for bit; one with a NaN component or a direction that is not
// finite and non-zero hits nothing (see traceable_direction in raylab/core/ray.h). Run in a
// child process so that a traversal that goes round in circles or runs off its stack fails this
// test instead of ending the whole test program.
std::vector<Ray> non_finite_rays() {
  const float comps[] = {kNaN, -kNaN, kInf, -kInf, 0.f, -0.f};
  std::vector<Ray> rays;
  // Directions built from these components (all-zero ones included), from an ordinary origin.
  for (float x : comps)
    for (float y : comps)
      for (float z : comps) {
        const Vec3 d{x, y, z};
        if (std::isfinite(x) && std::isfinite(y) && std::isfinite(z) && (x != 0.f || y != 0.f || z != 0.f)) continue;
        rays.push_back(Ray{{0.1f, 0.2f, -0.3f}, 0.f, d});
      }
  // NaN or infinite origins with ordinary directions.
  for (float o : {kNaN, kInf, -kInf}) {
    for (int a = 0; a < 3; ++a) {
      Ray r{{0.1f, 0.2f, -0.3f}, 0.f, {0.2f, -0.1f, 1.f}};
      r.origin[a] = o;
      rays.push_back(r);
    }
  }
  rays.push_back(Ray{Vec3(kNaN), 0.f, Vec3(kNaN)});
  return rays;
}

template <int W>
int non_finite_queries(const Geometry& g) {
  const WideBvh<W> accel(g);
  const BruteForce brute(g);
  const std::vector<Ray> rays = non_finite_rays();
  int bad = 0;
  for (const Ray& ray : rays) {
    Ray r = ray, rc = ray, rb = ray;
    Hit h, hc, hb;
    TraversalStats st;
    const bool hit = accel.intersect(r, h), hit_c = accel.intersect_counted(rc, hc, st);
    const bool occ = accel.occluded(ray), occ_c = accel.occluded_counted(ray, st);
    const bool hit_b = brute.intersect(rb, hb), occ_b = brute.occluded(ray);
    const bool must_miss = std::isnan(ray.origin.x) || std::isnan(ray.origin.y) || std::isnan(ray.origin.z) ||
                           std::isnan(ray.direction.x) || std::isnan(ray.direction.y) || std::isnan(ray.direction.z) ||
                           ray.direction == Vec3(0.f) || std::isinf(ray.direction.x) || std::isinf(ray.direction.y) ||
                           std::isinf(ray.direction.z);
    if (hit != hit_b || hit_c != hit || occ != occ_b || occ_c != occ || !same_bits(h, hb) || !same_bits(hc, hb) ||
        !same_bits(r, rb) || (must_miss && (hit || occ))) {
      std::fprintf(stderr, "differs from brute force (%d %d, %d %d) for ray %s\n", hit, hit_b, occ, occ_b,
                   describe(ray).c_str());
      ++bad;
    }
  }
  // Packets mixing them with ordinary rays: every lane as its single ray.
  Sampler s(77);
  std::vector<Ray> mixed = random_rays(g, s, int(rays.size()));
  for (std::size_t i = 0; i < rays.size(); i += 2) mixed[i] = rays[i];
  for (std::size_t n = 1; n <= mixed.size(); n += 7) {
    std::vector<Ray> group(mixed.begin(), mixed.begin() + long(n)), singles = group;
    std::vector<Hit> hits(n), single_hits(n);
    accel.intersect(std::span<Ray>(group), std::span<Hit>(hits));
    std::vector<std::uint8_t> occ(n, 7);
    accel.occluded(std::span<const Ray>(singles), std::span<std::uint8_t>(occ));
    for (std::size_t i = 0; i < n; ++i) {
      const bool single_occ = accel.occluded(singles[i]);
      accel.intersect(singles[i], single_hits[i]);
      if (!same_bits(hits[i], single_hits[i]) || !same_bits(group[i], singles[i]) || occ[i] != (single_occ ? 1 : 0)) {
        std::fprintf(stderr, "packet of %zu, lane %zu differs from the single ray %s\n", n, i,
                     describe(mixed[i]).c_str());
        ++bad;
      }
    }
  }
  return bad;
}

TYPED_TEST(WideBvhDeathTest, NonFiniteRaysNeitherCrashNorHit) {
  constexpr int W = TypeParam::value;
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  for (int which = 0; which < 3; ++which) {
    SCOPED_TRACE(which);
    Sampler s(90);
    const Geometry g = which == 0 ? degenerate(4) : (which == 1 ? spheres_and_triangles(s) : closed_meshes(s));
    EXPECT_EXIT(
        {
          alarm(60);  // a traversal that loops for ever fails instead of hanging
          std::_Exit(non_finite_queries<W>(g) == 0 ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "")
        << "a query with a NaN, infinite or zero ray crashed, looped or hit";
  }
}

}  // namespace
}  // namespace raylab
