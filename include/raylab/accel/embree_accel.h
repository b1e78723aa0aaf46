#pragma once
/// \file
/// Embree 3 as an accelerator (`--accel embree`): the reference tracer behind the same interface.

#include <cstdint>
#include <memory>
#include <span>

#include "raylab/accel/accelerator.h"
#include "raylab/geometry/geometry.h"

namespace raylab {

/// True when raylab was built with Embree 3 (then the factory offers "embree").
bool embree_available();

/// Builds an Embree scene over the primitives (or groups) `ids` of `geometry`, which must outlive
/// it: triangles as Embree triangles (robust mode, watertight like ours), everything else as user
/// geometry calling back into `geometry`. Hits are in our convention (global ids, u and v the
/// weights of p1 and p2, [tmin, tmax)); equal-distance ties between triangles follow Embree's
/// traversal order, not the lower-id rule. Rays Embree cannot trace (NaN, infinite or huge
/// components, tmin < 0) are answered by brute force over the same ids. Counted queries count
/// hits only (Embree exposes no traversal counts). Safe to query from many threads. Throws
/// UsageError when raylab was built without Embree, std::runtime_error when Embree fails.
std::unique_ptr<Accelerator> make_embree_accelerator(const Geometry& geometry, std::span<const std::uint32_t> ids);

}  // namespace raylab
