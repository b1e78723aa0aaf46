#pragma once
// Test helper: one primary ray traced by the Whitted integrator through a BVH, with the rays it
// cost.

#include <memory>

#include "raylab/accel/factory.h"
#include "raylab/render/whitted.h"

namespace raylab::test {

/// What one traced ray gave, with the rays it cost.
struct Traced {
  Color color;
  RenderStats stats;
};

/// Traces one primary ray from `origin` along `direction` through a BVH over `scene` (which must
/// not change afterwards), shadow rays by the `facing` reading of rule 10.
inline Traced trace_one(const Scene& scene, Vec3 origin, Vec3 direction, ShadowFacing facing = ShadowFacing::kViewer) {
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  Traced out;
  const TraceContext ctx{scene, *accel, out.stats, false, facing};
  Pcg32 rng(7);
  Ray ray;
  ray.origin = origin;
  ray.direction = normalize(direction);
  out.color = WhittedIntegrator::trace(ctx, ray, 1, RayKind::kPrimary, rng);
  return out;
}

}  // namespace raylab::test
