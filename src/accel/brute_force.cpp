#include "raylab/accel/brute_force.h"

#include <chrono>

namespace raylab {

BruteForce::BruteForce(const Geometry& geometry) : m_geometry(geometry) {
  const auto start = std::chrono::steady_clock::now();
  m_bounds = geometry.bounds();
  m_build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <bool kCount>
bool BruteForce::intersect_impl(Ray& ray, Hit& hit, TraversalStats* stats) const {
  const WatertightRay wr(ray);
  bool found = false;
  const std::uint32_t n = m_geometry.size();
  for (std::uint32_t i = 0; i < n; ++i) found |= m_geometry.intersect(i, wr, ray, hit);
  if constexpr (kCount) {
    stats->prim_tests += n;
    stats->hits += found ? 1 : 0;
  }
  return found;
}

template <bool kCount>
bool BruteForce::occluded_impl(const Ray& ray, TraversalStats* stats) const {
  const WatertightRay wr(ray);
  Ray probe = ray;
  Hit scratch;
  const std::uint32_t n = m_geometry.size();
  for (std::uint32_t i = 0; i < n; ++i) {
    if (m_geometry.intersect(i, wr, probe, scratch)) {
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
  info.memory_bytes = sizeof(*this);
  info.primitive_count = m_geometry.size();
  return info;
}

}  // namespace raylab
