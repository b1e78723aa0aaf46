// Binned SAH construction (Wald 2007) of a binary BVH, parallel over subtrees with oneTBB.

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>

#include "raylab/accel/bvh.h"

namespace raylab {
namespace {

// Beyond this depth splits fall back to the object median, which halves the count each level:
// a bound on depth that keeps traversal stacks (128 entries) from overflowing on pathological
// inputs such as sizes spread over many orders of magnitude.
constexpr int kMedianFallbackDepth = 64;
constexpr int kMaxBins = 64;

struct PrimInfo {
  Box3 box;
  Vec3 centroid;
};

struct Bin {
  Box3 box;
  std::uint32_t count = 0;
};

struct Split {
  int axis = -1;
  int bin = 0;  // primitives in bins [0, bin) go left
  float cost = INFINITY;
};

class Builder {
 public:
  Builder(const std::vector<PrimInfo>& prims, const BvhConfig& config, BvhTree& tree)
      : m_prims(prims), m_config(config), m_tree(tree) {
    m_bins = std::clamp(config.bin_count, 2, kMaxBins);
  }

  void build() {
    const std::size_t n = m_prims.size();
    m_tree.prim_ids.resize(n);
    std::iota(m_tree.prim_ids.begin(), m_tree.prim_ids.end(), 0u);
    m_tree.nodes.resize(std::max<std::size_t>(1, 2 * n));
    m_next_node.store(1);
    build_node(0, 0, static_cast<std::uint32_t>(n), 0);
    m_tree.nodes.resize(m_next_node.load());
    m_tree.max_depth = m_max_depth.load();
    m_tree.leaf_count = m_leaf_count.load();
  }

 private:
  void make_leaf(BvhNode& node, std::uint32_t begin, std::uint32_t end, int depth) {
    node.first = begin;
    node.count = end - begin;
    m_leaf_count.fetch_add(1, std::memory_order_relaxed);
    int seen = m_max_depth.load(std::memory_order_relaxed);
    while (depth > seen && !m_max_depth.compare_exchange_weak(seen, depth)) {
    }
  }

  void build_node(std::uint32_t index, std::uint32_t begin, std::uint32_t end, int depth) {
    BvhNode& node = m_tree.nodes[index];
    Box3 box, centroids;
    for (std::uint32_t i = begin; i < end; ++i) {
      const PrimInfo& p = m_prims[m_tree.prim_ids[i]];
      box.extend(p.box);
      centroids.extend(p.centroid);
    }
    for (int a = 0; a < 3; ++a) {
      node.lo[a] = box.lo[a];
      node.hi[a] = box.hi[a];
    }
    const std::uint32_t count = end - begin;
    if (count <= 1) {
      make_leaf(node, begin, end, depth);
      return;
    }

    std::uint32_t mid = begin;
    if (depth < kMedianFallbackDepth) {
      const Split split = find_split(begin, end, box, centroids);
      const float leaf_cost = m_config.intersection_cost * static_cast<float>(count);
      if (split.axis < 0 || (split.cost >= leaf_cost && count <= static_cast<std::uint32_t>(m_config.max_leaf_size))) {
        if (split.axis < 0 && count > static_cast<std::uint32_t>(m_config.max_leaf_size)) {
          mid = begin + count / 2;  // all centroids coincide: any halving is as good as another
        } else {
          make_leaf(node, begin, end, depth);
          return;
        }
      } else {
        const float lo = centroids.lo[split.axis];
        const float scale = m_bins / (centroids.hi[split.axis] - lo);
        auto* ids = m_tree.prim_ids.data();
        mid = static_cast<std::uint32_t>(std::partition(ids + begin, ids + end,
                                                        [&](std::uint32_t id) {
                                                          return bin_of(m_prims[id].centroid[split.axis], lo, scale) <
                                                                 split.bin;
                                                        }) -
                                         ids);
        if (mid == begin || mid == end) mid = begin + count / 2;  // rounding put all on one side
      }
    } else {
      const int axis = max_axis(centroids.extent());
      mid = begin + count / 2;
      auto* ids = m_tree.prim_ids.data();
      std::nth_element(ids + begin, ids + mid, ids + end, [&](std::uint32_t a, std::uint32_t b) {
        return m_prims[a].centroid[axis] < m_prims[b].centroid[axis];
      });
    }

    const std::uint32_t left = m_next_node.fetch_add(2, std::memory_order_relaxed);
    node.first = left;
    node.count = 0;
    if (count >= static_cast<std::uint32_t>(m_config.parallel_threshold)) {
      tbb::parallel_invoke([&] { build_node(left, begin, mid, depth + 1); },
                           [&] { build_node(left + 1, mid, end, depth + 1); });
    } else {
      build_node(left, begin, mid, depth + 1);
      build_node(left + 1, mid, end, depth + 1);
    }
  }

  int bin_of(float c, float lo, float scale) const {
    return std::clamp(static_cast<int>((c - lo) * scale), 0, m_bins - 1);
  }

