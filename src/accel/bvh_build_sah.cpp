// The binned SAH split search of the BVH builder (bvh_build_sah.h): sweeps over bins for large
// nodes, over the sorted references for small ones.

#include "bvh_build_sah.h"

namespace raylab::bvh_build {

using simd::Float4;

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

namespace {

// Sets `best.cost` from the `split_areas` of the best candidate. A NaN cost means no split: it
// happens where the node's area is 0, and then every candidate's cost is NaN.
void finish_cost(ObjectSplit& best, float best_areas, float parent_area, const CostModel& cost) {
  best.cost = cost.split_cost(best_areas, parent_area);
  if (std::isnan(best.cost)) best = ObjectSplit{};
  if (!(parent_area > 0.f) && best.axis >= 0) best.cost = 0.f;  // flat: any valid split helps
}

}  // namespace

// Evaluates the bin boundaries on every axis; cost is relative to the parent's area. Only
// boundaries right after a non-empty bin are evaluated: the others repeat the split (same
// sides, same boxes, same cost) of the boundary before them, which the strict `<` would keep
// anyway, so skipping them changes nothing but the time spent on small nodes. Candidates are
// compared by `split_areas`, which orders them as their costs do, without a division each.
ObjectSplit best_object_split(const BinSet& set, float parent_area, const CostModel& cost) {
  ObjectSplit best;
  float best_areas = INFINITY;
  const int bins = set.bins;
  float right_area[kMaxBins];
  std::uint32_t right_count[kMaxBins];
  for (int axis = 0; axis < 3; ++axis) {
    const BinBox* box = set.box[axis];
    const std::uint32_t* count = set.count[axis];
    Box4 acc;
    std::uint32_t n = 0;
    for (int b = bins - 1; b > 0; --b) {
      if (count[b] != 0) {  // an empty bin's box is empty
        acc.extend(box[b].box4());
        n += count[b];
      }
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
      const float c = cost.split_areas(area(acc), n, right_area[b], right_count[b]);
      if (c < best_areas) {
        best.axis = axis;
        best.bin = b;
        best_areas = c;
      }
    }
  }
  if (best.axis < 0) return best;
  for (int b = 0; b < bins; ++b) {
    if (set.count[best.axis][b] != 0) (b < best.bin ? best.left : best.right).extend(set.box[best.axis][b].box4());
  }
  finish_cost(best, best_areas, parent_area, cost);
  return best;
}

// The split best_object_split would find, for a node of few references, computed from the
// references directly: on each axis they are ordered by bin, and each boundary between two
// occupied bins is evaluated with the same unions (min/max are exact, so the same floats), the
// same counts and the same tie order as the binned sweep. The tree is therefore the same; the
// cost is O(count) boxes per axis instead of clearing and sweeping every bin.
ObjectSplit small_object_split(const BuildRef* refs, std::uint32_t count, const BinMap& map, float parent_area,
                               const CostModel& cost) {
  ObjectSplit best;
  if (count < 2) return best;  // nothing to split (and `order` below needs two references)
  float best_areas = INFINITY;
  Float4 lo[kSmallNode], hi[kSmallNode];
  int bin[3][kSmallNode];  // every reference's bin on every axis, computed as BinSet::add does
  const Float4 lo4 = Float4::load(map.lo), scale4 = Float4::load(map.scale);
  const Float4 last = Float4::broadcast(static_cast<float>(map.bins - 1));
  for (std::uint32_t i = 0; i < count; ++i) {
    lo[i] = load_lo(refs[i]);
    hi[i] = load_hi(refs[i]);
    float f[4];
    min(max((lo[i] + hi[i] - lo4) * scale4, Float4::broadcast(0.f)), last).store(f);
    for (int a = 0; a < 3; ++a) bin[a][i] = static_cast<int>(f[a]);
  }
  float right_area[kSmallNode];
  for (int axis = 0; axis < 3; ++axis) {
    // Indices ordered by bin, stably (equal bins keep index order), each placed at its rank:
    // the number of references before it. Branch-free on purpose: an insertion sort here
    // mispredicted about once per reference, a fifth of all the build's mispredictions.
    const int* b = bin[axis];
    std::uint8_t order[kSmallNode];
    for (std::uint32_t i = 0; i < count; ++i) {
      std::uint32_t rank = 0;
      for (std::uint32_t j = 0; j < count; ++j)
        rank += static_cast<std::uint32_t>(int(b[j] < b[i]) | (int(b[j] == b[i]) & int(j < i)));
      order[rank] = static_cast<std::uint8_t>(i);
    }
    if (b[order[0]] == b[order[count - 1]]) continue;  // one occupied bin: no split on this axis
    // The sweeps evaluate every position and discard those that are no boundary between bins,
    // again without branching on the bins.
    Box4 acc;
    for (std::uint32_t k = count - 1; k > 0; --k) {
      acc.extend(lo[order[k]], hi[order[k]]);
      right_area[k] = area(acc);  // read at boundaries only
    }
    acc = Box4{};
    for (std::uint32_t k = 0; k + 1 < count; ++k) {
      acc.extend(lo[order[k]], hi[order[k]]);
      const bool boundary = b[order[k]] != b[order[k + 1]];
      const float split = cost.split_areas(area(acc), k + 1, right_area[k + 1], count - k - 1);
      const float c = boundary ? split : INFINITY;
      if (c < best_areas) {
        best.axis = axis;
        best.bin = b[order[k]] + 1;
        best_areas = c;
      }
    }
  }
  if (best.axis < 0) return best;
  for (std::uint32_t i = 0; i < count; ++i)
    (bin[best.axis][i] < best.bin ? best.left : best.right).extend(lo[i], hi[i]);
  finish_cost(best, best_areas, parent_area, cost);
  return best;
}

}  // namespace raylab::bvh_build
