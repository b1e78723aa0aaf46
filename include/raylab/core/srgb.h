#pragma once
/// \file
/// The sRGB transfer curve: how linear radiance is encoded for display (8-bit images, the
/// contrast tests of adaptive sampling, the perceptual error measures).

#include <array>

namespace raylab {

/// Linear to sRGB-encoded value in [0, 1] (clamped; NaN gives 0).
float linear_to_srgb(float linear);

/// sRGB-encoded value in [0, 1] to linear.
float srgb_to_linear(float encoded);

/// srgb_to_linear of each 8-bit code i / 255, computed once: for decoding 8-bit images per
/// value rather than per pixel channel.
const std::array<float, 256>& srgb8_to_linear_table();

}  // namespace raylab
