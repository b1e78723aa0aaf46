#include "raylab/accel/brute_force.h"
#include "raylab/core/stopwatch.h"

#include <algorithm>
#include <chrono>

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

template <bool kCount>
bool BruteForce::intersect_impl(Ray& ray, Hit& hit, TraversalStats* stats) const {
  const WatertightRay wr(ray);
  bool found = false;
  const auto n = static_cast<std::uint32_t>(m_ids.size());
  for (std::uint32_t id : m_ids) found |= m_geometry.intersect(id, wr, ray, hit);
  if constexpr (kCount) {
    stats->prim_tests += n;
    stats->hits += found ? 1 : 0;
  }
  return found;
}

template <bool kCount>
bool BruteForce::occluded_impl(const Ray& ray, TraversalStats* stats) const {
  const WatertightRay wr(ray);
  const auto n = static_cast<std::uint32_t>(m_ids.size());
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
}

bool BruteForce::intersect(Ray& ray, Hit& hit) const { return intersect_impl<false>(ray, hit, nullptr); }
bool BruteForce::occluded(const Ray& ray) const { return occluded_impl<false>(ray, nullptr); }
bool BruteForce::intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const {
  return intersect_impl<true>(ray, hit, &stats);
}
bool BruteForce::occluded_counted(const Ray& ray, TraversalStats& stats) const {
  return occluded_impl<true>(ray, &stats);
}

AccelInfo BruteForce::info() const {
  AccelInfo info;
  info.name = "brute";
  info.build_seconds = m_build_seconds;
  info.memory_bytes = sizeof(*this) + m_ids.capacity() * sizeof(std::uint32_t);
  info.primitive_count = m_ids.size();
  return info;
}

}  // namespace raylab
