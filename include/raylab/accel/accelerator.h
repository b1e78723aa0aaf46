#pragma once
/// \file
/// The one interface every acceleration structure implements.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "raylab/core/box.h"
#include "raylab/core/ray.h"
#include "raylab/core/stats.h"

namespace raylab {

/// What a structure reports about itself after the build.
struct AccelInfo {
  std::string name;                 ///< factory name ("bvh", "brute", ...)
  double build_seconds = 0.0;       ///< wall-clock build time
  std::size_t memory_bytes = 0;     ///< bytes held by the structure (nodes, references, copies)
  std::size_t node_count = 0;       ///< nodes or cells (0 for brute force)
  std::size_t leaf_count = 0;       ///< leaves (0 for brute force)
  std::size_t primitive_count = 0;  ///< primitives indexed
  int max_depth = 0;                ///< deepest leaf
};

/// An acceleration structure over a Geometry. It answers closest-hit and any-hit queries for one
/// ray or a group of rays; one virtual call per query, nothing virtual per node or primitive.
/// The structure refers to the Geometry it was built from, which must outlive it unchanged.
class Accelerator {
 public:
  virtual ~Accelerator() = default;

  /// Bounds of everything the structure holds.
  virtual Box3 bounds() const = 0;

  /// Closest hit in [ray.tmin, ray.tmax). On a hit returns true, fills `hit` (t, prim_id, u, v)
  /// and shrinks `ray.tmax` to `hit.t`; on a miss leaves both unchanged.
  virtual bool intersect(Ray& ray, Hit& hit) const = 0;

  /// True when anything lies in [ray.tmin, ray.tmax) (shadow rays); may stop at the first hit.
  virtual bool occluded(const Ray& ray) const = 0;

  /// `intersect` that also adds its traversal work to `stats`. A separate entry point so that the
  /// timed path (`intersect`) is compiled without any counting.
  virtual bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const = 0;

  /// `occluded` that also adds its traversal work to `stats`.
  virtual bool occluded_counted(const Ray& ray, TraversalStats& stats) const = 0;

  /// Closest hits for a group of rays (same contract as `intersect`, element by element).
  /// The default traces the rays one by one; structures with packet kernels override it.
  virtual void intersect(std::span<Ray> rays, std::span<Hit> hits) const;

  /// Any-hit for a group of rays: `occluded[i]` is set to 1 or 0. Default: one by one.
  virtual void occluded(std::span<const Ray> rays, std::span<std::uint8_t> occluded) const;

  /// Every primitive hit in [ray.tmin, ray.tmax), appended to `hits` sorted by (t, prim_id),
  /// each primitive once: for counting the surfaces a ray crosses. The default finds them as
  /// successive closest hits, each search starting just past the last one's distance, so two
  /// primitives hit at exactly the same float distance count as one; structures that can
  /// visit every hit override it with an exact walk (brute force, the wide BVH).
  virtual void all_hits(const Ray& ray, std::vector<Hit>& hits) const;

  /// Build time, memory and sizes.
  virtual AccelInfo info() const = 0;
};

}  // namespace raylab
