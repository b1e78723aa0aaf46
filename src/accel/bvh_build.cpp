// Binned SAH construction (Wald 2007) of a binary BVH, parallel on oneTBB, with optional spatial
// splits (bvh_spatial_split.cpp).
//
// Where the time goes and why it is laid out so: one 32-byte reference per primitive, sorted in
// place (no index indirection, no copies); one pass bins all three axes at once with 4-wide
// min/max; the children's boxes come from the bins and their centroid bounds from the partition
// pass, so no node rescans its references. Large nodes bin in parallel; subtrees above
// `parallel_threshold` are tasks. The tree is the same whatever the thread count: a node's split
// depends only on its references, merging bins is exact (min, max, integer sums), the partition is
// sequential, and the final depth-first relayout removes the order in which tasks took node slots.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

#include "bvh_build_ref.h"
#include "raylab/accel/bvh.h"
#include "raylab/simd/float4.h"

namespace raylab {
namespace {

using bvh_build::BuildRef;
using bvh_build::CostModel;
using bvh_build::kMaxBins;
using simd::Float4;

// Beyond this depth splits fall back to the object median, which halves the count each level:
// a bound on depth that keeps traversal stacks (128 entries) from overflowing on pathological
// inputs such as sizes spread over many orders of magnitude.
constexpr int kMedianFallbackDepth = 64;
// Nodes with at least this many references bin in parallel (the bins merge exactly, so the
// result does not depend on how the range was cut).
constexpr std::uint32_t kParallelBinning = 16384;

Float4 load_lo(const BuildRef& r) { return Float4::load(r.lo); }
Float4 load_hi(const BuildRef& r) { return Float4::load(r.hi); }

// A box as two 4-wide vectors (the fourth lane is ignored), 32 bytes.
struct Box4 {
  Float4 lo = Float4::broadcast(INFINITY);
  Float4 hi = Float4::broadcast(-INFINITY);

  void extend(Float4 l, Float4 h) {
    lo = min(l, lo);
    hi = max(h, hi);
  }
  void extend(const Box4& b) { extend(b.lo, b.hi); }
  Box3 box3() const {
    float l[4], h[4];
    lo.store(l);
    hi.store(h);
    return {{l[0], l[1], l[2]}, {h[0], h[1], h[2]}};
  }
};

// Surface area of a 4-wide box; 0 when empty.
float area(const Box4& b) {
  float l[4], h[4];
  b.lo.store(l);
  b.hi.store(h);
  const float ex = h[0] - l[0], ey = h[1] - l[1], ez = h[2] - l[2];
  if (!(ex >= 0.f && ey >= 0.f && ez >= 0.f)) return 0.f;
  return 2.f * (ex * ey + ey * ez + ez * ex);
}

// Bounds of a node's references and of their doubled centroids.
struct Bounds {
  Box4 box, centroids;
  void merge(const Bounds& o) {
    box.extend(o.box);
    centroids.extend(o.centroids);
  }
};

Bounds bounds_of(const BuildRef* refs, std::uint32_t n) {
  Bounds b;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Float4 lo = load_lo(refs[i]), hi = load_hi(refs[i]);
    b.box.extend(lo, hi);
    const Float4 c = lo + hi;
    b.centroids.extend(c, c);
  }
  return b;
}

// Per-axis mapping of a doubled centroid to its bin.
struct BinMap {
  float lo[4] = {0.f, 0.f, 0.f, 0.f};
  float scale[4] = {0.f, 0.f, 0.f, 0.f};  // 0 on an axis whose centroids coincide: one bin
  int bins = 2;

  BinMap(const Box4& centroids, int bin_count) : bins(bin_count) {
    float l[4], h[4];
    centroids.lo.store(l);
    centroids.hi.store(h);
    for (int a = 0; a < 3; ++a) {
      lo[a] = l[a];
      const float s = static_cast<float>(bins) / (h[a] - l[a]);
      scale[a] = std::isfinite(s) && s > 0.f ? s : 0.f;
    }
  }
  int bin(float c2, int axis) const { return std::clamp(static_cast<int>((c2 - lo[axis]) * scale[axis]), 0, bins - 1); }
};

// A bin's box as plain floats (32 bytes), so that arrays of bins can stay uninitialised.
struct BinBox {
  float lo[4], hi[4];

