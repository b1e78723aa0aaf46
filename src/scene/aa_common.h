#pragma once
// What the antialiasing charts share: their settings and the unlit material.

#include <cstdint>
#include <string>

#include "raylab/scene/scene.h"

namespace raylab::aa_detail {

/// Sets the charts' common render settings: 640 x 480, 1 sample per pixel, seed 0, ray depth
/// `max_depth`; the sampler and filter keep their defaults.
void set_chart_settings(Scene& scene, int max_depth);

/// An empty unlit chart: the charts' settings, no lights, ambient (1, 1, 1) and ray depth 1, so
/// that a surface of kd = 1 shows exactly its diffuse colour, and `background` where no surface
/// is hit.
Scene unlit_chart(Color background);

/// Adds an unlit material (kd 1, nothing else) of colour `color`; returns its index.
std::uint32_t add_unlit_material(Scene& scene, std::string name, Color color);

/// A quad with corners at image positions `a`, `a + u` and `a + v` (and `a + u + v`) on the
/// plane z = `z` of the pixel camera.
Quad image_quad(Vec2 a, Vec2 u, Vec2 v, float z = 0.f);

}  // namespace raylab::aa_detail
