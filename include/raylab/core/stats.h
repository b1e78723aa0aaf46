#pragma once
/// \file
/// Counters gathered per thread during a render and merged afterwards.

#include <cstdint>

namespace raylab {

/// Traversal work counted inside accelerator kernels. Counting is a compile-time choice
/// (`intersect_counted` / `occluded_counted`): the timed path does not touch this record.
struct TraversalStats {
  std::uint64_t nodes_visited = 0;  ///< interior + leaf nodes (or cells) whose box was tested
  std::uint64_t prim_tests = 0;     ///< ray-primitive intersection tests
  std::uint64_t hits = 0;           ///< queries that found a hit
  std::uint64_t volume_tests = 0;   ///< bounding volumes (wrappers of meshes and instances) tested

  /// Adds another record's counts to this one.
  constexpr TraversalStats& operator+=(const TraversalStats& o) {
    nodes_visited += o.nodes_visited;
    prim_tests += o.prim_tests;
    hits += o.hits;
    volume_tests += o.volume_tests;
    return *this;
  }
};

/// The kinds of ray a Whitted integrator casts.
enum class RayKind : int { kPrimary = 0, kShadow, kReflection, kRefraction, kCount };

/// Name of a ray kind for reports ("primary", "shadow", ...).
const char* ray_kind_name(RayKind kind);

/// Per-render statistics: rays by kind and traversal work by kind.
struct RenderStats {
  std::uint64_t rays[static_cast<int>(RayKind::kCount)] = {};      ///< rays cast, by kind
  std::uint64_t ray_hits[static_cast<int>(RayKind::kCount)] = {};  ///< of which hit something
  TraversalStats traversal;  ///< summed over every ray (zero unless counting was enabled)
  /// Samples whose radiance came out NaN or infinite (from any path of the sample's ray tree);
  /// each was replaced by black, so that one bad sample cannot poison its pixel.
  std::uint64_t nonfinite_samples = 0;
  /// Transmitter hits (below the depth limit) where Snell's law has no refracted direction: total
  /// internal reflection, which spawns a reflection ray and no refraction ray.
  std::uint64_t total_internal_reflections = 0;

  /// Counts one ray of `kind`, and whether it hit.
  constexpr void count(RayKind kind, bool hit) {
    ++rays[static_cast<int>(kind)];
    ray_hits[static_cast<int>(kind)] += hit ? 1u : 0u;
  }
  /// Total rays of every kind.
  constexpr std::uint64_t total_rays() const {
    std::uint64_t n = 0;
    for (auto r : rays) n += r;
    return n;
  }
  /// Adds another record's counts to this one.
  constexpr RenderStats& operator+=(const RenderStats& o) {
    for (int i = 0; i < static_cast<int>(RayKind::kCount); ++i) {
      rays[i] += o.rays[i];
      ray_hits[i] += o.ray_hits[i];
    }
    traversal += o.traversal;
    nonfinite_samples += o.nonfinite_samples;
    total_internal_reflections += o.total_internal_reflections;
    return *this;
  }
};

}  // namespace raylab
