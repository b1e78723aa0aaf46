#pragma once
/// \file
/// Measured complex indices of refraction of named metals: plain data a scene names (a
/// conductor material) and the conductor BSDF's Fresnel term reads.

#include <optional>
#include <string_view>

#include "raylab/core/vec3.h"

namespace raylab {

/// Complex index of refraction of a conductor at the red, green and blue wavelengths the
/// renderer uses for its three channels (about 650, 550 and 450 nm), relative to the medium
/// the light arrives from.
struct ConductorIor {
  Color eta{1.f, 1.f, 1.f};  ///< real part n
  Color k{0.f, 0.f, 0.f};    ///< imaginary part (extinction coefficient)
};

/// Gold (Johnson and Christy 1972; src/scene/metals.cpp gives the sources): the default metal.
inline constexpr ConductorIor kGoldIor{{0.1678f, 0.3504f, 1.5085f}, {3.1378f, 2.7141f, 1.8788f}};

/// The measured complex index of a named metal ("gold", "copper", "aluminium" (also
/// "aluminum"), "silver"); std::nullopt for an unknown name.
std::optional<ConductorIor> metal_ior(std::string_view name);

}  // namespace raylab
