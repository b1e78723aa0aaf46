// Collapsing the binary BVH into W-wide nodes, with leaves' triangles packed in blocks of four
// and their other primitives listed by id.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "wide_bvh_collapse.h"

namespace raylab {
namespace {

float node_area(const BvhNode& n) {
  const float ex = n.hi[0] - n.lo[0], ey = n.hi[1] - n.lo[1], ez = n.hi[2] - n.lo[2];
  return 2.f * (ex * ey + ey * ez + ez * ex);
}

// The binary tree a collapse reads: `build_bvh`'s laid-out tree, or the builder's unordered one.
// Node slots [0, node_count) are all used; prim(i) is the primitive id of leaf reference i.
template <class PrimOf>
struct BinarySource {
  const BvhNode* nodes;
  std::size_t node_count;
  bool empty;  // no primitives at all
  PrimOf prim;
};

template <int W, class PrimOf>
class WideCollapser {
 public:
  WideCollapser(const BinarySource<PrimOf>& tree, const Geometry& geometry) : m_tree(tree), m_geometry(geometry) {}

  WideBvhTree<W> run() {
    WideBvhLeaves& leaves = m_out.leaves;
    leaves.triangle_count = static_cast<std::uint32_t>(m_geometry.triangles.size());
    m_out.nodes.reserve(m_tree.node_count / (W - 1) + 1);
    size_leaves();
    if (m_tree.empty) {
      m_out.nodes.push_back(empty_node());  // nothing to hold: every slot empty
    } else if (m_tree.nodes[0].is_leaf()) {
      m_out.nodes.push_back(empty_node());
      place(0, 0, 0, 0);  // a single leaf: slot 0 of the only node
    } else {
      convert(0, 0);
    }
    fill_blocks();
    return std::move(m_out);
  }

 private:
  // How a binary leaf's references divide: the triangles that go into blocks, and the ids that
  // go into `others` (the other kinds, and the triangles beyond kMaxMixedBlocks blocks of a leaf
  // that holds both).
  struct LeafSplit {
    std::uint32_t block_triangles = 0;
    std::uint32_t other_ids = 0;

    std::uint32_t blocks() const { return (block_triangles + 3) / 4; }
    bool mixed() const { return block_triangles != 0 && other_ids != 0; }
  };

  // The split of binary leaf `b`.
  LeafSplit split_of(const BvhNode& b) const {
    std::uint32_t triangles = 0;
    for (std::uint32_t i = 0; i < b.count; ++i) triangles += is_triangle(m_tree.prim(b.first + i)) ? 1 : 0;
    LeafSplit split;
    split.block_triangles = triangles;
    split.other_ids = b.count - triangles;
    if (split.other_ids != 0) split.block_triangles = std::min(triangles, WideBvhLeaves::kMaxMixedBlocks * 4);
    split.other_ids = b.count - split.block_triangles;
    return split;
  }

  bool is_triangle(std::uint32_t id) const { return id < m_out.leaves.triangle_count; }

  // Sizes the leaf arrays exactly, and puts the leaves holding both kinds first in `others`
  // (their starts must fit in the bits of `count` above the block count).
  void size_leaves() {
    std::size_t blocks = 0, mixed = 0, others = 0;
    for (std::size_t i = 0; i < m_tree.node_count; ++i) {
      const BvhNode& b = m_tree.nodes[i];
      if (!b.is_leaf()) continue;
      const LeafSplit split = split_of(b);
      blocks += split.blocks();
      if (split.mixed()) {
        mixed += 1 + split.other_ids;  // a header, then the ids
      } else {
        others += split.other_ids;
      }
    }
    if (mixed > WideBvhLeaves::kMaxOthersField || mixed + others > UINT32_MAX) {
      throw std::length_error("wide BVH: too many primitives listed by id in the leaves");
    }
    m_out.leaves.blocks.reserve(blocks);
    m_out.leaves.others.assign(mixed + others, 0);
    m_mixed_end = 0;
    m_others_end = static_cast<std::uint32_t>(mixed);
  }

  static WideBvhNode<W> empty_node() {
    WideBvhNode<W> n{};
    for (int a = 0; a < 3; ++a) {
      for (int i = 0; i < W; ++i) {
        n.lo[a][i] = INFINITY;
        n.hi[a][i] = -INFINITY;
      }
    }
    return n;
  }

  // Stores the references of binary leaf `b` (triangles into blocks, the rest into `others`);
  // returns the `child` and `count` of its slot.
  std::pair<std::uint32_t, std::uint32_t> pack_leaf(const BvhNode& b) {
    WideBvhLeaves& leaves = m_out.leaves;
    const LeafSplit split = split_of(b);
    const auto first_block = static_cast<std::uint32_t>(leaves.blocks.size());
    std::uint32_t* ids = nullptr;  // where this leaf's other ids go
    std::pair<std::uint32_t, std::uint32_t> slot{first_block, split.blocks()};
    if (split.mixed()) {
      leaves.others[m_mixed_end] = split.other_ids;  // the header
      slot.second |= WideBvhLeaves::kHasOthers | m_mixed_end << WideBvhLeaves::kBlockBits;
      ids = &leaves.others[m_mixed_end + 1];
      m_mixed_end += 1 + split.other_ids;
    } else if (split.other_ids != 0) {
      if (split.other_ids > WideBvhLeaves::kMaxOthersField) {
        throw std::length_error("wide BVH: a leaf with too many primitives");
      }
      slot = {m_others_end, WideBvhLeaves::kHasOthers | split.other_ids << WideBvhLeaves::kBlockBits};
      ids = &leaves.others[m_others_end];
      m_others_end += split.other_ids;
    }
    std::uint32_t lane = 0;
    for (std::uint32_t i = 0; i < b.count; ++i) {
      const std::uint32_t id = m_tree.prim(b.first + i);
      if (is_triangle(id) && lane < split.block_triangles) {
        if (lane % 4 == 0) leaves.blocks.push_back(empty_triangle_block());
        leaves.blocks.back().id[lane % 4] = id;  // vertices: fill_blocks
        ++lane;
      } else {
        *ids++ = id;  // tested through the Geometry
      }
    }
    return slot;
  }

