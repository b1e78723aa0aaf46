#pragma once
// What the demo scene and the aa-whitted chart share: the look of Whitted's 1980 image, a blue
// sky graded to a pale horizon over a mirror ball and a glass ball. Written once, so that the
// chart keeps testing the materials the demo shows.

#include "raylab/scene/material.h"
#include "raylab/scene/render_settings.h"

namespace raylab::whitted_detail {

/// Sets the sky: a gradient from a blue zenith to a pale horizon.
void set_whitted_sky(RenderSettings& settings);

/// The mirror ball: a near-perfect mirror with a sharp Phong highlight of weight `ks`.
Material whitted_mirror(float ks);

/// The glass ball: clear glass of index 1.5 with a sharp Phong highlight of weight `ks`.
Material whitted_glass(float ks);

}  // namespace raylab::whitted_detail
