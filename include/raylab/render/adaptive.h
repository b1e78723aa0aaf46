#pragma once
/// \file
/// Adaptive supersampling: pixel-loop policies that look at the colours already traced and spend
/// more rays only where the image needs them. See docs/antialiasing.md for the rules.

#include <span>
#include <string_view>

#include "raylab/accel/accelerator.h"
#include "raylab/render/film.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// Names of the adaptive samplers: "adaptive-corners" (the lecture's method) and "adaptive".
std::span<const std::string_view> adaptive_sampler_names();

/// True when `name` is an adaptive sampler.
bool is_adaptive_sampler(std::string_view name);

/// Parameters shared by both adaptive samplers.
struct AdaptiveParams {
  /// Refinement trigger: the largest difference of two samples' display-encoded (sRGB) colour
  /// in any channel, in [0, 1].
  float threshold = 0.1f;
  /// Most levels of subdivision: a pixel holds at most 4^depth cells.
  int depth = 3;
  /// adaptive only: a change of shading normal between two samples larger than this angle
  /// (cosine) also triggers refinement.
  float normal_cosine = 0.9f;
  /// adaptive only: objects whose projection is at most this many pixels wide and tall are
  /// refined wherever they appear, since base samples a pixel apart can miss them; 0: off.
  float small_object_pixels = 4.f;
};

/// The depth that lets a pixel hold at most `spp` samples: floor(log4 spp) (1 -> 0, 4 -> 1,
/// 16 -> 2, 64 -> 3).
int adaptive_depth_for_spp(int spp);

/// The parameters a render uses for adaptive sampler `name` under `settings`: aa_threshold and
/// aa_depth where set (>= 0), otherwise the sampler's defaults; a depth derived from spp
/// (adaptive_depth_for_spp) when spp > 1 and aa_depth is not set.
AdaptiveParams adaptive_params(std::string_view name, const RenderSettings& settings);

/// The lecture's adaptive supersampling. Rays go through every pixel corner (shared by the four
/// pixels that meet there). Where a cell's four corner colours differ by more than the
/// threshold, the midpoints of its edges and its centre are traced and its four quarters are
/// treated the same way, down to `depth` levels; a cell that is not split takes the mean of its
/// corners, weighted by its area. Deterministic (no random placement).
RenderResult render_adaptive_corners(const Scene& scene, const Accelerator& accel, Film& film,
                                     const RenderOptions& options, const AdaptiveParams& params);

/// Adaptive sampling that does not miss what falls between corners: one jittered sample per
/// pixel; a pixel is refined when the samples of its 3 x 3 neighbourhood differ (colour, object
/// or normal); a refined pixel gets a 4 x 4 stratified set (nested: the first sample keeps its
/// place), its quarters are split further where their samples still differ, and the refinement
/// spreads to the neighbours of every refined pixel whose own samples differ, until no new pixel
/// qualifies. Samples are weighted by the area of their stratum.
RenderResult render_adaptive(const Scene& scene, const Accelerator& accel, Film& film, const RenderOptions& options,
                             const AdaptiveParams& params);

}  // namespace raylab
