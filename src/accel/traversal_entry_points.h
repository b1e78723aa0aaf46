#pragma once
// The definitions of TraversalAccelerator's entry points (internal to src/accel): included by the
// source that instantiates TraversalAccelerator<Structure>, compiled once with the library's own
// flags. Each entry point calls the kernel of the structure's instruction set (with_kernels).

#include "kernel_dispatch.h"
#include "raylab/accel/traversal_accelerator.h"

namespace raylab {

// Defined out of the class, so not inline: with a structure's `extern template` declaration,
// other files call the instantiation its own source file compiles, and never need the kernel.
template <class Structure>
bool TraversalAccelerator<Structure>::intersect(Ray& ray, Hit& hit) const {
  if (!traceable_direction(ray.direction)) return false;  // no ray (see traceable_direction)
  return with_kernels(kernel_isa(),
                      [&]<class K>() { return self().template traverse<false, false, K>(ray, hit, nullptr); });
}

template <class Structure>
bool TraversalAccelerator<Structure>::occluded(const Ray& ray) const {
  if (!traceable_direction(ray.direction)) return false;  // no ray (see traceable_direction)
  Ray probe = ray;
  Hit scratch;
  return with_kernels(kernel_isa(),
                      [&]<class K>() { return self().template traverse<true, false, K>(probe, scratch, nullptr); });
}

template <class Structure>
bool TraversalAccelerator<Structure>::intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const {
  if (!traceable_direction(ray.direction)) return false;  // no ray (see traceable_direction)
  return with_kernels(kernel_isa(),
                      [&]<class K>() { return self().template traverse<false, true, K>(ray, hit, &stats); });
}

template <class Structure>
bool TraversalAccelerator<Structure>::occluded_counted(const Ray& ray, TraversalStats& stats) const {
  if (!traceable_direction(ray.direction)) return false;  // no ray (see traceable_direction)
  Ray probe = ray;
  Hit scratch;
  return with_kernels(kernel_isa(),
                      [&]<class K>() { return self().template traverse<true, true, K>(probe, scratch, &stats); });
}

}  // namespace raylab
