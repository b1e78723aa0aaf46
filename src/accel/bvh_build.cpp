// Binned SAH construction (Wald 2007) of a binary BVH, parallel on oneTBB, with optional spatial
// splits (bvh_spatial_split.cpp); the split search itself is in bvh_build_sah.cpp.
//
// Where the time goes and why it is laid out so: one 32-byte reference per primitive, sorted in
// place (no index indirection, no copies); one pass bins all three axes at once with 4-wide
// min/max; the children's boxes come from the bins and their centroid bounds from the partition
// pass, so no node rescans its references. Large nodes bin and partition in parallel; subtrees
// above `parallel_threshold` are tasks. The tree is the same whatever the thread count: a node's
// split depends only on its references, merging bins is exact (min, max, integer sums), the
// parallel partition cuts its work into chunks of a constant size (bvh_build_partition.h), and
// the final depth-first relayout removes the order in which tasks took node slots.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

#include "bvh_build_box.h"
#include "bvh_build_partition.h"
#include "bvh_build_ref.h"
#include "bvh_build_sah.h"
#include "bvh_build_unordered.h"
#include "bvh_depth.h"
#include "raylab/accel/bvh.h"
#include "raylab/simd/float4.h"

namespace raylab {
namespace {

using bvh_build::BinMap;
using bvh_build::BinSet;
using bvh_build::Bounds;
using bvh_build::Box4;
using bvh_build::BuildRef;
using bvh_build::CostModel;
using bvh_build::kMaxBins;
using bvh_build::kSmallNode;
using bvh_build::load_hi;
using bvh_build::load_lo;
using bvh_build::ObjectSplit;
using simd::Float4;

using bvh_depth::kMedianFallbackDepth;  // the depth bound the traversal stacks are sized by
// Nodes with at least this many references bin in parallel (the bins merge exactly, so the
// result does not depend on how the range was cut).
constexpr std::uint32_t kParallelBinning = 16384;
// Nodes with at least this many references partition in parallel (bvh_build_partition.h).
constexpr std::uint32_t kParallelPartition = 4 * bvh_build::kPartitionChunk;

// Only nodes with more references than this look for a spatial split.
constexpr std::uint32_t kSpatialSplitMin = 10;

// A node's references [begin, end), and the room up to `capacity` it may fill with the extra
// references of spatial splits (capacity == end without them).
struct Range {
  std::uint32_t begin, end, capacity;
};

class Builder {
 public:
  Builder(const Geometry& geometry, const BvhConfig& config, BuildRef* refs, BvhNode* nodes)
      : m_triangles(geometry.triangles), m_config(config), m_cost(config), m_refs(refs), m_nodes(nodes) {
    m_bins = std::clamp(config.bin_count, 2, kMaxBins);
  }

  // Builds the subtree of node 0 over refs [0, n) with room for references up to `capacity`;
  // returns the number of node slots used.
  std::uint32_t build(std::uint32_t n, std::uint32_t capacity, const Bounds& bounds) {
    m_root_area = area(bounds.box);
    build_node(0, Range{0, n, capacity}, bounds, 0);
    return m_next_node.load();
  }

 private:
  void make_leaf(BvhNode& node, std::uint32_t begin, std::uint32_t end) {
    node.first = begin;
    node.count = end - begin;
  }

  void set_box(BvhNode& node, const Box4& box) {
    const Box3 b = box.box3();
    for (int a = 0; a < 3; ++a) {
      node.lo[a] = b.lo[a];
      node.hi[a] = b.hi[a];
    }
  }

  void bin(std::uint32_t begin, std::uint32_t end, const BinMap& map, BinSet& set) const {
    if (end - begin < kParallelBinning) return set.add(m_refs + begin, end - begin, map);
    set = tbb::parallel_reduce(
        tbb::blocked_range<std::uint32_t>(begin, end, 4096), set,
        [&](const tbb::blocked_range<std::uint32_t>& r, BinSet part) {
          part.add(m_refs + r.begin(), r.end() - r.begin(), map);
          return part;
        },
        [](BinSet a, const BinSet& b) {
          a.merge(b);
          return a;
        });
  }

