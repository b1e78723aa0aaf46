// Collapsing the binary BVH into W-wide nodes with leaves packed in blocks of four triangles.

#include <algorithm>
#include <cmath>

#include "raylab/accel/wide_bvh.h"

namespace raylab {
namespace {

float node_area(const BvhNode& n) {
  const float ex = n.hi[0] - n.lo[0], ey = n.hi[1] - n.lo[1], ez = n.hi[2] - n.lo[2];
  return 2.f * (ex * ey + ey * ez + ez * ex);
}

template <int W>
class WideCollapser {
 public:
  WideCollapser(const BvhTree& tree, const Geometry& geometry) : m_tree(tree), m_geometry(geometry) {}

  WideBvhTree<W> run() {
    m_out.leaves.triangle_count = static_cast<std::uint32_t>(m_geometry.triangles.size());
    m_out.nodes.reserve(m_tree.nodes.size() / (W - 1) + 1);
    m_out.leaves.blocks.reserve(m_tree.prim_ids.size() / 2 + 1);
    if (m_tree.prim_ids.empty()) {
      m_out.nodes.push_back(empty_node());  // nothing to hold: every slot empty
    } else if (m_tree.nodes[0].is_leaf()) {
      m_out.nodes.push_back(empty_node());
      place(0, 0, 0, 0);  // a single leaf: slot 0 of the only node
    } else {
      convert(0, 0);
    }
    return std::move(m_out);
  }

 private:
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

  // Packs the references of binary leaf `b` into blocks; returns the block count and flag.
  std::uint32_t pack_leaf(const BvhNode& b, std::uint32_t& first_block) {
    auto& blocks = m_out.leaves.blocks;
    first_block = static_cast<std::uint32_t>(blocks.size());
    const std::uint32_t tri_count = m_out.leaves.triangle_count;
    bool others = false;
    for (std::uint32_t i = 0; i < b.count; ++i) {
      if (i % 4 == 0) blocks.push_back(empty_triangle_block());
      const std::uint32_t id = m_tree.prim_ids[b.first + i];
      TriangleBlock4& block = blocks.back();
      if (id < tri_count) {
        block.set(static_cast<int>(i % 4), m_geometry.triangles[id], id);
      } else {
        block.id[i % 4] = id;  // tested through the Geometry; its lane keeps degenerate vertices
        others = true;
      }
    }
    const auto count = static_cast<std::uint32_t>(blocks.size()) - first_block;
    return count | (others ? WideBvhNode<W>::kLeafHasOthers : 0u);
  }

  // Puts binary node `binary_index` into slot `slot` of wide node `wide`: its box and, for a
  // leaf, its blocks (an interior child's index is filled in by the caller).
  void place(std::size_t wide, int slot, std::uint32_t binary_index, int depth) {
    const BvhNode& b = m_tree.nodes[binary_index];
    for (int a = 0; a < 3; ++a) {
      m_out.nodes[wide].lo[a][slot] = b.lo[a];
      m_out.nodes[wide].hi[a][slot] = b.hi[a];
    }
    if (b.is_leaf()) {
      std::uint32_t first = 0;
      const std::uint32_t count = pack_leaf(b, first);
      m_out.nodes[wide].child[slot] = first;
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

  const BvhTree& m_tree;
  const Geometry& m_geometry;
  WideBvhTree<W> m_out;
};

}  // namespace

template <int W>
WideBvhTree<W> collapse_to_wide(const BvhTree& tree, const Geometry& geometry) {
  return WideCollapser<W>(tree, geometry).run();
}

template WideBvhTree<4> collapse_to_wide<4>(const BvhTree&, const Geometry&);
template WideBvhTree<8> collapse_to_wide<8>(const BvhTree&, const Geometry&);
template WideBvhTree<16> collapse_to_wide<16>(const BvhTree&, const Geometry&);

}  // namespace raylab
