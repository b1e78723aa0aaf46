// Collapsing the binary BVH into W-wide nodes, with leaves' triangles packed in blocks of four
// and their other primitives listed by id.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

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

// What the leaves of a binary subtree take in the wide tree's leaf arrays: it is the same
// whichever way the subtree is collapsed, so it tells a subtree where its leaves start before
// those to its left are written.
struct SubtreeLeaves {
  std::uint32_t leaves = 0;  // binary leaves
  std::uint32_t blocks = 0;  // triangle blocks
  std::uint64_t mixed = 0;   // entries (headers and ids) of leaves holding both kinds
  std::uint64_t others = 0;  // ids of leaves holding other kinds only

  SubtreeLeaves& operator+=(const SubtreeLeaves& o) {
    leaves += o.leaves;
    blocks += o.blocks;
    mixed += o.mixed;
    others += o.others;
    return *this;
  }
};

// Where the next leaf's content goes: its first block, and its first entry in each region of
// `others` (leaves holding both kinds first, then those holding others only).
struct LeafCursor {
  std::uint32_t block = 0;
  std::uint64_t mixed = 0;
  std::uint64_t others = 0;

  void advance(const SubtreeLeaves& s) {
    block += s.blocks;
    mixed += s.mixed;
    others += s.others;
  }
};

// Subtrees with less leaf content than this (blocks plus ids) are collapsed by one task each;
// above it, nodes are collapsed on the calling thread (a few hundred on a 2M-triangle mesh).
constexpr std::uint64_t kFragmentWork = 4096;
// The leaf sums of subtrees with at least this much work are kept for the top of the tree (the
// slots of its nodes, up to W - 1 levels below them); smaller ones are summed again if needed.
constexpr std::uint64_t kKeptSumWork = 64;
// Binary nodes down to this depth sum their subtrees' leaves in parallel tasks.
constexpr int kParallelSumDepth = 10;

// Whether slot `i` of `node` holds an interior child: count 0 and a child other than 0 (index 0
// is a tree's root, never a child; empty slots hold 0).
template <int W>
bool is_interior_slot(const WideBvhNode<W>& node, int i) {
  return node.count[i] == 0 && node.child[i] != 0;
}

template <int W, class PrimOf>
class WideCollapser {
 public:
  // `ids`: the primitives the tree was built over.
  WideCollapser(const BinarySource<PrimOf>& tree, const Geometry& geometry, std::span<const std::uint32_t> ids)
      : m_tree(tree), m_geometry(geometry), m_ids(ids) {}

