// Spatial splits of the BVH build (Stich, Friedrich & Dietrich 2009, "Spatial Splits in Bounding
// Volume Hierarchies"): bins over the node's box rather than over centroids, each triangle clipped
// into every bin it crosses, and straddling references duplicated into both children.

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <new>
#include <vector>

#include "bvh_build_ref.h"
#include "raylab/core/float_neighbour.h"

namespace raylab::bvh_build {
namespace {

// Rounds a double outward to the float below (toward -inf) or above (toward +inf), so that boxes
// of clipped triangles, whose corners are computed in double, contain the exact clipped part.
float round_down(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) > x ? next_float_down(f) : f;
}
float round_up(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) < x ? next_float_up(f) : f;
}

// Boxes of the parts of triangle `t` on either side of the plane x[axis] = position, each
// intersected with `box` (the reference's current, possibly already clipped, box). A part that
// the box does not reach comes out empty.
void split_triangle(const Triangle& t, int axis, float position, const Box3& box, Box3& left, Box3& right) {
  const Vec3 v[3] = {t.p0, t.p1, t.p2};
  left = Box3{};
  right = Box3{};
  for (int i = 0; i < 3; ++i) {
    const Vec3 a = v[i], b = v[i == 2 ? 0 : i + 1];
    if (a[axis] <= position) left.extend(a);
    if (a[axis] >= position) right.extend(a);
    // The edge crosses the plane strictly: its crossing point belongs to both parts.
    if ((a[axis] < position && b[axis] > position) || (a[axis] > position && b[axis] < position)) {
      const double s = (double(position) - a[axis]) / (double(b[axis]) - a[axis]);
      Vec3 lo, hi;
      for (int k = 0; k < 3; ++k) {
        const double x = double(a[k]) + s * (double(b[k]) - a[k]);
        lo[k] = k == axis ? position : round_down(x);
        hi[k] = k == axis ? position : round_up(x);
      }
      left.extend(lo);
      left.extend(hi);
      right.extend(lo);
      right.extend(hi);
    }
  }
  left = intersect_boxes(left, box);
  right = intersect_boxes(right, box);
}

// Bins of one axis over the node's box: bin of x is floor((x - lo) * scale), clamped.
struct AxisBins {
  float lo = 0.f, scale = 0.f, width = 0.f;
  int count = 2;

  int bin(float x) const { return std::clamp(static_cast<int>((x - lo) * scale), 0, count - 1); }
  // The plane between bins b - 1 and b.
  float plane(int b) const { return lo + width * static_cast<float>(b); }
};

// Where a reference lies in the bins: triangles span the bins of their box's extent; other
// shapes sit whole in the bin of their centre, so they never straddle a plane.
void bin_range(const BuildRef& r, const AxisBins& bins, int axis, int& first, int& last) {
  if (r.splittable) {
    first = bins.bin(r.lo[axis]);
    last = bins.bin(r.hi[axis]);
  } else {
    first = last = bins.bin(0.5f * (r.lo[axis] + r.hi[axis]));
  }
}

}  // namespace