  // Evaluates every bin boundary on every axis; cost is relative to the parent's area.
  Split find_split(std::uint32_t begin, std::uint32_t end, const Box3& parent, const Box3& centroids) const {
    Split best;
    const float parent_area = parent.area();
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = centroids.hi[axis] - centroids.lo[axis];
      if (!(extent > 0.f)) continue;
      Bin bins[kMaxBins];
      const float lo = centroids.lo[axis];
      const float scale = m_bins / extent;
      for (std::uint32_t i = begin; i < end; ++i) {
        const PrimInfo& p = m_prims[m_tree.prim_ids[i]];
        Bin& b = bins[bin_of(p.centroid[axis], lo, scale)];
        b.box.extend(p.box);
        ++b.count;
      }
      // Sweep from the right to get the area and count right of each boundary.
      float right_area[kMaxBins];
      std::uint32_t right_count[kMaxBins];
      Box3 acc;
      std::uint32_t n = 0;
      for (int b = m_bins - 1; b > 0; --b) {
        acc.extend(bins[b].box);
        n += bins[b].count;
        right_area[b] = acc.area();
        right_count[b] = n;
      }
      acc = Box3{};
      n = 0;
      for (int b = 1; b < m_bins; ++b) {
        acc.extend(bins[b - 1].box);
        n += bins[b - 1].count;
        if (n == 0 || right_count[b] == 0) continue;
        const float cost =
            m_config.traversal_cost +
            m_config.intersection_cost *
                (acc.area() * static_cast<float>(n) + right_area[b] * static_cast<float>(right_count[b])) / parent_area;
        if (cost < best.cost) best = {axis, b, cost};
      }
    }
    if (!(parent_area > 0.f) && best.axis >= 0) best.cost = 0.f;  // flat: any valid split helps
    return best;
  }

  const std::vector<PrimInfo>& m_prims;
  const BvhConfig& m_config;
  BvhTree& m_tree;
  int m_bins = 16;
  std::atomic<std::uint32_t> m_next_node{1};
  std::atomic<int> m_max_depth{0};
  std::atomic<std::size_t> m_leaf_count{0};
};

// Rewrites the nodes in depth-first order, siblings kept adjacent: the parallel build hands out
// node slots in whatever order tasks ran, and traversal is faster when a subtree is contiguous.
void relayout_depth_first(BvhTree& tree) {
  decltype(tree.nodes) out;
  out.reserve(tree.nodes.size());
  out.push_back(tree.nodes[0]);
  // (old index, new index) pairs still to copy children for.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{0u, 0u}};
  while (!stack.empty()) {
    const auto [old_index, new_index] = stack.back();
    stack.pop_back();
    const BvhNode& node = tree.nodes[old_index];
    if (node.is_leaf()) continue;
    const auto left = static_cast<std::uint32_t>(out.size());
    out.push_back(tree.nodes[node.first]);
    out.push_back(tree.nodes[node.first + 1]);
    out[new_index].first = left;
    // Push the right child first so the left subtree is laid out right after this pair.
    stack.emplace_back(node.first + 1, left + 1);
    stack.emplace_back(node.first, left);
  }
  tree.nodes = std::move(out);
}

}  // namespace

BvhTree build_bvh(const Geometry& geometry, const BvhConfig& config) {
  return build_bvh(geometry, geometry.primitive_ids(), config);
}

BvhTree build_bvh(const Geometry& geometry, std::span<const std::uint32_t> ids, const BvhConfig& config) {
  BvhTree tree;
  const auto n = static_cast<std::uint32_t>(ids.size());
  if (n == 0) {
    BvhNode empty{};
    for (int a = 0; a < 3; ++a) {
      empty.lo[a] = INFINITY;
      empty.hi[a] = -INFINITY;
    }
    tree.nodes.push_back(empty);  // an empty leaf whose box no ray can enter
    tree.nodes[0].count = 0;
    tree.nodes[0].first = 0;
    return tree;
  }
  std::vector<PrimInfo> prims(n);
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, n, 1024), [&](const auto& range) {
    for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
      prims[i].box = geometry.bounds(ids[i]);
      prims[i].centroid = prims[i].box.center();
    }
  });
  Builder(prims, config, tree).build();
  relayout_depth_first(tree);
  // The builder numbered the references 0..n-1 in `ids` order; hand back the primitives' own ids.
  for (std::uint32_t& ref : tree.prim_ids) ref = ids[ref];
  return tree;
}

double sah_cost(const BvhTree& tree, const BvhConfig& config) {
  auto area = [](const BvhNode& n) {
    const double ex = n.hi[0] - n.lo[0], ey = n.hi[1] - n.lo[1], ez = n.hi[2] - n.lo[2];
    return 2.0 * (ex * ey + ey * ez + ez * ex);
  };
  const double root_area = area(tree.nodes[0]);
  if (!(root_area > 0.0)) return 0.0;
  double cost = 0.0;
  for (const BvhNode& n : tree.nodes) {
    const double rel = area(n) / root_area;
    cost += n.is_leaf() ? rel * config.intersection_cost * n.count : rel * config.traversal_cost;
  }
  return cost;
}

}  // namespace raylab
