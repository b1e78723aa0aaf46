// The `raylab._raylab` extension module: numpy arrays in and out over the library's public API.
// python/raylab/__init__.py imports it and is what users import.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "py_render.h"
#include "py_scene.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/core/isa.h"

namespace py = pybind11;

PYBIND11_MODULE(_raylab, m) {
  m.doc() = "raylab: ray tracing structures, ray queries and rendering (see docs/python.md)";

  // A broken scene file: ValueError with the position, so `except ValueError` catches it too.
  static py::exception<raylab::InputError> scene_error(m, "SceneError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const raylab::InputError& e) {
      // Calling the type makes an instance, which carries the position as attributes.
      py::object error = py::reinterpret_borrow<py::object>(scene_error.ptr())(e.what());
      error.attr("file") = e.file();
      error.attr("line") = e.line();
      error.attr("column") = e.column();
      PyErr_SetObject(scene_error.ptr(), error.ptr());
    } catch (const raylab::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  m.def(
      "accelerators",
      [] {
        std::vector<std::string> names;
        for (auto n : raylab::accelerator_names()) names.emplace_back(n);
        return names;
      },
      "Names of the acceleration structures this build has, for Scene.build(accel=...).");

  m.def(
      "isa", [] { return std::string(raylab::isa_name(raylab::active_isa())); },
      "The instruction set of the kernels that structures built from now on run: 'baseline', 'avx2' or "
      "'avx512' (the widest this CPU has, unless RAYLAB_ISA or set_isa chose another).");
  m.def(
      "set_isa",
      [](const std::string& isa) {
        try {
          raylab::set_isa(raylab::usable_isa_named(isa, "isa: '" + isa + "'"));
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        }
      },
      py::arg("isa"), "Makes `isa` the instruction set of structures built from now on (for comparisons).");
  m.def(
      "usable_isas",
      [] {
        std::vector<std::string> names;
        for (raylab::Isa isa : raylab::usable_isas()) names.emplace_back(raylab::isa_name(isa));
        return names;
      },
      "The instruction sets this build has and this CPU can run, narrowest first.");

  m.attr("__version__") = RAYLAB_PYTHON_VERSION;

  raylab::python::bind_scene(m);
  raylab::python::bind_render(m);
  raylab::python::bind_lab(m);
}
