// Collapsing the binary BVH into 4-wide nodes.

#include <algorithm>
#include <cmath>

#include "raylab/accel/bvh4.h"

namespace raylab {
namespace {

float node_area(const BvhNode& n) {
  const float ex = n.hi[0] - n.lo[0], ey = n.hi[1] - n.lo[1], ez = n.hi[2] - n.lo[2];
  return 2.f * (ex * ey + ey * ez + ez * ex);
}

class Collapser {
 public:
  explicit Collapser(const BvhTree& tree) : m_tree(tree) {}

  std::vector<Bvh4Node> run() {
    m_out.reserve(m_tree.nodes.size() / 2 + 1);
    m_out.push_back(empty_node());
    if (m_tree.prim_ids.empty()) return std::move(m_out);  // nothing to hold: four empty slots
    if (m_tree.nodes[0].is_leaf()) {
      place(m_out[0], 0, 0);  // a single leaf: slot 0 of the only node
      return std::move(m_out);
    }
    m_out.clear();
    convert(0);
    return std::move(m_out);
  }

 private:
  static Bvh4Node empty_node() {
    Bvh4Node n{};
    for (int a = 0; a < 3; ++a) {
      for (int i = 0; i < 4; ++i) {
        n.lo[a][i] = INFINITY;
        n.hi[a][i] = -INFINITY;
      }
    }
    return n;
  }

  // Puts binary node `binary_index` into slot `slot` of `wide`: its box, and either its leaf
  // range or (filled in later by the caller) its wide node index.
  void place(Bvh4Node& wide, int slot, std::uint32_t binary_index) {
    const BvhNode& b = m_tree.nodes[binary_index];
    for (int a = 0; a < 3; ++a) {
      wide.lo[a][slot] = b.lo[a];
      wide.hi[a][slot] = b.hi[a];
    }
    wide.child[slot] = b.first;
    wide.count[slot] = b.count;  // 0 for an interior node
  }

  // Converts the binary interior node `binary_index`; returns the index of its wide node.
  std::uint32_t convert(std::uint32_t binary_index) {
    const auto index = static_cast<std::uint32_t>(m_out.size());
    m_out.push_back(empty_node());
    const BvhNode& b = m_tree.nodes[binary_index];
    std::uint32_t children[4] = {b.first, b.first + 1, 0, 0};
    int n = 2;
    while (n < 4) {
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
      place(m_out[index], i, children[i]);
      if (!m_tree.nodes[children[i]].is_leaf()) {
        const std::uint32_t wide_child = convert(children[i]);  // may reallocate m_out
        m_out[index].child[i] = wide_child;
      }
    }
    return index;
  }

  const BvhTree& m_tree;
  std::vector<Bvh4Node> m_out;
};

}  // namespace

std::vector<Bvh4Node> collapse_to_bvh4(const BvhTree& tree) { return Collapser(tree).run(); }

}  // namespace raylab