SpatialSplit find_spatial_split(std::span<const BuildRef> refs, const Box3& box, int bin_count,
                                const std::vector<Triangle>& triangles, const CostModel& cost) {
  SpatialSplit best;
  const float parent_area = box.area();
  if (!(parent_area > 0.f)) return best;
  for (int axis = 0; axis < 3; ++axis) {
    const float extent = box.hi[axis] - box.lo[axis];
    AxisBins bins{box.lo[axis], static_cast<float>(bin_count) / extent, extent / static_cast<float>(bin_count),
                  bin_count};
    if (!(extent > 0.f) || !std::isfinite(bins.scale)) continue;
    // Only the node's own bins are initialised (there may be far fewer than kMaxBins).
    alignas(Box3) unsigned char storage[sizeof(Box3) * kMaxBins];
    Box3* bin_box = reinterpret_cast<Box3*>(storage);
    std::uint32_t enter[kMaxBins], leave[kMaxBins];
    for (int b = 0; b < bin_count; ++b) {
      new (bin_box + b) Box3{};
      enter[b] = leave[b] = 0;
    }
    for (const BuildRef& r : refs) {
      int first = 0, last = 0;
      bin_range(r, bins, axis, first, last);
      ++enter[first];
      ++leave[last];
      if (first == last) {
        bin_box[first].extend(r.box());
        continue;
      }
      // Clip bin by bin: the part of the triangle in a bin is bounded by its corners in the bin
      // and the points where its edges cross the bin's planes, so one walk along each edge
      // bounds every part. (Estimates only, in float: the split that is carried out clips
      // exactly, and the children's boxes come from its references.)
      alignas(Box3) unsigned char part_storage[sizeof(Box3) * kMaxBins];
      Box3* parts = reinterpret_cast<Box3*>(part_storage);
      for (int b = 0; b <= last - first; ++b) new (parts + b) Box3{};
      const Triangle& t = triangles[r.id];
      const Vec3 v[3] = {t.p0, t.p1, t.p2};
      for (int e = 0; e < 3; ++e) {
        Vec3 a = v[e], b = v[e == 2 ? 0 : e + 1];
        if (a[axis] > b[axis]) std::swap(a, b);
        const int ba = std::clamp(bins.bin(a[axis]), first, last), bb = std::clamp(bins.bin(b[axis]), first, last);
        parts[ba - first].extend(a);
        parts[bb - first].extend(b);
        const Vec3 d = b - a;
        for (int k = ba + 1; k <= bb; ++k) {
          const float plane = bins.plane(k);
          Vec3 p = a + d * ((plane - a[axis]) / d[axis]);
          p[axis] = plane;
          parts[k - 1 - first].extend(p);
          parts[k - first].extend(p);
        }
      }
      const Box3 ref_box = r.box();
      for (int b = first; b <= last; ++b) {
        const Box3 part = intersect_boxes(parts[b - first], ref_box);
        if (!part.empty()) bin_box[b].extend(part);  // disjoint boxes intersect "inside out"
      }
    }
    float right_area[kMaxBins];
    std::uint32_t right_count[kMaxBins];
    Box3 acc;
    std::uint32_t n = 0;
    for (int b = bin_count - 1; b > 0; --b) {
      acc.extend(bin_box[b]);
      n += leave[b];
      right_area[b] = acc.area();
      right_count[b] = n;
    }
    acc = Box3{};
    n = 0;
    for (int b = 1; b < bin_count; ++b) {
      acc.extend(bin_box[b - 1]);
      n += enter[b - 1];
      if (n == 0 || right_count[b] == 0) continue;
      const float c = cost.split(acc.area(), n, right_area[b], right_count[b], parent_area);
      if (c < best.cost) {
        best = {axis,         b, c, n + right_count[b] - static_cast<std::uint32_t>(refs.size()), bins.lo, bins.scale,
                bins.plane(b)};
      }
    }
  }
  return best;
}

bool spatial_partition(std::span<BuildRef> space, std::uint32_t count, const SpatialSplit& split,
                       const std::vector<Triangle>& triangles, SpatialChildren& out, std::uint32_t& right_offset) {
  const int axis = split.axis;
  const AxisBins bins{split.lo, split.scale, 0.f, kMaxBins};  // count only clamps: any bin >= split.bin
  // is right, so a clamp past the node's own bin count changes nothing.
  std::vector<BuildRef> left, right;
  left.reserve(count);
  right.reserve(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    const BuildRef& r = space[i];
    int first = 0, last = 0;
    bin_range(r, bins, axis, first, last);
    if (last < split.bin) {
      left.push_back(r);
    } else if (first >= split.bin) {
      right.push_back(r);
    } else {
      Box3 l, h;
      split_triangle(triangles[r.id], axis, split.position, r.box(), l, h);
      BuildRef lr = r, rr = r;
      lr.set_box(l);
      rr.set_box(h);
      // A part the reference's box does not reach holds none of the triangle: drop it.
      if (!l.empty()) left.push_back(lr);
      if (!h.empty()) right.push_back(rr);
      if (l.empty() && h.empty()) (first < split.bin ? left : right).push_back(r);
    }
  }
  const auto left_n = static_cast<std::uint32_t>(left.size()), right_n = static_cast<std::uint32_t>(right.size());
  const auto room = static_cast<std::uint32_t>(space.size());
  if (left_n == 0 || right_n == 0 || left_n + right_n > room) return false;
  right_offset = left_share(left_n, right_n, room);
  std::copy(left.begin(), left.end(), space.begin());
  std::copy(right.begin(), right.end(), space.begin() + right_offset);
  out = {};
  out.left_count = left_n;
  out.right_count = right_n;
  for (const BuildRef& r : left) {
    out.left_box.extend(r.box());
    out.left_centroids.extend(r.box().lo + r.box().hi);
  }
  for (const BuildRef& r : right) {
    out.right_box.extend(r.box());
    out.right_centroids.extend(r.box().lo + r.box().hi);
  }
  return true;
}

}  // namespace raylab::bvh_build
