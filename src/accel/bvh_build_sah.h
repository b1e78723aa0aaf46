#pragma once
/// \file
/// Internal to the BVH builder: the search for the best object split by the surface area
/// heuristic (binned, Wald 2007), for large nodes over bins and for small ones over the
/// references directly (the same answer either way).

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "bvh_build_box.h"
#include "bvh_build_ref.h"
#include "raylab/simd/float4.h"

namespace raylab::bvh_build {

/// Bounds of a node's references and of their doubled centroids.
struct Bounds {
  Box4 box, centroids;
  /// Grows both boxes to contain `o`'s.
  void merge(const Bounds& o) {
    box.extend(o.box);
    centroids.extend(o.centroids);
  }
};

/// The bounds of references [refs, refs + n).
Bounds bounds_of(const BuildRef* refs, std::uint32_t n);

/// Per-axis mapping of a doubled centroid to its bin.
struct BinMap {
  float lo[4] = {0.f, 0.f, 0.f, 0.f};     ///< the smallest doubled centroid
  float scale[4] = {0.f, 0.f, 0.f, 0.f};  ///< 0 on an axis whose centroids coincide: one bin
  float hi[4] = {0.f, 0.f, 0.f, 0.f};     ///< the largest doubled centroid
  int bins = 2;                           ///< bins per axis

  /// `bin_count` bins per axis spanning the doubled `centroids`.
  BinMap(const Box4& centroids, int bin_count) : bins(bin_count) {
    float l[4], h[4];
    centroids.lo.store(l);
    centroids.hi.store(h);
    for (int a = 0; a < 3; ++a) {
      lo[a] = l[a];
      hi[a] = h[a];
      const float s = static_cast<float>(bins) / (h[a] - l[a]);
      scale[a] = std::isfinite(s) && s > 0.f ? s : 0.f;
    }
  }
  /// The bin of doubled centroid coordinate `c2` on `axis`.
  int bin(float c2, int axis) const { return std::clamp(static_cast<int>((c2 - lo[axis]) * scale[axis]), 0, bins - 1); }
};

/// A bin's box as plain floats (32 bytes), so that arrays of bins can stay uninitialised.
struct BinBox {
  float lo[4], hi[4];  ///< corners (the fourth lane is ignored)

  /// Makes the box empty.
  void clear() {
    simd::Float4::broadcast(INFINITY).store(lo);
    simd::Float4::broadcast(-INFINITY).store(hi);
  }
  /// Grows the box to contain [l, h].
  void extend(simd::Float4 l, simd::Float4 h) {
    min(l, simd::Float4::load(lo)).store(lo);
    max(h, simd::Float4::load(hi)).store(hi);
  }
  /// Grows the box to contain `b`.
  void extend(const BinBox& b) { extend(simd::Float4::load(b.lo), simd::Float4::load(b.hi)); }
  /// The box as a Box4.
  Box4 box4() const { return {simd::Float4::load(lo), simd::Float4::load(hi)}; }
};

/// Boxes and counts of every bin on every axis (6.9 KB at 64 bins). Only the first `bins` of
/// each axis are initialised: with the default 16 bins, clearing all 64 would cost more than the
/// binning itself in the many small nodes near the leaves.
struct BinSet {
  BinBox box[3][kMaxBins];           ///< per axis, the union of each bin's references
  std::uint32_t count[3][kMaxBins];  ///< per axis, the references in each bin
  int bins;                          ///< bins in use per axis

  /// `bin_count` empty bins per axis.
  explicit BinSet(int bin_count) : bins(bin_count) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < bins; ++b) {
        box[a][b].clear();
        count[a][b] = 0;
      }
  }

  /// Adds reference `r` (binned by the map's `lo4`, `scale4`; `last` = bins - 1) on every axis.
  // The bin index is clamped as a float, before the conversion: for the references of the node
  // the scaled centroid lies in [0, bins] (the map comes from their own centroid bounds), where
  // this gives what clamping the converted integer gives, at the cost of two vector operations
  // instead of six scalar ones. A NaN goes to bin 0 (max returns its second operand).
  void add_one(const BuildRef& r, simd::Float4 lo4, simd::Float4 scale4, simd::Float4 last) {
    const simd::Float4 lo = load_lo(r), hi = load_hi(r);
    float f[4];
    min(max((lo + hi - lo4) * scale4, simd::Float4::broadcast(0.f)), last).store(f);
    for (int a = 0; a < 3; ++a) {
      const int b = static_cast<int>(f[a]);
      box[a][b].extend(lo, hi);
      ++count[a][b];
    }
  }
  /// Adds references [refs, refs + n) binned by `map`.
  void add(const BuildRef* refs, std::uint32_t n, const BinMap& map) {
    const simd::Float4 lo4 = simd::Float4::load(map.lo), scale4 = simd::Float4::load(map.scale);
    const simd::Float4 last = simd::Float4::broadcast(static_cast<float>(bins - 1));
    for (std::uint32_t i = 0; i < n; ++i) add_one(refs[i], lo4, scale4, last);
  }
  /// Adds `o`'s bins to these (exact: unions and integer sums).
  void merge(const BinSet& o) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < bins; ++b) {
        box[a][b].extend(o.box[a][b]);
        count[a][b] += o.count[a][b];
      }
  }
};

/// The best split of a node's references by bin, and the boxes of its two sides.
struct ObjectSplit {
  int axis = -1;          ///< -1: no split
  int bin = 0;            ///< references in bins [0, bin) go left
  float cost = INFINITY;  ///< SAH cost relative to the parent's area
  Box4 left, right;       ///< the children's boxes, unions of their bins
};

/// Nodes with at most this many references find their split without bins (small_object_split).
inline constexpr std::uint32_t kSmallNode = 16;

/// The best object split over the bins of `set` on every axis; its cost is relative to
/// `parent_area`. No split (axis -1) when no boundary separates two non-empty sides or the
/// node's area is 0 with no valid candidate.
ObjectSplit best_object_split(const BinSet& set, float parent_area, const CostModel& cost);

/// The split best_object_split would find for the `count` (at most kSmallNode) references at
/// `refs` binned by `map`, computed from the references without bins: the same tree, in
/// O(count) boxes per axis instead of clearing and sweeping every bin.
ObjectSplit small_object_split(const BuildRef* refs, std::uint32_t count, const BinMap& map, float parent_area,
                               const CostModel& cost);

}  // namespace raylab::bvh_build
