#pragma once
// Rendering, images and the lab's measurements from Python (internal to the module).

#include <pybind11/pybind11.h>

#include "raylab/render/film.h"
#include "raylab/scene/scene.h"

namespace raylab::python {

/// The scene a render or a measurement runs on: a path or name is loaded; a Scene is copied as
/// it is, and a Mesh (no lights, no camera of its own) gets a fitted camera and two lights, as a
/// mesh file does.
Scene scene_of(const pybind11::object& scene_or_path);

/// A linear image given as an (H, W, 3) array of real numbers, as a Film. Raises ValueError
/// naming `name` for another shape.
Film film_of(const pybind11::object& image, const char* name);

/// Adds render, write_image and pinhole_rays to `m`.
void bind_render(pybind11::module_& m);

/// Adds compare and quality, the lab's measurements, to `m`.
void bind_lab(pybind11::module_& m);

}  // namespace raylab::python