  // Moves the references of bins [0, split_bin) on the split axis to the front and gathers each
  // side's centroid bounds; large nodes partition in parallel (with a result that does not
  // depend on the thread count), since a sequential pass over them is what keeps the first
  // levels of the tree from using more than one core.
  std::uint32_t partition(std::uint32_t begin, std::uint32_t end, const BinMap& map, int axis, int split_bin,
                          Box4& left_centroids, Box4& right_centroids) {
    const bvh_build::SplitTest test{axis, split_bin, map.lo[axis], map.scale[axis], map.bins, map.hi[axis]};
    const bvh_build::PartitionResult p = end - begin >= kParallelPartition
                                             ? bvh_build::partition_parallel(m_refs + begin, end - begin, test)
                                             : bvh_build::partition_sequential(m_refs + begin, end - begin, test);
    left_centroids = p.left_centroids;
    right_centroids = p.right_centroids;
    return begin + p.mid;
  }

  // Splits [begin, end) at `mid` after ordering by centroid along the widest centroid axis
  // (fallback for too deep nodes and for references whose centroids all coincide).
  std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, const Bounds& bounds, Bounds& left,
                             Bounds& right) {
    const Box3 c = bounds.centroids.box3();
    const int axis = max_axis(c.extent());
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(m_refs + begin, m_refs + mid, m_refs + end, [&](const BuildRef& a, const BuildRef& b) {
      const float ca = a.centroid2(axis), cb = b.centroid2(axis);
      return ca < cb || (ca == cb && a.id < b.id);  // ids break ties, so the order is unique
    });
    left = bounds_of(m_refs + begin, mid - begin);
    right = bounds_of(m_refs + mid, end - mid);
    return mid;
  }

  // Gives the free room of a node after an object split to its children in proportion to their
  // sizes, moving the right references up to make the left child's share.
  void share_room(const Range& node, std::uint32_t mid, Range& left, Range& right) {
    const std::uint32_t left_cap =
        node.begin + bvh_build::left_share(mid - node.begin, node.end - mid, node.capacity - node.begin);
    std::copy_backward(m_refs + mid, m_refs + node.end, m_refs + left_cap + (node.end - mid));
    left = {node.begin, mid, left_cap};
    right = {left_cap, left_cap + (node.end - mid), node.capacity};
  }

  void build_node(std::uint32_t index, const Range& range, const Bounds& bounds, int depth) {
    BvhNode& node = m_nodes[index];
    set_box(node, bounds.box);
    const std::uint32_t begin = range.begin, end = range.end;
    const std::uint32_t count = end - begin;
    if (count <= 1) return make_leaf(node, begin, end);
    const auto max_leaf = static_cast<std::uint32_t>(std::max(1, m_config.max_leaf_size));

    Bounds left_bounds, right_bounds;
    Range left{}, right{};
    bool done = false;  // a spatial split has set the ranges
    std::uint32_t mid = begin;
    if (depth < kMedianFallbackDepth) {
      const BinMap map(bounds.centroids, m_bins);
      const float parent_area = area(bounds.box);
      ObjectSplit split;
      if (count <= kSmallNode) {
        split = small_object_split(m_refs + begin, count, map, parent_area, m_cost);
      } else {
        BinSet bins(m_bins);
        bin(begin, end, map, bins);
        split = best_object_split(bins, parent_area, m_cost);
      }
      bvh_build::SpatialSplit spatial;
      if (m_config.spatial_splits && count > kSpatialSplitMin && range.capacity > end)
        spatial = try_spatial(range, bounds, split);
      const float best_cost = std::min(split.cost, spatial.cost);
      if ((split.axis < 0 && spatial.axis < 0) || (best_cost >= m_cost.leaf(count) && count <= max_leaf)) {
        if (count <= max_leaf) return make_leaf(node, begin, end);
        mid = median_split(begin, end, bounds, left_bounds, right_bounds);  // all centroids coincide
      } else if (spatial.axis >= 0 && spatial.cost < split.cost &&
                 apply_spatial(range, spatial, left_bounds, right_bounds, left, right)) {
        done = true;
      } else if (split.axis >= 0) {
        left_bounds.box = split.left;
        right_bounds.box = split.right;
        mid = partition(begin, end, map, split.axis, split.bin, left_bounds.centroids, right_bounds.centroids);
      } else {
        mid = median_split(begin, end, bounds, left_bounds, right_bounds);
      }
    } else {
      mid = median_split(begin, end, bounds, left_bounds, right_bounds);
    }
    if (!done) {
      if (range.capacity > end) {
        share_room(range, mid, left, right);
      } else {
        left = {begin, mid, mid};
        right = {mid, end, end};
      }
    }

    const std::uint32_t first = m_next_node.fetch_add(2, std::memory_order_relaxed);
    node.first = first;
    node.count = 0;
    if (count >= static_cast<std::uint32_t>(m_config.parallel_threshold)) {
      tbb::parallel_invoke([&] { build_node(first, left, left_bounds, depth + 1); },
                           [&] { build_node(first + 1, right, right_bounds, depth + 1); });
    } else {
      build_node(first, left, left_bounds, depth + 1);
      build_node(first + 1, right, right_bounds, depth + 1);
    }
  }

