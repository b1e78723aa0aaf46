#pragma once
// Internal to the render module: the tests adaptive sampling uses to decide that samples differ.

#include <algorithm>
#include <span>

#include "raylab/core/srgb.h"
#include "raylab/core/vec3.h"

namespace raylab::detail {

/// A colour as the display shows it: each channel through the sRGB curve, in [0, 1]. Contrast is
/// judged here, where a difference means the same to the eye in dark and bright areas.
inline Color display_encoded(Color c) { return {linear_to_srgb(c.x), linear_to_srgb(c.y), linear_to_srgb(c.z)}; }

/// Running minimum and maximum of display-encoded colours, per channel.
struct ContrastRange {
  Color lo{2.f, 2.f, 2.f};
  Color hi{-1.f, -1.f, -1.f};

  /// Widens the range by `display` (display-encoded).
  void add(Color display) {
    lo = {std::min(lo.x, display.x), std::min(lo.y, display.y), std::min(lo.z, display.z)};
    hi = {std::max(hi.x, display.x), std::max(hi.y, display.y), std::max(hi.z, display.z)};
  }
  /// The largest difference in any channel (0 when fewer than two colours were added).
  float contrast() const { return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 0.f}); }
};

}  // namespace raylab::detail
