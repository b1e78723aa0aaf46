#pragma once
/// \file
/// Render settings given apart from the scene (by a command line, a script or a checkpoint being
/// resumed), each one replacing the scene's own only when given.

#include <cstdint>
#include <optional>
#include <string>

#include "raylab/scene/render_settings.h"

namespace raylab {

/// The RenderSettings a caller may set over a scene's; an empty member leaves the scene's value.
struct SettingsOverride {
  std::optional<int> width;            ///< image width in pixels
  std::optional<int> height;           ///< image height in pixels
  std::optional<int> spp;              ///< samples per pixel
  std::optional<int> max_depth;        ///< ray tree depth
  std::optional<std::uint64_t> seed;   ///< seed of every random choice
  std::optional<std::string> sampler;  ///< sampler name (as --sampler)
  std::optional<std::string> filter;   ///< reconstruction filter name
  std::optional<float> filter_radius;  ///< filter half-width in pixels
  std::optional<float> aa_threshold;   ///< adaptive samplers: refinement contrast
  std::optional<int> aa_depth;         ///< adaptive samplers: subdivision depth
  // Later members last, with initialisers, so that positional initialisers of the members above
  // stay valid (and warning-free).
  std::optional<std::string> integrator{};  ///< integrator name (as --integrator)
  /// The environment, as --env names it ("R,G,B" or an image file). Not a RenderSettings member:
  /// apply_render_overrides (io) loads it into Scene::environment.
  std::optional<std::string> environment{};
  std::optional<float> environment_rotate{};  ///< --env-rotate: degrees about +y (applied with `environment`)
};

/// Sets every member `over` gives on `settings`, leaving the others as they are; a sampler that
/// takes one sample per pixel given without a count also sets spp to 1. No checks: the
/// values go through check_sampling_settings and render() as the scene's own would.
void apply_settings_override(RenderSettings& settings, const SettingsOverride& over);

}  // namespace raylab
