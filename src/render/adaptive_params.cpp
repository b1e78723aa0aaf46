// Names and parameters of the adaptive samplers (the pixel loops are in adaptive_corners.cpp and
// adaptive_sampler.cpp).

#include <array>
#include <cmath>

#include "raylab/render/adaptive.h"

namespace raylab {
namespace {

constexpr std::array<std::string_view, 2> kNames = {"adaptive-corners", "adaptive"};

}  // namespace

std::span<const std::string_view> adaptive_sampler_names() { return kNames; }

bool is_adaptive_sampler(std::string_view name) { return name == kNames[0] || name == kNames[1]; }

int adaptive_depth_for_spp(int spp) {
  int depth = 0;
  while (depth < 8 && (1 << (2 * (depth + 1))) <= spp) ++depth;
  return depth;
}

AdaptiveParams adaptive_params(std::string_view name, const RenderSettings& settings) {
  AdaptiveParams p;
  if (name == "adaptive-corners") p.depth = 2;
  if (settings.aa_threshold >= 0.f) p.threshold = settings.aa_threshold;
  if (settings.aa_depth >= 0) {
    p.depth = settings.aa_depth;
  } else if (settings.spp > 1) {
    p.depth = adaptive_depth_for_spp(settings.spp);
  }
  return p;
}

}  // namespace raylab
