#pragma once
// Internal to the render module: the tests adaptive sampling uses to decide that samples differ.

#include <algorithm>
#include <cmath>
#include <span>

#include "raylab/core/srgb.h"
#include "raylab/core/vec3.h"

namespace raylab::detail {

/// Running minimum and maximum of linear colours, per channel, and the contrast between them as
/// the display shows it: each channel through the sRGB curve, where a difference means the same
/// to the eye in dark and bright areas. The curve is monotonic, so only the two ends of each
/// channel's range need encoding, not every sample.
struct ContrastRange {
  Color lo{INFINITY, INFINITY, INFINITY};
  Color hi{-INFINITY, -INFINITY, -INFINITY};

  /// Widens the range by linear colour `c`.
  void add(Color c) {
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
  }
  /// The largest display-encoded difference in any channel, in [0, 1] (0 when fewer than two
  /// colours were added).
  float contrast() const {
    if (!(hi.x >= lo.x)) return 0.f;
    return std::max({linear_to_srgb(hi.x) - linear_to_srgb(lo.x), linear_to_srgb(hi.y) - linear_to_srgb(lo.y),
                     linear_to_srgb(hi.z) - linear_to_srgb(lo.z), 0.f});
  }
};

}  // namespace raylab::detail