  // The collapse runs in three steps. The leaves of the binary subtrees are summed (in parallel;
  // kept for the nodes the next step needs). The top of the tree (subtrees above kFragmentWork)
  // is collapsed on this thread, which cuts the rest into fragments, each then collapsed
  // depth first by a task into its own nodes, its leaves written in place from where the sums
  // say they start. The fragments are copied after one another in depth-first order. The
  // result is the sequential depth-first collapse, whatever the number of threads.
  WideBvhTree<W> run() {
    WideBvhLeaves& leaves = m_out.leaves;
    leaves.triangle_count = static_cast<std::uint32_t>(m_geometry.triangles.size());
    // Before any leaf is packed: the leaves' cylinder lanes are copied from the frames.
    leaves.cylinder_frames = CylinderFrames::of(m_geometry, m_ids);
    if (m_tree.empty) {
      m_out.nodes.push_back(empty_node());  // nothing to hold: every slot empty
      return std::move(m_out);
    }
    m_all_triangles = m_geometry.size() == m_geometry.triangles.size() && m_geometry.groups.empty();
    m_sums.reset(new SubtreeLeaves[m_tree.node_count]);  // not written: only the entries marked in m_summed are
    m_summed.assign(m_tree.node_count, 0);
    const SubtreeLeaves all = sum_subtree(0, 0);
    if (all.mixed > WideBvhLeaves::kMaxOthersField || all.mixed + all.others > UINT32_MAX) {
      throw std::length_error("wide BVH: too many primitives listed by id in the leaves");
    }
    leaves.blocks.resize(all.blocks);  // not written here: each block is written once, by its leaf
    leaves.others.assign(all.mixed + all.others, 0);
    if (!m_geometry.spheres.empty() && !leaves.others.empty()) {
      // Radius 0 (never hit) wherever pack_leaf writes no sphere; 3 floats of padding.
      for (auto* lane : {&leaves.sphere_x, &leaves.sphere_y, &leaves.sphere_z, &leaves.sphere_radius}) {
        lane->assign(leaves.others.size() + 3, 0.f);
      }
    }
    if (!m_geometry.cylinders.empty()) leaves.cylinder_lanes.assign(leaves.others.size());
    leaves.leaf_kinds.assign(leaves.others.size(), {});
    m_out.leaf_count = all.leaves;
    const LeafCursor start{0, 0, all.mixed};
    if (m_tree.nodes[0].is_leaf()) {
      m_out.nodes.push_back(empty_node());
      LeafCursor at = start;
      set_slot(m_out.nodes[0], 0, 0, at);  // a single leaf: slot 0 of the only node
      return std::move(m_out);
    }
    visit(0, 0, start, all);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m_fragments.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t f = r.begin(); f < r.end(); ++f) collapse_fragment(m_fragments[f]);
                      });
    assemble();
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
    // What the leaf takes in the leaf arrays.
    SubtreeLeaves usage() const {
      SubtreeLeaves s;
      s.leaves = 1;
      s.blocks = blocks();
      if (mixed()) {
        s.mixed = 1 + other_ids;  // a header, then the ids
      } else {
        s.others = other_ids;
      }
      return s;
    }
  };

  // A subtree collapsed by one task: its wide nodes, indexed from its root at 0.
  struct Fragment {
    std::uint32_t binary_root;
    int depth;  // the wide depth of its root
    LeafCursor at;
    std::uint32_t leaves;  // binary leaves
    UninitializedVector<WideBvhNode<W>> nodes;
    int max_depth = 0;
  };

  // One piece of the final node array, in depth-first order: a node of the top, or a fragment.
  struct Piece {
    bool fragment;
    std::uint32_t index;  // into m_top or m_fragments
  };

  // The split of binary leaf `b`.
  LeafSplit split_of(const BvhNode& b) const {
    if (m_all_triangles) return {b.count, 0};  // no need to look at the ids
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
  bool is_sphere(std::uint32_t id) const { return id - m_out.leaves.triangle_count < m_geometry.spheres.size(); }

  static std::uint64_t work(const SubtreeLeaves& s) { return s.blocks + s.mixed + s.others; }

  // The leaves of the subtree of binary node `b` at binary depth `depth`, kept (in m_sums,
  // marked in m_summed) for subtrees of kKeptSumWork or more: the top of the tree needs them,
  // the fragments do not.
  SubtreeLeaves sum_subtree(std::uint32_t b, int depth) {
    const BvhNode& node = m_tree.nodes[b];
    if (node.is_leaf()) {
      const LeafSplit split = split_of(node);
      if (!split.mixed() && split.other_ids > WideBvhLeaves::kMaxOthersField) {
        throw std::length_error("wide BVH: a leaf with too many primitives");
      }
      return split.usage();
    }
    SubtreeLeaves left, right;
    if (depth < kParallelSumDepth) {
      tbb::parallel_invoke([&] { left = sum_subtree(node.first, depth + 1); },
                           [&] { right = sum_subtree(node.first + 1, depth + 1); });
    } else {
      left = sum_subtree(node.first, depth + 1);
      right = sum_subtree(node.first + 1, depth + 1);
    }
    SubtreeLeaves s = left;
    s += right;
    if (work(s) >= kKeptSumWork) {
      m_sums[b] = s;
      m_summed[b] = 1;
    }
    return s;
  }

  // The leaves of the subtree of binary node `b`: kept, or summed again (a small subtree, below
  // a node opened for its area rather than its size).
  SubtreeLeaves sums_of(std::uint32_t b) { return m_summed[b] != 0 ? m_sums[b] : sum_subtree(b, kParallelSumDepth); }

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

  // The binary nodes that become the slots of the wide node made from binary interior node
  // `b`: its two children, then, while there is room, the interior one of largest area is
  // replaced by its own two (it is the one most rays would enter). Returns their number.
  int open_children(const BvhNode& b, std::uint32_t children[W]) const {
    float area[W];  // an interior candidate's area; -inf for a leaf, which is never opened
    auto add = [&](int i, std::uint32_t index) {
      children[i] = index;
      const BvhNode& c = m_tree.nodes[index];
      area[i] = c.is_leaf() ? -INFINITY : node_area(c);
    };
    add(0, b.first);
    add(1, b.first + 1);
    int n = 2;
    while (n < W) {
      int pick = -1;
      float best = -1.f;
      for (int i = 0; i < n; ++i) {
        if (area[i] > best) {
          best = area[i];
          pick = i;
        }
      }
      if (pick < 0) break;
      const std::uint32_t opened = m_tree.nodes[children[pick]].first;
      add(pick, opened);
      add(n++, opened + 1);
    }
    return n;
  }

  // Puts binary node `b` into slot `i` of `node`: its box and, for a leaf, its content, stored
  // at `at`, which moves past it (an interior child's index is filled in by the caller).
  void set_slot(WideBvhNode<W>& node, int i, std::uint32_t b, LeafCursor& at) {
    const BvhNode& bn = m_tree.nodes[b];
    for (int a = 0; a < 3; ++a) {
      node.lo[a][i] = bn.lo[a];
      node.hi[a][i] = bn.hi[a];
    }
    if (bn.is_leaf()) {
      const auto [child, count] = pack_leaf(bn, at);
      node.child[i] = child;
      node.count[i] = count;
    }
  }

  // Stores the references of binary leaf `b` at `at` (triangles into blocks, the rest into
  // `others`), and moves `at` past them; returns the `child` and `count` of its slot.
  std::pair<std::uint32_t, std::uint32_t> pack_leaf(const BvhNode& b, LeafCursor& at) {
    WideBvhLeaves& leaves = m_out.leaves;
    const LeafSplit split = split_of(b);
    std::uint32_t* ids = nullptr;  // where this leaf's other ids go
    std::pair<std::uint32_t, std::uint32_t> slot{at.block, split.blocks()};
    if (split.mixed()) {
      const auto header = static_cast<std::uint32_t>(at.mixed);
      leaves.others[header] = split.other_ids;
      slot.second |= WideBvhLeaves::kHasOthers | header << WideBvhLeaves::kBlockBits;
      ids = &leaves.others[header + 1];
    } else if (split.other_ids != 0) {
      slot = {static_cast<std::uint32_t>(at.others),
              WideBvhLeaves::kHasOthers | split.other_ids << WideBvhLeaves::kBlockBits};
      ids = &leaves.others[at.others];
    }
    TriangleBlock4* block = leaves.blocks.data() + at.block;
    std::uint32_t* const listed = ids;
    std::uint32_t lane = 0;
    for (std::uint32_t i = 0; i < b.count; ++i) {
      const std::uint32_t id = m_tree.prim(b.first + i);
      if (is_triangle(id) && lane < split.block_triangles) {
        if (lane % 4 == 0) block[lane / 4] = empty_triangle_block();
        block[lane / 4].set(static_cast<int>(lane % 4), m_geometry.triangles[id], id);
        ++lane;
      } else {
        *ids++ = id;  // tested through the Geometry
      }
    }
    // The spheres first, in leaf order, so that the traversal finds them as one run of lanes,
    // and their copies beside their ids.
    std::uint32_t* const spheres_end =
        std::stable_partition(listed, ids, [&](std::uint32_t id) { return is_sphere(id); });
    for (const std::uint32_t* p = listed; p < spheres_end; ++p) {
      const Sphere& s = m_geometry.spheres[*p - leaves.triangle_count];
      const auto at = static_cast<std::size_t>(p - leaves.others.data());
      leaves.sphere_x[at] = s.center.x;
      leaves.sphere_y[at] = s.center.y;
      leaves.sphere_z[at] = s.center.z;
      leaves.sphere_radius[at] = s.radius;
    }
    // Then the cylinders (the ids with a frame), with their rejection data beside their ids.
    std::uint32_t* const cylinders_end = std::stable_partition(
        spheres_end, ids, [&](std::uint32_t id) { return leaves.cylinder_frame_of(id) != nullptr; });
    for (const std::uint32_t* p = spheres_end; p < cylinders_end; ++p) {
      leaves.cylinder_lanes.set(static_cast<std::size_t>(p - leaves.others.data()), *leaves.cylinder_frame_of(*p));
    }
    if (ids != listed) {
      const auto saturated = [](std::ptrdiff_t n) {
        return static_cast<std::uint8_t>(std::min<std::ptrdiff_t>(n, WideBvhLeaves::kKindCountSaturated));
      };
      leaves.leaf_kinds[static_cast<std::size_t>(listed - leaves.others.data())] = {
          saturated(spheres_end - listed), saturated(cylinders_end - spheres_end)};
    }
    for (std::uint32_t k = 0; k < split.blocks(); ++k) block[k].repeat_first_lane();
    at.advance(split.usage());
    return slot;
  }

  // Collapses the top of the tree from binary interior node `b` (its children at wide depth
  // `depth`, its leaves from `at`, `sums` its subtree's leaves): a subtree small enough becomes
  // a fragment, a larger one a node of m_top whose interior slots hold, until `assemble`, the
  // piece of their child. Returns the piece of `b`.
  std::uint32_t visit(std::uint32_t b, int depth, const LeafCursor& at, const SubtreeLeaves& sums) {
    const auto piece = static_cast<std::uint32_t>(m_pieces.size());
    if (work(sums) < kFragmentWork) {
      m_pieces.push_back({true, static_cast<std::uint32_t>(m_fragments.size())});
      m_fragments.push_back({b, depth, at, sums.leaves, {}, 0});
      return piece;
    }
    const auto index = static_cast<std::uint32_t>(m_top.size());
    m_pieces.push_back({false, index});
    m_top.push_back(empty_node());
    std::uint32_t children[W];
    const int n = open_children(m_tree.nodes[b], children);
    LeafCursor next = at;  // where the leaves of slot i start
    for (int i = 0; i < n; ++i) {
      const LeafCursor slot_start = next;
      set_slot(m_top[index], i, children[i], next);  // a leaf moves `next` past itself
      if (m_tree.nodes[children[i]].is_leaf()) {
        m_top_max_depth = std::max(m_top_max_depth, depth);
      } else {
        const SubtreeLeaves child_sums = sums_of(children[i]);
        next.advance(child_sums);
        const std::uint32_t child = visit(children[i], depth + 1, slot_start, child_sums);  // may reallocate m_top
        m_top[index].child[i] = child;
      }
    }
    return piece;
  }

  void collapse_fragment(Fragment& f) {
    f.nodes.reserve(f.leaves / (W - 1) + 1);
    LeafCursor at = f.at;
    collapse_local(f, f.binary_root, f.depth, at);
  }

  // Collapses binary interior node `b` into fragment `f` (its children at wide depth `depth`),
  // its leaves stored from `at` on in depth-first order; returns its index in the fragment.
  std::uint32_t collapse_local(Fragment& f, std::uint32_t b, int depth, LeafCursor& at) {
    const auto index = static_cast<std::uint32_t>(f.nodes.size());
    f.nodes.push_back(empty_node());
    std::uint32_t children[W];
    const int n = open_children(m_tree.nodes[b], children);
    for (int i = 0; i < n; ++i) {
      set_slot(f.nodes[index], i, children[i], at);
      if (m_tree.nodes[children[i]].is_leaf()) {
        f.max_depth = std::max(f.max_depth, depth);
      } else {
        const std::uint32_t child = collapse_local(f, children[i], depth + 1, at);  // may reallocate
        f.nodes[index].child[i] = child;
      }
    }
    return index;
  }

  // Lays the pieces out one after another in depth-first order, and turns the top's piece
  // numbers and the fragments' own indices into indices of the whole array.
  void assemble() {
    std::vector<std::uint32_t> first(m_pieces.size());
    std::size_t total = 0;
    for (std::size_t p = 0; p < m_pieces.size(); ++p) {
      first[p] = static_cast<std::uint32_t>(total);
      total += m_pieces[p].fragment ? m_fragments[m_pieces[p].index].nodes.size() : 1;
    }
    if (total > UINT32_MAX) throw std::length_error("wide BVH: too many nodes");
    m_out.nodes.resize(total);  // not written here: every node is copied in below
    WideBvhNode<W>* out = m_out.nodes.data();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m_pieces.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t p = r.begin(); p < r.end(); ++p) {
                          const Piece piece = m_pieces[p];
                          if (piece.fragment) {
                            const Fragment& f = m_fragments[piece.index];
                            std::copy(f.nodes.begin(), f.nodes.end(), out + first[p]);
                            for (std::size_t k = 0; k < f.nodes.size(); ++k) {
                              WideBvhNode<W>& node = out[first[p] + k];
                              for (int i = 0; i < W; ++i) {
                                if (is_interior_slot(node, i)) node.child[i] += first[p];  // own index to global
                              }
                            }
                          } else {
                            WideBvhNode<W>& node = out[first[p]];
                            node = m_top[piece.index];
                            for (int i = 0; i < W; ++i) {
                              if (is_interior_slot(node, i)) node.child[i] = first[node.child[i]];  // piece to index
                            }
                          }
                        }
                      });
    m_out.max_depth = m_top_max_depth;
    for (const Fragment& f : m_fragments) m_out.max_depth = std::max(m_out.max_depth, f.max_depth);
  }

  const BinarySource<PrimOf>& m_tree;
  const Geometry& m_geometry;
  std::span<const std::uint32_t> m_ids;
  WideBvhTree<W> m_out;
  bool m_all_triangles = false;             // the geometry holds triangles only
  std::unique_ptr<SubtreeLeaves[]> m_sums;  // per binary node, where m_summed is set
  std::vector<std::uint8_t> m_summed;
  std::vector<WideBvhNode<W>> m_top;  // the nodes above the fragments
  std::vector<Fragment> m_fragments;
  std::vector<Piece> m_pieces;  // depth-first order
  int m_top_max_depth = 0;
};

}  // namespace

