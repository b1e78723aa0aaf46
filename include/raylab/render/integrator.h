#pragma once
/// \file
/// The integrator interface: what turns a camera ray into radiance. The pixel loops (uniform,
/// adaptive, adaptive-corners, tile renderer) call it; each integrator is a file of its own,
/// chosen by name through make_integrator(), like the accelerators.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "raylab/core/ray.h"
#include "raylab/core/vec3.h"
#include "raylab/render/sample_source.h"
#include "raylab/render/trace_context.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Computes the radiance arriving at the camera along a primary ray. Implementations are
/// immutable once made (many threads call radiance() at once) and draw every random number
/// from the SampleSource, so an image never depends on the thread that traced it.
class Integrator {
 public:
  virtual ~Integrator() = default;

  /// The name the command line and scene files use ("whitted", "path").
  virtual std::string_view name() const = 0;

  /// Radiance arriving along primary ray `ray`. Counts the rays it casts in ctx.stats; `feature`
  /// (optional) receives what `ray` itself hit.
  virtual Color radiance(const TraceContext& ctx, const Ray& ray, SampleSource& samples,
                         PrimaryFeature* feature = nullptr) const = 0;

  /// True when the packet path (primary rays and the shadow rays toward point lights grouped
  /// into packets, RenderOptions::packets) gives this integrator's image bit for bit.
  virtual bool traces_packets() const { return false; }
};

/// The integrator names, in the order help lists them.
std::span<const std::string_view> integrator_names();

/// Throws UsageError naming the valid integrators unless `name` is one of them.
void check_integrator_name(std::string_view name);

/// The integrator `name` for `scene` (which must outlive it: integrators keep what they
/// precompute from it, such as the light list). Throws UsageError for an unknown name.
std::unique_ptr<Integrator> make_integrator(std::string_view name, const Scene& scene);

}  // namespace raylab
