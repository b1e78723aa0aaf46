// The object-split partition of the BVH builder, sequential and parallel (see the header).
//
// Why in place and in two steps: the references of a large node are tens of megabytes, and the
// partition is bound by memory traffic. Partitioning fixed chunks independently touches each
// reference once, as the sequential pass does; afterwards only the references on the wrong side
// of the split point move, once each. A scatter into a second buffer would move every reference
// twice (out and back) and need the buffer.

#include "bvh_build_partition.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace raylab::bvh_build {

namespace {

// Floats in order as integers: a < b exactly when ordered_key(a) < ordered_key(b), for every
// non-NaN a and b (-0 and +0 share key 0), so a search over floats can bisect integers.
std::int64_t ordered_key(float f) {
  const std::int32_t bits = std::bit_cast<std::int32_t>(f);
  return bits >= 0 ? bits : -static_cast<std::int64_t>(bits & 0x7fffffff);
}
float from_ordered_key(std::int64_t k) {
  return k >= 0 ? std::bit_cast<float>(static_cast<std::int32_t>(k))
                : std::bit_cast<float>(static_cast<std::uint32_t>(-k) | 0x80000000u);
}

}  // namespace

float SplitTest::threshold() const {
  if (!(scale > 0.f)) return bin > 0 ? INFINITY : -INFINITY;  // one bin, bin 0
  if (bin_of(hi) < bin) return INFINITY;                      // all left
  if (bin_of(lo) >= bin) return -INFINITY;                    // all right
  // The least float of (lo, hi] in bin `bin` or above, bin_of growing with its argument. The
  // plane the bins were laid out with is within a few floats of it, so the search brackets it
  // from there with steps doubling in the floats' order, then bisects the bracket. (Stepping
  // float by float is not bounded: near zero, one rounding step of a large `lo` spans billions
  // of floats.) Invariant: bin_of(from(below)) < bin <= bin_of(from(above)).
  const std::int64_t lo_key = ordered_key(lo), hi_key = ordered_key(hi);
  const std::int64_t guess = std::clamp(ordered_key(lo + static_cast<float>(bin) / scale), lo_key, hi_key);
  auto right_of = [&](std::int64_t k) { return bin_of(from_ordered_key(k)) >= bin; };
  std::int64_t below = lo_key, above = hi_key;
  if (right_of(guess)) {
    above = guess;
    for (std::int64_t step = 1; above - step > lo_key; step *= 2) {
      if (!right_of(above - step)) {
        below = above - step;
        break;
      }
      above -= step;
    }
  } else {
    below = guess;
    for (std::int64_t step = 1; below + step < hi_key; step *= 2) {
      if (right_of(below + step)) {
        above = below + step;
        break;
      }
      below += step;
    }
  }
  while (above - below > 1) {
    const std::int64_t mid = below + (above - below) / 2;
    if (right_of(mid)) {
      above = mid;
    } else {
      below = mid;
    }
  }
  return from_ordered_key(above);
}

namespace {

// The Hoare partition with the split as a threshold on the doubled centroid (NaN goes left, as
// bin_of puts it in bin 0).
PartitionResult partition_by_threshold(BuildRef* refs, std::uint32_t n, int axis, float t) {
  PartitionResult out;
  BuildRef* i = refs;
  BuildRef* j = refs + n;
  auto goes_left = [&](const BuildRef& r) { return !(r.centroid2(axis) >= t); };
  auto centroid = [](const BuildRef& r) { return load_lo(r) + load_hi(r); };
  // Each reference is looked at once: a swapped pair is counted when i and j pass over it.
  for (;;) {
    while (i < j && goes_left(*i)) {
      const simd::Float4 c = centroid(*i++);
      out.left_centroids.extend(c, c);
    }
    while (i < j && !goes_left(j[-1])) {
      const simd::Float4 c = centroid(*--j);
      out.right_centroids.extend(c, c);
    }
    if (i >= j) break;
    std::swap(*i, j[-1]);
  }
  out.mid = static_cast<std::uint32_t>(i - refs);
  return out;
}

}  // namespace

