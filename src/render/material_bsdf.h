#pragma once
// Internal to the render module: the one place where a material, as its source described it,
// becomes the path integrator's scattering model (docs/rendering.md has the table).

#include "raylab/render/bsdf.h"
#include "raylab/scene/material.h"

namespace raylab::detail {

/// The BSDF of material `m` at a point where its textured parameters are `at`. A material
/// that mixes two models (glTF's fractional metallic or transmission) picks one with `u_mix`, in
/// proportion to its weight: the one-sample estimate of the mixture.
Bsdf material_bsdf(const Material& m, const MaterialPoint& at, float u_mix);

}  // namespace raylab::detail