  void clear() {
    Float4::broadcast(INFINITY).store(lo);
    Float4::broadcast(-INFINITY).store(hi);
  }
  void extend(Float4 l, Float4 h) {
    min(l, Float4::load(lo)).store(lo);
    max(h, Float4::load(hi)).store(hi);
  }
  void extend(const BinBox& b) { extend(Float4::load(b.lo), Float4::load(b.hi)); }
  Box4 box4() const { return {Float4::load(lo), Float4::load(hi)}; }
};

// Boxes and counts of every bin on every axis (6.9 KB at 64 bins). Only the first `bins` of
// each axis are initialised: with the default 16 bins, clearing all 64 would cost more than the
// binning itself in the many small nodes near the leaves.
struct BinSet {
  BinBox box[3][kMaxBins];
  std::uint32_t count[3][kMaxBins];
  int bins;

  explicit BinSet(int bin_count) : bins(bin_count) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < bins; ++b) {
        box[a][b].clear();
        count[a][b] = 0;
      }
  }

  void add_one(const BuildRef& r, Float4 lo4, Float4 scale4) {
    const Float4 lo = load_lo(r), hi = load_hi(r);
    float f[4];
    ((lo + hi - lo4) * scale4).store(f);
    for (int a = 0; a < 3; ++a) {
      const int b = std::clamp(static_cast<int>(f[a]), 0, bins - 1);
      box[a][b].extend(lo, hi);
      ++count[a][b];
    }
  }
  void add(const BuildRef* refs, std::uint32_t n, const BinMap& map) {
    const Float4 lo4 = Float4::load(map.lo), scale4 = Float4::load(map.scale);
    for (std::uint32_t i = 0; i < n; ++i) add_one(refs[i], lo4, scale4);
  }
  void merge(const BinSet& o) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < bins; ++b) {
        box[a][b].extend(o.box[a][b]);
        count[a][b] += o.count[a][b];
      }
  }
};

struct ObjectSplit {
  int axis = -1;
  int bin = 0;  // references in bins [0, bin) go left
  float cost = INFINITY;
  Box4 left, right;  // the children's boxes, unions of their bins
};

// Evaluates the bin boundaries on every axis; cost is relative to the parent's area. Only
// boundaries right after a non-empty bin are evaluated: the others repeat the split (same
// sides, same boxes, same cost) of the boundary before them, which the strict `<` would keep
// anyway, so skipping them changes nothing but the time spent on small nodes.
ObjectSplit best_object_split(const BinSet& set, float parent_area, const CostModel& cost) {
  ObjectSplit best;
  const int bins = set.bins;
  float right_area[kMaxBins];
  std::uint32_t right_count[kMaxBins];
  for (int axis = 0; axis < 3; ++axis) {
    const BinBox* box = set.box[axis];
    const std::uint32_t* count = set.count[axis];
    Box4 acc;
    std::uint32_t n = 0;
    for (int b = bins - 1; b > 0; --b) {
      acc.extend(box[b].box4());
      n += count[b];
      if (count[b - 1] != 0) {
        right_area[b] = area(acc);
        right_count[b] = n;
      }
    }
    acc = Box4{};
    n = 0;
    for (int b = 1; b < bins; ++b) {
      if (count[b - 1] == 0) continue;
      acc.extend(box[b - 1].box4());
      n += count[b - 1];
      if (right_count[b] == 0) continue;
      const float c = cost.split(area(acc), n, right_area[b], right_count[b], parent_area);
      if (c < best.cost) {
        best.axis = axis;
        best.bin = b;
        best.cost = c;
      }
    }
  }
  if (best.axis >= 0) {
    for (int b = 0; b < bins; ++b) (b < best.bin ? best.left : best.right).extend(set.box[best.axis][b].box4());
    if (!(parent_area > 0.f)) best.cost = 0.f;  // flat: any valid split helps
  }
  return best;
}

// Nodes with at most this many references find their split without bins (small_object_split).
constexpr std::uint32_t kSmallNode = 10;

