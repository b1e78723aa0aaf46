#include "raylab/accel/brute_force.h"
#include "raylab/core/stopwatch.h"

#include <algorithm>
#include <chrono>

#include "hit_list.h"
#include "traversal_entry_points.h"

namespace raylab {

BruteForce::BruteForce(const Geometry& geometry) : BruteForce(geometry, geometry.primitive_ids()) {}

BruteForce::BruteForce(const Geometry& geometry, std::span<const std::uint32_t> ids)
    : m_geometry(geometry), m_ids(ids.begin(), ids.end()) {
  const auto start = std::chrono::steady_clock::now();
  // Ascending ids, so that an any-hit query finds the same first hit whatever order was given.
  std::sort(m_ids.begin(), m_ids.end());
  for (std::uint32_t id : m_ids) m_bounds.extend(geometry.bounds(id));
  m_build_seconds = seconds_since(start);
}

// Through Geometry::intersect for every kind, not the structures' shared leaf test: the
// reference stays independent of the code it checks.
template <bool kAnyHit, bool kCount, class K>
bool BruteForce::traverse(Ray& ray, Hit& hit, TraversalStats* stats) const {
  const WatertightRay wr(ray);
  const auto n = static_cast<std::uint32_t>(m_ids.size());
  if constexpr (kAnyHit) {
    for (std::uint32_t i = 0; i < n; ++i) {
      if (m_geometry.occluded(m_ids[i], wr, ray)) {
        if constexpr (kCount) {
          stats->prim_tests += i + 1;
          ++stats->hits;
        }
        return true;
      }
    }
    if constexpr (kCount) stats->prim_tests += n;
    return false;
  } else {
    bool found = false;
    for (std::uint32_t id : m_ids) found |= m_geometry.intersect(id, wr, ray, hit);
    if constexpr (kCount) {
      stats->prim_tests += n;
      stats->hits += found ? 1 : 0;
    }
    return found;
  }
}

void BruteForce::all_hits(const Ray& ray, std::vector<Hit>& hits) const {
  if (!traceable_direction(ray.direction)) return;  // no ray (see traceable_direction)
  const WatertightRay wr(ray);
  const std::size_t first = hits.size();
  for (std::uint32_t id : m_ids) {
    Ray probe = ray;
    Hit hit;
    if (m_geometry.intersect(id, wr, probe, hit)) hits.push_back(hit);
  }
  order_all_hits(hits, first);
}

AccelInfo BruteForce::info() const {
  AccelInfo info;
  info.name = "brute";
  info.build_seconds = m_build_seconds;
  info.memory_bytes = sizeof(*this) + m_ids.capacity() * sizeof(std::uint32_t);
  info.primitive_count = m_ids.size();
  return info;
}

// The reference has no kernel of its own: every set's name calls the one compilation above,
// so that brute force answers the same whatever the active set.
RAYLAB_INSTANTIATE_TRAVERSE_AS(BruteForce, KernelIsa);
#ifdef RAYLAB_KERNELS_AVX2
RAYLAB_INSTANTIATE_TRAVERSE_AS(BruteForce, isa_avx2::KernelIsa);
#endif
#ifdef RAYLAB_KERNELS_AVX512
RAYLAB_INSTANTIATE_TRAVERSE_AS(BruteForce, isa_avx512::KernelIsa);
#endif
template class TraversalAccelerator<BruteForce>;

}  // namespace raylab
