#pragma once
/// \file
/// What every integrator shares while it traces: the per-thread trace context, the facing rule
/// for shadow rays, and the visible-surface record that adaptive sampling (and AOVs) read.

#include <cstdint>

#include "raylab/accel/accelerator.h"
#include "raylab/core/stats.h"
#include "raylab/core/vec3.h"
#include "raylab/scene/scene.h"

namespace raylab {

class Integrator;

/// Which normal decides whether a surface faces a light (the SPD testing procedure's rule 10: "a
/// shadow ray is not generated if the surface normal points away from the light"). The rule can
/// be read two ways, and published ray counts differ by which one their tracer followed.
enum class ShadowFacing : std::uint8_t {
  /// The normal turned toward the arriving ray: a surface is lit from the side the ray sees. At a
  /// hit on the inside of a glass sphere, shadow rays go toward the lights on the inner side of
  /// the tangent plane there.
  kViewer = 0,
  /// The primitive's own (outward) normal, whichever side the ray came from. At a hit on the
  /// inside of a glass sphere no shadow ray goes toward a light on the inner side of the tangent
  /// plane (behind the surface, seen from outside); one goes toward each light on the outer side,
  /// and is counted, but adds nothing: the side the ray sees faces away from that light.
  kOutward,
};

/// Everything one thread needs to trace: the scene, its structure, whether to count traversal
/// work, where to count, the facing rule for shadow rays, and the integrator of the render.
struct TraceContext {
  const Scene& scene;
  const Accelerator& accel;
  RenderStats& stats;
  bool count_traversal = false;                        ///< use the counted kernels (slower; for --stats)
  ShadowFacing shadow_facing = ShadowFacing::kViewer;  ///< which normal must face a light for a shadow ray
  /// The integrator the pixel loops call for a camera ray's radiance (the render's own; the SPD
  /// protocol, which always traces Whitted, leaves it null).
  const Integrator* integrator = nullptr;
};

/// What a primary ray met first: the features adaptive sampling compares between samples.
struct PrimaryFeature {
  std::int32_t object = -1;    ///< object id of the first hit; -1 when the ray left the scene
  Vec3 normal{0.f, 0.f, 0.f};  ///< unit shading normal there (zero when nothing was hit)
};

}  // namespace raylab