// The split best_object_split would find, for a node of few references, computed from the
// references directly: on each axis they are ordered by bin, and each boundary between two
// occupied bins is evaluated with the same unions (min/max are exact, so the same floats), the
// same counts and the same tie order as the binned sweep. The tree is therefore the same; the
// cost is O(count) boxes per axis instead of clearing and sweeping every bin.
ObjectSplit small_object_split(const BuildRef* refs, std::uint32_t count, const BinMap& map, float parent_area,
                               const CostModel& cost) {
  ObjectSplit best;
  Float4 lo[kSmallNode], hi[kSmallNode];
  for (std::uint32_t i = 0; i < count; ++i) {
    lo[i] = load_lo(refs[i]);
    hi[i] = load_hi(refs[i]);
  }
  float right_area[kSmallNode];
  for (int axis = 0; axis < 3; ++axis) {
    // Indices ordered by bin (insertion sort: count is small).
    int bin[kSmallNode];
    std::uint8_t order[kSmallNode];
    for (std::uint32_t i = 0; i < count; ++i) {
      bin[i] = map.bin(refs[i].centroid2(axis), axis);
      std::uint32_t j = i;
      for (; j > 0 && bin[order[j - 1]] > bin[i]; --j) order[j] = order[j - 1];
      order[j] = static_cast<std::uint8_t>(i);
    }
    if (bin[order[0]] == bin[order[count - 1]]) continue;  // one occupied bin: no split on this axis
    Box4 acc;
    for (std::uint32_t k = count - 1; k > 0; --k) {
      acc.extend(lo[order[k]], hi[order[k]]);
      right_area[k] = area(acc);
    }
    acc = Box4{};
    for (std::uint32_t k = 0; k + 1 < count; ++k) {
      acc.extend(lo[order[k]], hi[order[k]]);
      if (bin[order[k]] == bin[order[k + 1]]) continue;  // not a boundary between bins
      const float c = cost.split(area(acc), k + 1, right_area[k + 1], count - k - 1, parent_area);
      if (c < best.cost) {
        best.axis = axis;
        best.bin = bin[order[k]] + 1;
        best.cost = c;
      }
    }
  }
  if (best.axis >= 0) {
    for (std::uint32_t i = 0; i < count; ++i)
      (map.bin(refs[i].centroid2(best.axis), best.axis) < best.bin ? best.left : best.right).extend(lo[i], hi[i]);
    if (!(parent_area > 0.f)) best.cost = 0.f;
  }
  return best;
}

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

  // Moves the references of bins [0, split.bin) on the split axis to the front (a sequential
  // Hoare partition, so the order is deterministic) and gathers each side's centroid bounds.
  std::uint32_t partition(std::uint32_t begin, std::uint32_t end, const BinMap& map, int axis, int split_bin,
                          Box4& left_centroids, Box4& right_centroids) {
    BuildRef* i = m_refs + begin;
    BuildRef* j = m_refs + end;
    auto goes_left = [&](const BuildRef& r) { return map.bin(r.centroid2(axis), axis) < split_bin; };
    auto centroid = [](const BuildRef& r) { return load_lo(r) + load_hi(r); };
    for (;;) {
      while (i < j && goes_left(*i)) {
        const Float4 c = centroid(*i++);
        left_centroids.extend(c, c);
      }
      while (i < j && !goes_left(j[-1])) {
        const Float4 c = centroid(*--j);
        right_centroids.extend(c, c);
      }
      if (i >= j) break;
      std::swap(*i, j[-1]);
    }
    return static_cast<std::uint32_t>(i - m_refs);
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
      if (m_config.spatial_splits && count > kSmallNode && range.capacity > end)
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
  // Spatial splits get room for extra references; node slots: at most two per reference.
  const double budget = config.spatial_splits ? std::clamp(double(config.spatial_split_budget), 0.0, 4.0) : 0.0;
  const auto capacity = static_cast<std::uint32_t>(n + std::floor(budget * n));
  // Default-initialised (not zeroed): every slot that is read is written first.
  std::unique_ptr<BuildRef[]> refs(new BuildRef[capacity]);
  std::unique_ptr<BvhNode[]> nodes(new BvhNode[2 * std::size_t{capacity}]);
  const Bounds bounds = make_refs(geometry, ids, refs.get());
  const std::uint32_t node_count = Builder(geometry, config, refs.get(), nodes.get()).build(n, capacity, bounds);
  relayout_depth_first(nodes.get(), node_count, refs.get(), tree);
  return tree;
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
