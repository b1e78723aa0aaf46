#include "raylab/accel/accelerator.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "hit_list.h"
#include "raylab/core/float_neighbour.h"

namespace raylab {

void Accelerator::intersect(std::span<Ray> rays, std::span<Hit> hits) const {
  assert(rays.size() == hits.size());
  for (std::size_t i = 0; i < rays.size(); ++i) intersect(rays[i], hits[i]);
}

void Accelerator::occluded(std::span<const Ray> rays, std::span<std::uint8_t> result) const {
  assert(rays.size() == result.size());
  for (std::size_t i = 0; i < rays.size(); ++i) result[i] = occluded(rays[i]) ? 1 : 0;
}

void order_all_hits(std::vector<Hit>& hits, std::size_t first) {
  const auto begin = hits.begin() + static_cast<std::ptrdiff_t>(first);
  std::sort(begin, hits.end(),
            [](const Hit& a, const Hit& b) { return a.t < b.t || (a.t == b.t && a.prim_id < b.prim_id); });
  hits.erase(std::unique(begin, hits.end(), [](const Hit& a, const Hit& b) { return a.prim_id == b.prim_id; }),
             hits.end());
}

void Accelerator::all_hits(const Ray& ray, std::vector<Hit>& hits) const {
  Ray probe = ray;
  for (;;) {
    Hit hit;
    if (!intersect(probe, hit)) return;
    hits.push_back(hit);
    // Past this hit: the next search starts at the next float, and runs to the original end.
    probe.tmin = next_float_up(hit.t);
    probe.tmax = ray.tmax;
    if (!(probe.tmin < probe.tmax)) return;
  }
}

}  // namespace raylab
