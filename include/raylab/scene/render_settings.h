#pragma once
/// \file
/// Settings a scene carries and the command line may override.

#include <cstdint>
#include <string>

#include "raylab/core/vec3.h"

namespace raylab {

/// Image size, sampling and recursion settings, with the defaults used when nothing says otherwise.
struct RenderSettings {
  int width = 640;                   ///< image width in pixels
  int height = 480;                  ///< image height in pixels
  int spp = 1;                       ///< samples per pixel (jittered on a sqrt(spp) grid where square)
  std::string sampler = "jittered";  ///< pixel sample placement (see --sampler)
  int max_depth = 5;                 ///< ray tree depth: 1 = eye rays only (SPD testing procedure: 5)
  std::uint64_t seed = 0;            ///< seed of every random choice
  Color background{0.f, 0.f, 0.f};   ///< radiance of rays that leave the scene
  bool sky_gradient = false;         ///< background blends towards `horizon` near the horizon
  Color horizon{1.f, 1.f, 1.f};      ///< the gradient's horizon colour
  Color ambient{0.f, 0.f, 0.f};      ///< Whitted's ambient term: added as ambient * kd * diffuse colour
};

}  // namespace raylab
