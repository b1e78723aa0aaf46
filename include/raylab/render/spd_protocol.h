#pragma once
/// \file
/// Eric Haines' SPD testing procedure: a fixed way to render a scene so that ray counts (and
/// times) can be compared between ray tracers.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/render/film.h"
#include "raylab/render/renderer.h"
#include "raylab/render/whitted.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// The ray-count invariants of the procedure, by the rows of the SPD README's statistics table
/// (eye, reflect, refract and shadow rays) with the hits of each. They depend only on the scene
/// (its camera, lights and materials) and the facing rule, never on the acceleration structure.
struct SpdProtocolCounts {
  std::uint64_t primary = 0;          ///< eye rays: (width + 1) x (height + 1)
  std::uint64_t primary_hits = 0;     ///< eye rays that hit an object
  std::uint64_t reflection = 0;       ///< reflection rays (off reflectors and every transmitter hit)
  std::uint64_t reflection_hits = 0;  ///< of which hit an object
  std::uint64_t refraction = 0;       ///< refraction rays (transmitter hits without total internal reflection)
  std::uint64_t refraction_hits = 0;  ///< of which hit an object
  std::uint64_t shadow = 0;           ///< shadow rays cast (only toward lights the surface faces)
  std::uint64_t shadow_hits = 0;      ///< shadow rays that hit something (the point is in shadow)
  /// Transmitter hits that reflected totally: a reflection ray and no refraction ray (rule 9).
  /// Not in the published tables; refraction + this = the transmitter hits below the depth limit.
  std::uint64_t total_internal_reflections = 0;

  /// Reflection plus refraction rays (the "secondary rays" of Havran & Sixta's tables).
  std::uint64_t secondary() const { return reflection + refraction; }
  /// Reflection plus refraction rays that hit an object.
  std::uint64_t secondary_hits() const { return reflection_hits + refraction_hits; }
  /// Counts compare equal field by field.
  bool operator==(const SpdProtocolCounts&) const = default;
};

/// The counts of a finished render's statistics.
SpdProtocolCounts spd_protocol_counts(const RenderStats& stats);

/// What a protocol render reports.
struct SpdProtocolResult {
  SpdProtocolCounts counts;
  RenderStats stats;     ///< the same rays by kind, with traversal work when counted
  double seconds = 0.0;  ///< wall-clock time of tracing
};

/// The names of the readings of rule 10 (ShadowFacing), for the command line: "viewer", "outward".
std::vector<std::string> spd_facing_names();

/// The reading `name` names; empty for any other name.
std::optional<ShadowFacing> parse_spd_facing(std::string_view name);

/// The name of reading `facing`.
std::string_view spd_facing_name(ShadowFacing facing);

/// Image size the procedure prescribes.
inline constexpr int kSpdProtocolSize = 512;

/// Renders `scene` by the SPD testing procedure and replaces `film` with the image
/// (kSpdProtocolSize squared, whatever size `film` had): one eye ray through each pixel corner,
/// (512 + 1)^2 rays, a pixel being the average of its four corners; ray trees 5 deep with no
/// adaptive cutoff. The image takes over the corners' memory, so a caller that passes an empty
/// film (Film(0, 0)) allocates no pixels of its own. The outermost corner rays lie on the
/// camera's field of view (NFF's angle spans the outermost sample rows, which are here the
/// corners). Sets `scene.settings` to the procedure's size and depth first. `facing` is the
/// reading of rule 10 (which normal must face a light for a shadow ray to be cast).
SpdProtocolResult render_spd_protocol(Scene& scene, const Accelerator& accel, Film& film,
                                      const RenderOptions& options = {}, ShadowFacing facing = ShadowFacing::kViewer);

}  // namespace raylab
