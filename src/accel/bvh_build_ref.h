#pragma once
/// \file
/// Internal to the BVH builder: the primitive reference it sorts, the SAH cost rule, and the
/// entry points of the spatial-split half (bvh_spatial_split.cpp).

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "raylab/accel/bvh.h"
#include "raylab/core/box.h"
#include "raylab/geometry/triangle.h"

namespace raylab::bvh_build {

/// One primitive reference, 32 bytes, laid out so that `lo` and `hi` each load as four floats:
///   bytes  0-11  box minimum      bytes 12-15  global primitive id
///   bytes 16-27  box maximum      bytes 28-31  1 when the primitive is a triangle (may be clipped)
/// With spatial splits a primitive has several references whose boxes are clipped parts of its box.
struct BuildRef {
  float lo[3];
  std::uint32_t id;
  float hi[3];
  std::uint32_t splittable;

  /// Twice the centre on axis `a`: the builder bins doubled centroids, which saves a multiply.
  float centroid2(int a) const { return lo[a] + hi[a]; }
  /// The reference's box.
  Box3 box() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
  /// Replaces the reference's box.
  void set_box(const Box3& b) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = b.lo[a];
      hi[a] = b.hi[a];
    }
  }
};
static_assert(sizeof(BuildRef) == 32, "BuildRef must stay 32 bytes");

/// Most bins per axis either kind of split uses.
inline constexpr int kMaxBins = 64;

/// The SAH cost rule of both the builder and `sah_cost`: a leaf pays the intersection cost for
/// every started block of `leaf_block_size` primitives, since wide leaves test that many at once.
struct CostModel {
  float traversal = 1.f;
  float intersection = 1.f;
  std::uint32_t block = 1;
  /// ~(block - 1) when `block` is a power of two (rounding up is then a mask, not a division,
  /// which matters: the builder prices every candidate split this way); 0 otherwise.
  std::uint32_t block_mask = ~0u;

  /// The rule from a build configuration.
  explicit CostModel(const BvhConfig& config)
      : traversal(config.traversal_cost),
        intersection(config.intersection_cost),
        block(static_cast<std::uint32_t>(std::max(1, config.leaf_block_size))),
        block_mask(std::has_single_bit(block) ? ~(block - 1) : 0u) {}

  /// Primitive tests a leaf of `n` references is charged for.
  float blocked(std::uint32_t n) const {
    return static_cast<float>(block_mask != 0 ? (n + block - 1) & block_mask : (n + block - 1) / block * block);
  }
  /// Cost of a leaf of `n` references, relative to one primitive test.
  float leaf(std::uint32_t n) const { return intersection * blocked(n); }
  /// The part of a split's cost that differs between candidate splits of one node: comparing
  /// these instead of `split` saves a division per candidate.
  float split_areas(float left_area, std::uint32_t left_n, float right_area, std::uint32_t right_n) const {
    return left_area * blocked(left_n) + right_area * blocked(right_n);
  }
  /// Cost of a split whose `split_areas` is `areas`, for a node of area `parent_area`.
  float split_cost(float areas, float parent_area) const { return traversal + intersection * areas / parent_area; }
  /// Cost of splitting a node of area `parent_area` into children (area, count) left and right.
  float split(float left_area, std::uint32_t left_n, float right_area, std::uint32_t right_n, float parent_area) const {
    return split_cost(split_areas(left_area, left_n, right_area, right_n), parent_area);
  }
};

/// Room for the left child when a node of `left_n` + `right_n` references owns `space` slots
/// (space >= left_n + right_n): its references plus a share of the free slots proportional to
/// its size, so each subtree's budget for spatial splits follows its size.
inline std::uint32_t left_share(std::uint32_t left_n, std::uint32_t right_n, std::uint32_t space) {
  const std::uint64_t free_slots = space - left_n - right_n;
  return left_n + static_cast<std::uint32_t>(free_slots * left_n / (std::uint64_t{left_n} + right_n));
}

/// The box both boxes contain (empty when they are disjoint).
inline Box3 intersect_boxes(const Box3& a, const Box3& b) { return {max(a.lo, b.lo), min(a.hi, b.hi)}; }

/// The best spatial split found for a node (`axis` < 0: none).
struct SpatialSplit {
  int axis = -1;
  int bin = 0;                   ///< references in bins [0, bin) go left, those in [bin, ...) right
  float cost = INFINITY;         ///< the SAH cost, relative to the node's area as for object splits
  std::uint32_t duplicates = 0;  ///< references the split adds (straddlers, at most)
  float lo = 0.f, scale = 0.f;   ///< the bins: bin of x is floor((x - lo) * scale), clamped
  float position = 0.f;          ///< the split plane
};

/// Children produced by `spatial_partition`: counts, boxes and centroid bounds (doubled centroids).
struct SpatialChildren {
  std::uint32_t left_count = 0, right_count = 0;
  Box3 left_box, right_box, left_centroids, right_centroids;
};

/// Bins references `refs` of a node with box `box` on every axis by where their triangles really
/// lie (clipped bin by bin), and returns the spatial split of lowest SAH cost. Non-triangle
/// references are binned whole at their centre and never straddle.
SpatialSplit find_spatial_split(std::span<const BuildRef> refs, const Box3& box, int bin_count,
                                const std::vector<Triangle>& triangles, const CostModel& cost);

/// Carries out `split` on the node's references `space[0, count)`: straddling triangles are
/// clipped at the plane into one reference per side. Writes the left references to the start of
/// `space` and the right ones from `right_start` = the returned left count plus the left child's
/// share of the free room (computed here, returned through `right_offset`). Returns false, and
/// leaves `space` as it was, when a side would come out empty or the room is too small.
bool spatial_partition(std::span<BuildRef> space, std::uint32_t count, const SpatialSplit& split,
                       const std::vector<Triangle>& triangles, SpatialChildren& out, std::uint32_t& right_offset);

}  // namespace raylab::bvh_build
