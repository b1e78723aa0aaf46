#pragma once
/// \file
/// The sRGB transfer curve: how linear radiance is encoded for display (8-bit images, the
/// contrast tests of adaptive sampling, the perceptual error measures).

namespace raylab {

/// Linear to sRGB-encoded value in [0, 1] (clamped; NaN gives 0).
float linear_to_srgb(float linear);

/// sRGB-encoded value in [0, 1] to linear.
float srgb_to_linear(float encoded);

}  // namespace raylab
