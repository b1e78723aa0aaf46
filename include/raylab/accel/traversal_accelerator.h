#pragma once
/// \file
/// The four single-ray entry points of Accelerator, written once for every structure that has
/// one traversal kernel for all of them.

#include "raylab/accel/accelerator.h"

namespace raylab {

/// Derives `intersect`, `occluded`, `intersect_counted` and `occluded_counted` from the
/// structure's one kernel (the curiously recurring template pattern):
///
///     template <bool kAnyHit, bool kCount>
///     bool traverse(Ray& ray, Hit& hit, TraversalStats* stats) const;
///
/// kAnyHit asks for any hit instead of the closest; kCount adds the work to `*stats` (null
/// otherwise). The kernel has the contract of `intersect`: on a hit it fills `hit` and shrinks
/// `ray.tmax`. Any-hit queries pass it copies, so an occlusion test leaves the caller's ray
/// alone. A ray without a traceable direction (traceable_direction) misses here, before any
/// kernel sees it. A structure declares `friend class TraversalAccelerator<Structure>` when its kernel is
/// private, and instantiates this class in the source file that defines the kernel (see
/// uniform_grid.cpp), so the four entry points are compiled there once.
template <class Structure>
class TraversalAccelerator : public Accelerator {
 public:
  bool intersect(Ray& ray, Hit& hit) const final;
  bool occluded(const Ray& ray) const final;
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const final;
  bool occluded_counted(const Ray& ray, TraversalStats& stats) const final;
  using Accelerator::intersect;
  using Accelerator::occluded;

 private:
  const Structure& self() const { return static_cast<const Structure&>(*this); }
};

// Defined out of the class, so not inline: with a structure's `extern template` declaration,
// other files call the instantiation its own source file compiles, and never need the kernel.
template <class Structure>
bool TraversalAccelerator<Structure>::intersect(Ray& ray, Hit& hit) const {
  if (!traceable_direction(ray.direction)) return false;  // no ray (see traceable_direction)
  return self().template traverse<false, false>(ray, hit, nullptr);
}

template <class Structure>
bool TraversalAccelerator<Structure>::occluded(const Ray& ray) const {
  if (!traceable_direction(ray.direction)) return false;  // no ray (see traceable_direction)
  Ray probe = ray;
  Hit scratch;
  return self().template traverse<true, false>(probe, scratch, nullptr);
}

template <class Structure>
bool TraversalAccelerator<Structure>::intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const {
  if (!traceable_direction(ray.direction)) return false;  // no ray (see traceable_direction)
  return self().template traverse<false, true>(ray, hit, &stats);
}

template <class Structure>
bool TraversalAccelerator<Structure>::occluded_counted(const Ray& ray, TraversalStats& stats) const {
  if (!traceable_direction(ray.direction)) return false;  // no ray (see traceable_direction)
  Ray probe = ray;
  Hit scratch;
  return self().template traverse<true, true>(probe, scratch, &stats);
}

}  // namespace raylab