  // The SBVH rule: a spatial split is worth looking for only where the best object split leaves
  // children that overlap by a noticeable fraction of the root's area.
  bvh_build::SpatialSplit try_spatial(const Range& range, const Bounds& bounds, const ObjectSplit& split) const {
    if (split.axis >= 0) {
      Box4 overlap;
      overlap.lo = max(split.left.lo, split.right.lo);
      overlap.hi = min(split.left.hi, split.right.hi);
      if (!(area(overlap) > m_config.spatial_split_alpha * m_root_area)) return {};
    }
    bvh_build::SpatialSplit s =
        bvh_build::find_spatial_split(std::span<const BuildRef>(m_refs + range.begin, range.end - range.begin),
                                      bounds.box.box3(), m_bins, m_triangles, m_cost);
    if (s.duplicates > range.capacity - range.end) return {};  // over the budget
    return s;
  }

  bool apply_spatial(const Range& range, const bvh_build::SpatialSplit& split, Bounds& left_bounds,
                     Bounds& right_bounds, Range& left, Range& right) {
    bvh_build::SpatialChildren children;
    std::uint32_t right_offset = 0;
    const std::span<BuildRef> space(m_refs + range.begin, range.capacity - range.begin);
    if (!bvh_build::spatial_partition(space, range.end - range.begin, split, m_triangles, children, right_offset))
      return false;
    auto to_box4 = [](const Box3& b) {
      Box4 r;
      const float lo[4] = {b.lo.x, b.lo.y, b.lo.z, 0.f}, hi[4] = {b.hi.x, b.hi.y, b.hi.z, 0.f};
      r.lo = Float4::load(lo);
      r.hi = Float4::load(hi);
      return r;
    };
    left_bounds = {to_box4(children.left_box), to_box4(children.left_centroids)};
    right_bounds = {to_box4(children.right_box), to_box4(children.right_centroids)};
    left = {range.begin, range.begin + children.left_count, range.begin + right_offset};
    right = {range.begin + right_offset, range.begin + right_offset + children.right_count, range.capacity};
    return true;
  }

  const std::vector<Triangle>& m_triangles;
  const BvhConfig& m_config;
  CostModel m_cost;
  BuildRef* m_refs;
  BvhNode* m_nodes;
  int m_bins = 16;
  float m_root_area = 0.f;
  std::atomic<std::uint32_t> m_next_node{1};
};

}  // namespace
}  // namespace raylab