  // Copies every block's triangles in by their ids, in parallel: the ids come in build order,
  // so this is a gather from all over the triangle array (on spd:mount at 2M triangles 30 ms on
  // one thread and 16 on two, next to the 115 ms of the sequential walk before it).
  void fill_blocks() {
    std::vector<TriangleBlock4>& blocks = m_out.leaves.blocks;
    const std::vector<Triangle>& triangles = m_geometry.triangles;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t b = r.begin(); b < r.end(); ++b) {
                          TriangleBlock4& block = blocks[b];
                          for (int lane = 0; lane < 4; ++lane) {
                            const std::uint32_t id = block.id[lane];
                            if (id != TriangleBlock4::kNoPrimitive) block.set(lane, triangles[id], id);
                          }
                          block.repeat_first_lane();
                        }
                      });
  }

  // Puts binary node `binary_index` into slot `slot` of wide node `wide`: its box and, for a
  // leaf, its content (an interior child's index is filled in by the caller).
  void place(std::size_t wide, int slot, std::uint32_t binary_index, int depth) {
    const BvhNode& b = m_tree.nodes[binary_index];
    for (int a = 0; a < 3; ++a) {
      m_out.nodes[wide].lo[a][slot] = b.lo[a];
      m_out.nodes[wide].hi[a][slot] = b.hi[a];
    }
    if (b.is_leaf()) {
      const auto [child, count] = pack_leaf(b);
      m_out.nodes[wide].child[slot] = child;
      m_out.nodes[wide].count[slot] = count;
      ++m_out.leaf_count;
      m_out.max_depth = std::max(m_out.max_depth, depth);
    }
  }

  // Converts binary interior node `binary_index`, whose children sit at wide depth `depth`;
  // returns its index.
  std::uint32_t convert(std::uint32_t binary_index, int depth) {
    const auto index = static_cast<std::uint32_t>(m_out.nodes.size());
    m_out.nodes.push_back(empty_node());
    const BvhNode& b = m_tree.nodes[binary_index];
    std::uint32_t children[W] = {b.first, b.first + 1};
    int n = 2;
    while (n < W) {
      // Open the interior child of largest area: it is the one most rays would enter.
      int pick = -1;
      float best = -1.f;
      for (int i = 0; i < n; ++i) {
        const BvhNode& c = m_tree.nodes[children[i]];
        if (!c.is_leaf() && node_area(c) > best) {
          best = node_area(c);
          pick = i;
        }
      }
      if (pick < 0) break;
      const std::uint32_t opened = m_tree.nodes[children[pick]].first;
      children[pick] = opened;
      children[n++] = opened + 1;
    }
    for (int i = 0; i < n; ++i) {
      place(index, i, children[i], depth);
      if (!m_tree.nodes[children[i]].is_leaf()) {
        const std::uint32_t wide_child = convert(children[i], depth + 1);  // may reallocate
        m_out.nodes[index].child[i] = wide_child;
      }
    }
    return index;
  }

  const BinarySource<PrimOf>& m_tree;
  const Geometry& m_geometry;
  WideBvhTree<W> m_out;
  std::uint32_t m_mixed_end = 0;   // end of the `others` written by leaves holding both kinds
  std::uint32_t m_others_end = 0;  // end of the `others` written by leaves holding others only
};

}  // namespace

template <int W>
WideBvhTree<W> collapse_to_wide(const BvhTree& tree, const Geometry& geometry) {
  const std::uint32_t* ids = tree.prim_ids.data();
  auto prim = [ids](std::size_t i) { return ids[i]; };
  const BinarySource<decltype(prim)> source{tree.nodes.data(), tree.nodes.size(), tree.prim_ids.empty(), prim};
  return WideCollapser<W, decltype(prim)>(source, geometry).run();
}

template <int W>
WideBvhTree<W> collapse_to_wide(const UnorderedBvh& tree, const Geometry& geometry) {
  const bvh_build::BuildRef* refs = tree.refs.get();
  auto prim = [refs](std::size_t i) { return refs[i].id; };
  const BinarySource<decltype(prim)> source{tree.nodes.get(), tree.node_count, tree.node_count == 0, prim};
  return WideCollapser<W, decltype(prim)>(source, geometry).run();
}

template WideBvhTree<4> collapse_to_wide<4>(const BvhTree&, const Geometry&);
template WideBvhTree<8> collapse_to_wide<8>(const BvhTree&, const Geometry&);
template WideBvhTree<16> collapse_to_wide<16>(const BvhTree&, const Geometry&);
template WideBvhTree<4> collapse_to_wide<4>(const UnorderedBvh&, const Geometry&);
template WideBvhTree<8> collapse_to_wide<8>(const UnorderedBvh&, const Geometry&);
template WideBvhTree<16> collapse_to_wide<16>(const UnorderedBvh&, const Geometry&);

}  // namespace raylab