PartitionResult partition_sequential(BuildRef* refs, std::uint32_t n, const SplitTest& test) {
  return partition_by_threshold(refs, n, test.axis, test.threshold());
}

namespace {

// A run of positions [begin, end) holding references on the wrong side of the split point.
struct Run {
  std::uint32_t begin, end;
};

// The runs in order with the number of positions before each, so that the k-th misplaced
// position can be found by a binary search.
struct Runs {
  std::vector<Run> runs;
  std::vector<std::uint32_t> before;  // positions in the runs before runs[i]
  std::uint32_t total = 0;

  void add(std::uint32_t begin, std::uint32_t end) {
    if (begin >= end) return;
    runs.push_back({begin, end});
    before.push_back(total);
    total += end - begin;
  }
  // Index of the run holding the k-th position (k < total).
  std::size_t find(std::uint32_t k) const {
    return static_cast<std::size_t>(std::upper_bound(before.begin(), before.end(), k) - before.begin()) - 1;
  }
};

}  // namespace

PartitionResult partition_parallel(BuildRef* refs, std::uint32_t n, const SplitTest& test) {
  const std::uint32_t chunks = (n + kPartitionChunk - 1) / kPartitionChunk;
  if (chunks <= 1) return partition_sequential(refs, n, test);

  // Step 1: every chunk partitioned on its own; chunk c then holds its left references first.
  const float t = test.threshold();
  std::vector<PartitionResult> parts(chunks);
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, chunks, 1), [&](const tbb::blocked_range<std::uint32_t>& r) {
    for (std::uint32_t c = r.begin(); c < r.end(); ++c) {
      const std::uint32_t begin = c * kPartitionChunk;
      parts[c] = partition_by_threshold(refs + begin, std::min(kPartitionChunk, n - begin), test.axis, t);
    }
  });

  PartitionResult out;
  for (const PartitionResult& p : parts) {
    out.mid += p.mid;
    out.left_centroids.extend(p.left_centroids);
    out.right_centroids.extend(p.right_centroids);
  }
  const std::uint32_t mid = out.mid;

  // Step 2: right references before `mid` and left ones from `mid` on are equally many; the
  // k-th of the former trades places with the k-th of the latter.
  Runs rights, lefts;
  for (std::uint32_t c = 0; c < chunks; ++c) {
    const std::uint32_t begin = c * kPartitionChunk, end = std::min(begin + kPartitionChunk, n);
    const std::uint32_t split = begin + parts[c].mid;
    rights.add(split, std::min(end, mid));
    lefts.add(std::max(begin, mid), split);
  }
  const std::uint32_t misplaced = rights.total;  // == lefts.total
  const std::uint32_t pieces = (misplaced + kPartitionChunk - 1) / kPartitionChunk;
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, pieces, 1), [&](const tbb::blocked_range<std::uint32_t>& r) {
    for (std::uint32_t p = r.begin(); p < r.end(); ++p) {
      std::uint32_t k = p * kPartitionChunk;
      const std::uint32_t stop = std::min(k + kPartitionChunk, misplaced);
      std::size_t ra = rights.find(k), la = lefts.find(k);
      std::uint32_t a = rights.runs[ra].begin + (k - rights.before[ra]);
      std::uint32_t b = lefts.runs[la].begin + (k - lefts.before[la]);
      while (k < stop) {
        if (a == rights.runs[ra].end) a = rights.runs[++ra].begin;
        if (b == lefts.runs[la].end) b = lefts.runs[++la].begin;
        const std::uint32_t step = std::min({rights.runs[ra].end - a, lefts.runs[la].end - b, stop - k});
        std::swap_ranges(refs + a, refs + a + step, refs + b);
        a += step;
        b += step;
        k += step;
      }
    }
  });
  return out;
}

}  // namespace raylab::bvh_build