template <int W>
WideBvhTree<W> collapse_to_wide(const BvhTree& tree, const Geometry& geometry) {
  const std::uint32_t* ids = tree.prim_ids.data();
  auto prim = [ids](std::size_t i) { return ids[i]; };
  const BinarySource<decltype(prim)> source{tree.nodes.data(), tree.nodes.size(), tree.prim_ids.empty(), prim};
  return WideCollapser<W, decltype(prim)>(source, geometry, tree.prim_ids).run();
}

template <int W>
WideBvhTree<W> collapse_to_wide(const UnorderedBvh& tree, const Geometry& geometry,
                                std::span<const std::uint32_t> ids) {
  const bvh_build::BuildRef* refs = tree.refs.data();
  auto prim = [refs](std::size_t i) { return refs[i].id; };
  const BinarySource<decltype(prim)> source{tree.nodes.data(), tree.node_count, tree.node_count == 0, prim};
  return WideCollapser<W, decltype(prim)>(source, geometry, ids).run();
}

template WideBvhTree<4> collapse_to_wide<4>(const BvhTree&, const Geometry&);
template WideBvhTree<8> collapse_to_wide<8>(const BvhTree&, const Geometry&);
template WideBvhTree<16> collapse_to_wide<16>(const BvhTree&, const Geometry&);
template WideBvhTree<4> collapse_to_wide<4>(const UnorderedBvh&, const Geometry&, std::span<const std::uint32_t>);
template WideBvhTree<8> collapse_to_wide<8>(const UnorderedBvh&, const Geometry&, std::span<const std::uint32_t>);
template WideBvhTree<16> collapse_to_wide<16>(const UnorderedBvh&, const Geometry&, std::span<const std::uint32_t>);

}  // namespace raylab
