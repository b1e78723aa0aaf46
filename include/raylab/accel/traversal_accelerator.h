#pragma once
/// \file
/// The four single-ray entry points of Accelerator, written once for every structure that has
/// one traversal kernel for all of them.

#include "raylab/accel/accelerator.h"
#include "raylab/core/isa.h"

namespace raylab {

/// Derives `intersect`, `occluded`, `intersect_counted` and `occluded_counted` from the
/// structure's one kernel (the curiously recurring template pattern):
///
///     template <bool kAnyHit, bool kCount, class K>
///     bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
///
/// kAnyHit asks for any hit instead of the closest; kCount adds the work to `*stats` (null
/// otherwise); K names the instruction set whose compilation of the kernel runs: the one
/// active when the structure was built (raylab/core/isa.h), kept for its lifetime. The kernel has the contract of
/// `intersect`: on a hit it fills `hit` and shrinks `ray.tmax`. Any-hit queries pass it copies, so an occlusion test
/// leaves the caller's ray alone. A ray without a traceable direction (traceable_direction) misses here, before any
/// kernel sees it. A structure declares `friend class TraversalAccelerator<Structure>` when its kernel is
/// private. The entry points are defined in src/accel/traversal_entry_points.h and instantiated
/// once, with the library's own flags, in the structure's build source; the kernel source is
/// compiled once per instruction set (src/CMakeLists.txt) and instantiates the kernel for it.
template <class Structure>
class TraversalAccelerator : public Accelerator {
 public:
  bool intersect(Ray& ray, Hit& hit) const final;
  bool occluded(const Ray& ray) const final;
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const final;
  bool occluded_counted(const Ray& ray, TraversalStats& stats) const final;
  using Accelerator::intersect;
  using Accelerator::occluded;

  /// The instruction set whose kernels this structure runs.
  Isa kernel_isa() const { return m_kernel_isa; }

 private:
  const Isa m_kernel_isa = active_isa();

  const Structure& self() const { return static_cast<const Structure&>(*this); }
};

}  // namespace raylab
