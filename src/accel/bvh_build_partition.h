#pragma once
/// \file
/// Internal to the BVH builder: moving a node's references to the side of an object split they
/// fall on, sequentially for small nodes and in parallel for large ones, with the same result
/// whatever the number of threads.

#include <algorithm>
#include <cstdint>

#include "bvh_build_box.h"
#include "bvh_build_ref.h"

namespace raylab::bvh_build {

/// An object split as a test on one reference: the bin of its doubled centroid on `axis` (bins
/// as the binning pass computes them) lies left of `bin`.
struct SplitTest {
  int axis = 0;
  int bin = 1;      ///< references in bins [0, bin) go left
  float lo = 0.f;   ///< doubled centroid at the start of bin 0: the node's smallest
  float scale = 0;  ///< bins per unit of doubled centroid (0: one bin)
  int bins = 2;
  float hi = 0.f;  ///< the node's largest doubled centroid on `axis`

  /// The bin of doubled centroid `c2`.
  int bin_of(float c2) const { return std::clamp(static_cast<int>((c2 - lo) * scale), 0, bins - 1); }
  /// True when `r` goes to the left child.
  bool goes_left(const BuildRef& r) const { return bin_of(r.centroid2(axis)) < bin; }
  /// The doubled centroid `t` from which on references go right: for every c2 in [lo, hi],
  /// `!(c2 >= t)` equals `bin_of(c2) < bin` (the bin grows with c2, as every step of bin_of
  /// rounds monotonically), so the partition needs one comparison per reference, not a bin.
  float threshold() const;
};

/// Where a partition left the references: `mid` is the first right one; the doubled centroids of
/// each side are bounded by `left_centroids` and `right_centroids`.
struct PartitionResult {
  std::uint32_t mid = 0;
  Box4 left_centroids, right_centroids;
};

/// Partitions `refs[0, n)` in place by `test` (a Hoare partition, one pass).
PartitionResult partition_sequential(BuildRef* refs, std::uint32_t n, const SplitTest& test);

/// References per chunk of the parallel partition. A constant, not a function of the thread
/// count, so that the order it leaves, and hence the tree, is the same with any number of threads.
inline constexpr std::uint32_t kPartitionChunk = 8192;

/// Partitions `refs[0, n)` in place by `test` on oneTBB: each chunk of `kPartitionChunk`
/// references is partitioned on its own, then the right references left of the split point are
/// swapped, in order, with the left ones right of it. The sides hold the same references as
/// `partition_sequential` leaves (in another order), and the order depends only on the input.
PartitionResult partition_parallel(BuildRef* refs, std::uint32_t n, const SplitTest& test);

}  // namespace raylab::bvh_build
