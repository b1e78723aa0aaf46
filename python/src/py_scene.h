#pragma once
// The Python `Scene` (and `Mesh`): primitives, the structure built over them, and the batched
// ray queries with numpy arrays in and out (internal to the module).

#include <pybind11/pybind11.h>

#include <string>
#include <utility>

#include "raylab/query/ray_query.h"

namespace raylab::python {

/// What a Python Scene holds. `vertices` and `triangles` are the arrays a Mesh was made from,
/// kept as given (None for a loaded scene).
struct PyScene {
  /// A scene answering through `q`.
  explicit PyScene(RayQuery q) : query(std::move(q)) {}

  RayQuery query;
  std::string accel = "bvh";  ///< the structure queries use (built on first use)
  pybind11::object vertices = pybind11::none();
  pybind11::object triangles = pybind11::none();
  std::string source;  ///< the path or name it was loaded from, for repr and reports
};

/// Options for a batch from the calling Python code: `threads` (None = all cores) and a stop
/// check that answers Ctrl-C (it takes the GIL for a moment, between waves of rays).
QueryOptions query_options(const pybind11::object& threads);

/// The thread count of a `threads=` argument: None is 0 (all cores); below 1 raises ValueError.
int thread_count(const pybind11::object& threads);

/// Adds the classes Scene and Mesh and the function load to `m`.
void bind_scene(pybind11::module_& m);

}  // namespace raylab::python