namespace raylab {
namespace {

// Rewrites the nodes in depth-first order, siblings kept adjacent, and gathers the leaves'
// references in the same order: the parallel build hands out node slots in whatever order tasks
// ran (traversal is faster, and the result deterministic, when a subtree is contiguous), and
// spatial splits leave unused slots between subtrees' references.
void relayout_depth_first(const BvhNode* nodes, std::uint32_t node_count, const BuildRef* refs, BvhTree& tree) {
  tree.nodes.clear();
  tree.nodes.reserve(node_count);
  tree.nodes.push_back(nodes[0]);
  tree.prim_ids.clear();
  tree.max_depth = 0;
  tree.leaf_count = 0;
  struct Pending {
    std::uint32_t old_index, new_index;
    int depth;
  };
  std::vector<Pending> stack{{0u, 0u, 0}};
  while (!stack.empty()) {
    const Pending p = stack.back();
    stack.pop_back();
    const BvhNode& node = nodes[p.old_index];
    if (node.is_leaf()) {
      BvhNode& out = tree.nodes[p.new_index];
      out.first = static_cast<std::uint32_t>(tree.prim_ids.size());
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) tree.prim_ids.push_back(refs[i].id);
      ++tree.leaf_count;
      tree.max_depth = std::max(tree.max_depth, p.depth);
      continue;
    }
    const auto left = static_cast<std::uint32_t>(tree.nodes.size());
    tree.nodes.push_back(nodes[node.first]);
    tree.nodes.push_back(nodes[node.first + 1]);
    tree.nodes[p.new_index].first = left;
    // Push the right child first so the left subtree is laid out right after this pair.
    stack.push_back({node.first + 1, left + 1, p.depth + 1});
    stack.push_back({node.first, left, p.depth + 1});
  }
}

// Fills references for `ids` (triangles are bounded from their vertices directly, without the
// id-to-kind lookup) and returns their bounds.
Bounds make_refs(const Geometry& geometry, std::span<const std::uint32_t> ids, BuildRef* refs) {
  const auto triangle_count = static_cast<std::uint32_t>(geometry.triangles.size());
  auto fill = [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t id = ids[i];
      Box3 box;
      if (id < triangle_count) {
        const Triangle& t = geometry.triangles[id];
        box = {min(t.p0, min(t.p1, t.p2)), max(t.p0, max(t.p1, t.p2))};
      } else {
        box = geometry.bounds(id);
      }
      BuildRef& r = refs[i];
      r.set_box(box);
      r.id = id;
      r.splittable = id < triangle_count ? 1u : 0u;
    }
    return bounds_of(refs + begin, end - begin);
  };
  const auto n = static_cast<std::uint32_t>(ids.size());
  return tbb::parallel_reduce(
      tbb::blocked_range<std::uint32_t>(0, n, 4096), Bounds{},
      [&](const tbb::blocked_range<std::uint32_t>& r, Bounds b) {
        b.merge(fill(r.begin(), r.end()));
        return b;
      },
      [](Bounds a, const Bounds& b) {
        a.merge(b);
        return a;
      });
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
    return tree;
  }
  const UnorderedBvh built = build_bvh_unordered(geometry, ids, config);
  relayout_depth_first(built.nodes.data(), built.node_count, built.refs.data(), tree);
  return tree;
}

UnorderedBvh build_bvh_unordered(const Geometry& geometry, std::span<const std::uint32_t> ids,
                                 const BvhConfig& config) {
  const auto n = static_cast<std::uint32_t>(ids.size());
  // Spatial splits get room for extra references; node slots: at most two per reference.
  const double budget = config.spatial_splits ? std::clamp(double(config.spatial_split_budget), 0.0, 4.0) : 0.0;
  const auto capacity = static_cast<std::uint32_t>(n + std::floor(budget * n));
  // Default-initialised (not zeroed): every slot that is read is written first.
  UnorderedBvh built;
  built.refs.resize(capacity);
  built.nodes.resize(2 * std::size_t{capacity});
  const Bounds bounds = make_refs(geometry, ids, built.refs.data());
  built.node_count = Builder(geometry, config, built.refs.data(), built.nodes.data()).build(n, capacity, bounds);
  return built;
}

double sah_cost(const BvhTree& tree, const BvhConfig& config) {
  auto area = [](const BvhNode& n) {
    const double ex = n.hi[0] - n.lo[0], ey = n.hi[1] - n.lo[1], ez = n.hi[2] - n.lo[2];
    return 2.0 * (ex * ey + ey * ez + ez * ex);
  };
  const double root_area = area(tree.nodes[0]);
  if (!(root_area > 0.0)) return 0.0;
  const CostModel cost(config);
  double total = 0.0;
  for (const BvhNode& n : tree.nodes) {
    const double rel = area(n) / root_area;
    total += n.is_leaf() ? rel * cost.intersection * cost.blocked(n.count) : rel * config.traversal_cost;
  }
  return total;
}

}  // namespace raylab
