#pragma once
/// \file
/// Eric Haines' SPD testing procedure: a fixed way to render a scene so that ray counts (and
/// times) can be compared between ray tracers.

#include <cstdint>

#include "raylab/accel/accelerator.h"
#include "raylab/render/film.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// The ray-count invariants of the procedure. They depend only on the scene (and its camera and
/// lights), never on the acceleration structure.
struct SpdProtocolCounts {
  std::uint64_t primary = 0;         ///< eye rays: (width + 1) x (height + 1)
  std::uint64_t primary_hits = 0;    ///< eye rays that hit an object
  std::uint64_t shadow = 0;          ///< shadow rays cast (only toward lights the surface faces)
  std::uint64_t shadow_hits = 0;     ///< shadow rays that hit something (the point is in shadow)
  std::uint64_t secondary = 0;       ///< reflected plus refracted rays
  std::uint64_t secondary_hits = 0;  ///< of which hit an object
};

/// What a protocol render reports.
struct SpdProtocolResult {
  SpdProtocolCounts counts;
  RenderStats stats;     ///< the same rays by kind, with traversal work when counted
  double seconds = 0.0;  ///< wall-clock time of tracing
};

/// Image size the procedure prescribes.
inline constexpr int kSpdProtocolSize = 512;

/// Renders `scene` by the SPD testing procedure into `film` (kSpdProtocolSize squared): one eye
/// ray through each pixel corner, (512 + 1)^2 rays, a pixel being the average of its four
/// corners; ray trees 5 deep with no adaptive cutoff. The outermost corner rays lie on the
/// camera's field of view (NFF's angle spans the outermost sample rows, which are here the
/// corners). Sets `scene.settings` to the procedure's size and depth first.
SpdProtocolResult render_spd_protocol(Scene& scene, const Accelerator& accel, Film& film,
                                      const RenderOptions& options = {});

}  // namespace raylab
