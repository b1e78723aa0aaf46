#pragma once
// Rendering, images and the lab's measurements from Python (internal to the module).

#include <pybind11/pybind11.h>

namespace raylab::python {

/// Adds render, write_image, pinhole_rays and compare to `m`.
void bind_render(pybind11::module_& m);

}  // namespace raylab::python
