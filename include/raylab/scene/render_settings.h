#pragma once
/// \file
/// Settings a scene carries and the command line may override.

#include <cstdint>
#include <string>

#include "raylab/core/vec3.h"

namespace raylab {

/// Image size, sampling and recursion settings, with the defaults used when nothing says otherwise.
struct RenderSettings {
  int width = 640;                     ///< image width in pixels
  int height = 480;                    ///< image height in pixels
  int spp = 1;                         ///< samples per pixel (adaptive samplers: the most per pixel)
  std::string sampler = "auto";        ///< pixel sample placement (see --sampler); auto: center at 1 spp, else jittered
  std::string filter = "box";          ///< reconstruction filter (see --filter)
  float filter_radius = 0.f;           ///< filter half-width in pixels; 0 = the filter's default
  float aa_threshold = -1.f;           ///< adaptive samplers: contrast that triggers refinement; < 0 = default
  int aa_depth = -1;                   ///< adaptive samplers: subdivision depth; < 0 = derived from spp
  std::string integrator = "whitted";  ///< what computes a camera ray's radiance (see --integrator)
  int max_depth = 5;                   ///< ray tree depth: 1 = eye rays only (SPD testing procedure: 5)
  std::uint64_t seed = 0;              ///< seed of every random choice
  Color background{0.f, 0.f, 0.f};     ///< radiance of rays that leave the scene
  bool sky_gradient = false;           ///< background blends towards `horizon` near the horizon
  Color horizon{1.f, 1.f, 1.f};        ///< the gradient's horizon colour
  Color ambient{0.f, 0.f, 0.f};        ///< Whitted's ambient term: added as ambient * kd * diffuse colour
};

}  // namespace raylab
