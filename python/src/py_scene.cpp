#include "py_scene.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "accel_config.h"
#include "numpy_views.h"
#include "raylab/core/error.h"
#include "raylab/io/scene_loader.h"

namespace raylab::python {

namespace py = pybind11;

int thread_count(const py::object& threads) {
  if (threads.is_none()) return 0;
  const int n = threads.cast<int>();
  if (n < 1)
    throw py::value_error("threads: expected None (all cores) or a count of at least 1, got " + std::to_string(n));
  return n;
}

QueryOptions query_options(const py::object& threads) {
  QueryOptions options;
  options.threads = thread_count(threads);
  options.should_stop = [] {
    const py::gil_scoped_acquire gil;
    return PyErr_CheckSignals() != 0;
  };
  return options;
}

namespace {

// The rays of a query call: one (..., 6) array, or origins and directions of shape (..., 3).
struct Rays {
  FloatRows origins, directions;
  py::object tmin_owner, tmax_owner;  ///< per-ray limits, when given as arrays
  RayBatch batch;
};

// A ray limit (`name` is tmin or tmax): one number for every ray, or an array of the rays'
// leading shape read as float32 (in place when it is a C-contiguous float32 array).
void ray_limit(const py::object& value, const char* name, const std::vector<py::ssize_t>& shape, float& scalar,
               const float*& per_ray, py::object& owner) {
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) {
    scalar = value.cast<float>();
    if (std::isnan(scalar)) throw py::value_error(std::string(name) + ": must not be NaN");
    return;
  }
  const auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a) throw py::type_error(std::string(name) + ": expected a number or an array of the rays' leading shape");
  if (a.ndim() == 0) {  // a numpy scalar, such as a t taken from an earlier answer
    scalar = *a.data();
    if (std::isnan(scalar)) throw py::value_error(std::string(name) + ": must not be NaN");
    return;
  }
  if (std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()) != shape) {
    throw py::value_error(std::string(name) + ": an array of limits must have the rays' leading shape (one per ray)");
  }
  per_ray = a.data();
  owner = a;
}

Rays rays_of(const py::object& origins, const py::object& directions, const py::object& tmin, const py::object& tmax) {
  Rays r;
  if (directions.is_none()) {
    r.origins = float_rows(origins, "rays", 6);
    r.batch.origins = r.origins.data;
    r.batch.directions = r.origins.data + 3;
    r.batch.origin_stride = r.batch.direction_stride = r.origins.row_stride;
  } else {
    r.origins = float_rows(origins, "origins", 3);
    r.directions = float_rows(directions, "directions", 3);
    if (r.origins.shape != r.directions.shape) {
      throw py::value_error("directions: shape does not match origins (one direction per origin, both (..., 3))");
    }
    r.batch.origins = r.origins.data;
    r.batch.directions = r.directions.data;
    r.batch.origin_stride = r.origins.row_stride;
    r.batch.direction_stride = r.directions.row_stride;
  }
  r.batch.count = r.origins.count;
  ray_limit(tmin, "tmin", r.origins.shape, r.batch.tmin, r.batch.tmins, r.tmin_owner);
  ray_limit(tmax, "tmax", r.origins.shape, r.batch.tmax, r.batch.tmaxs, r.tmax_owner);
  return r;
}

// Runs a query with the GIL released; a Ctrl-C seen by the stop check becomes KeyboardInterrupt.
template <class F>
void without_gil(F&& run) {
  try {
    const py::gil_scoped_release released;
    run();
  } catch (const QueryInterrupted&) {
    throw py::error_already_set();  // PyErr_CheckSignals left the KeyboardInterrupt set
  }
}

// The answers of intersect: all five, or those named in `fields`.
std::vector<std::string> hit_fields(const py::object& fields) {
  const std::vector<std::string> all = {"t", "prim_id", "object_id", "uv", "normal"};
  if (fields.is_none()) return all;
  if (py::isinstance<py::str>(fields)) throw py::type_error("fields: expected a sequence of names, not one string");
  std::vector<std::string> names = fields.cast<std::vector<std::string>>();
  for (const std::string& n : names) {
    if (std::find(all.begin(), all.end(), n) == all.end()) {
      throw py::value_error("fields: unknown answer '" + n + "'; the answers are t, prim_id, object_id, uv, normal");
    }
  }
  return names;
}

py::dict intersect(const PyScene& s, const py::object& origins, const py::object& directions, const py::object& tmin,
                   const py::object& tmax, const py::object& threads, const py::object& fields) {
  const std::vector<std::string> wanted = hit_fields(fields);
  const Rays r = rays_of(origins, directions, tmin, tmax);
  const QueryOptions options = query_options(threads);
  auto wants = [&](const char* name) { return std::find(wanted.begin(), wanted.end(), name) != wanted.end(); };
  py::dict result;
  HitArrays out;
  if (wants("t")) {
    auto a = new_array<float>(r.origins.shape);
    out.t = a.mutable_data();
    result["t"] = a;
  }
  if (wants("prim_id")) {
    auto a = new_array<std::int32_t>(r.origins.shape);
    out.prim_id = a.mutable_data();
    result["prim_id"] = a;
  }
  if (wants("object_id")) {
    auto a = new_array<std::int32_t>(r.origins.shape);
    out.object_id = a.mutable_data();
    result["object_id"] = a;
  }
  if (wants("uv")) {
    auto a = new_array<float>(r.origins.shape, 2);
    out.uv = a.mutable_data();
    result["uv"] = a;
  }
  if (wants("normal")) {
    auto a = new_array<float>(r.origins.shape, 3);
    out.normal = a.mutable_data();
    result["normal"] = a;
  }
  without_gil([&] { s.query.intersect(r.batch, out, options); });
  return result;
}

py::array occluded(const PyScene& s, const py::object& origins, const py::object& directions, const py::object& tmin,
                   const py::object& tmax, const py::object& threads) {
  const Rays r = rays_of(origins, directions, tmin, tmax);
  const QueryOptions options = query_options(threads);
  auto out = new_array<bool>(r.origins.shape);
  auto* flags = reinterpret_cast<std::uint8_t*>(out.mutable_data());  // numpy bools are bytes of 0 or 1
  without_gil([&] { s.query.occluded(r.batch, flags, options); });
  return out;
}

py::array count_intersections(const PyScene& s, const py::object& origins, const py::object& directions,
                              const py::object& tmin, const py::object& tmax, const py::object& threads) {
  const Rays r = rays_of(origins, directions, tmin, tmax);
  const QueryOptions options = query_options(threads);
  auto out = new_array<std::uint32_t>(r.origins.shape);
  without_gil([&] { s.query.count_intersections(r.batch, out.mutable_data(), options); });
  return out;
}

py::array contains(const PyScene& s, const py::object& points, const py::object& threads) {
  const FloatRows p = float_rows(points, "points", 3);
  const QueryOptions options = query_options(threads);
  auto out = new_array<bool>(p.shape);
  auto* flags = reinterpret_cast<std::uint8_t*>(out.mutable_data());
  without_gil([&] { s.query.contains(p.data, p.count, p.row_stride, flags, options); });
  return out;
}

// The triangles of a Mesh, read from the arrays with the GIL released (the arrays stay alive).
RayQuery query_from_arrays(const py::object& vertices, const py::object& triangles) {
  const auto tri = matrix<std::uint32_t>(triangles, "triangles", 3);
  const std::span<const std::uint32_t> indices(tri.data(), static_cast<std::size_t>(tri.size()));
  const py::array given = py::array::ensure(vertices);
  if (given && given.dtype().is(py::dtype::of<double>())) {
    const auto v = matrix<double>(vertices, "vertices", 3);
    const std::span<const double> coords(v.data(), static_cast<std::size_t>(v.size()));
    const py::gil_scoped_release released;
    return RayQuery::from_triangles(coords, indices);
  }
  const auto v = matrix<float>(vertices, "vertices", 3);
  const std::span<const float> coords(v.data(), static_cast<std::size_t>(v.size()));
  const py::gil_scoped_release released;
  return RayQuery::from_triangles(coords, indices);
}

// The library names the index array `indices`; Python users passed it as `triangles`.
RayQuery checked_query_from_arrays(const py::object& vertices, const py::object& triangles) {
  try {
    return query_from_arrays(vertices, triangles);
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    const std::string library_name = "indices:";
    if (message.rfind(library_name, 0) == 0) throw py::value_error("triangles:" + message.substr(library_name.size()));
    throw py::value_error(message);
  }
}

PyScene make_mesh(const py::object& vertices, const py::object& triangles) {
  PyScene s(checked_query_from_arrays(vertices, triangles));
  s.vertices = vertices;
  s.triangles = triangles;
  s.source = "Mesh";
  return s;
}

PyScene load(const py::object& path, bool allow_outside_paths) {
  const std::string source = py::str(py::module_::import("os").attr("fspath")(path));
  LoadOptions options;
  options.allow_outside_paths = allow_outside_paths;
  Scene scene;
  try {
    const py::gil_scoped_release released;
    scene = load_scene(source, options);
  } catch (const InputError& e) {
    // The loader speaks to command-line users; name the keyword a Python user passes instead.
    std::string message = e.what();
    const std::string flag = "--allow-outside-paths";
    if (const auto at = message.find(flag); at != std::string::npos) {
      message.replace(at, flag.size(), "allow_outside_paths=True");
      // e.what() already carries the position; keep file, line and column for SceneError.
      const std::string prefix = e.file() + ":" + std::to_string(e.line()) + ":" + std::to_string(e.column()) + ": ";
      if (message.rfind(prefix, 0) == 0) message = message.substr(prefix.size());
      throw InputError(e.file(), e.line(), e.column(), message);
    }
    throw;
  }
  PyScene s(RayQuery::from_scene(std::move(scene)));
  s.source = source;
  return s;
}

py::dict info(const PyScene& s) {
  const AccelInfo i = s.query.accelerator().info();
  py::dict d;
  d["name"] = i.name;
  d["build_seconds"] = i.build_seconds;
  d["memory_bytes"] = i.memory_bytes;
  d["node_count"] = i.node_count;
  d["leaf_count"] = i.leaf_count;
  d["primitive_count"] = i.primitive_count;
  d["max_depth"] = i.max_depth;
  return d;
}

}  // namespace

void bind_scene(py::module_& m) {
  const py::float_ kInf(std::numeric_limits<double>::infinity());
  const char* rays_doc = R"(
    Rays are ``origins`` and ``directions`` of shape (..., 3), or one array ``rays`` of shape
    (..., 6) (origin then direction per row, as Open3D takes them) with ``directions=None``.
    Directions need not be unit length: ``t`` is measured in units of them. Each ray is
    limited to tmin <= t < tmax. float32 arrays are read in place; other real dtypes are
    converted. Answers keep the leading shape: (H, W, 3) rays give (H, W) answers.
    ``threads``: None for all cores. The GIL is released while rays are traced, and Ctrl-C
    interrupts the call (KeyboardInterrupt). ``tmin`` and ``tmax`` are one number for all
    rays or an array of the rays' leading shape (one limit per ray, e.g. shadow rays).)";

  py::class_<PyScene>(m, "Scene", R"(Primitives and the acceleration structure built over them.

Made by :func:`raylab.load` (any scene file, mesh file, built-in scene or SPD generator) or
:class:`raylab.Mesh` (numpy arrays). Queries before :meth:`build` use ``accel="bvh"``.)")
      .def(
          "build",
          [](PyScene& s, const std::string& accel, const py::object& threads, const py::kwargs& config) -> PyScene& {
            const AccelConfig c = accel_config(accel, config);
            const int n = thread_count(threads);
            {
              const py::gil_scoped_release released;
              s.query.build(accel, c, n);
            }
            s.accel = accel;
            return s;
          },
          py::arg("accel") = "bvh", py::kw_only(), py::arg("threads") = py::none(),
          R"(Builds (or rebuilds) the acceleration structure and returns the scene.

``accel`` is one of :func:`raylab.accelerators` ("bvh", "bvh2", "grid", "grid2", "octree",
"irregular", "brute", "embree", ...). Keyword parameters configure it: bin_count, max_leaf_size,
traversal_cost, intersection_cost, spatial_splits, spatial_split_alpha, spatial_split_budget for
the BVHs; density and mailbox for "grid"; top_density, leaf_density and mailbox for "grid2";
max_items, max_depth and mailbox for "octree"; top_density, sub_density, max_shift, max_depth,
step_cost, prim_cost, merge_rounds, expand_rounds and mailbox for "irregular". An unknown
name raises ValueError, an unknown parameter TypeError.)",
          py::return_value_policy::reference_internal)
      .def("intersect", &intersect, py::arg("origins"), py::arg("directions") = py::none(), py::kw_only(),
           py::arg("tmin") = 0.f, py::arg("tmax") = kInf, py::arg("threads") = py::none(),
           py::arg("fields") = py::none(),
           (std::string(R"(Closest hit of every ray.

Returns a dict of arrays: ``t`` (float32, inf on a miss), ``prim_id`` and ``object_id``
(int32, -1 on a miss), ``uv`` (..., 2) (barycentric weights of the triangle's vertices 1 and 2)
and ``normal`` (..., 3) (the unit geometric normal as the primitive is wound, 0 on a miss).
``fields``: the names of the answers wanted (default all); fewer answers cost less.
)") + rays_doc)
               .c_str())
      .def("occluded", &occluded, py::arg("origins"), py::arg("directions") = py::none(), py::kw_only(),
           py::arg("tmin") = 0.f, py::arg("tmax") = kInf, py::arg("threads") = py::none(),
           (std::string("Whether anything lies on each ray (bool array): the any-hit query of shadow rays.\n") +
            rays_doc)
               .c_str())
      .def("count_intersections", &count_intersections, py::arg("origins"), py::arg("directions") = py::none(),
           py::kw_only(), py::arg("tmin") = 0.f, py::arg("tmax") = kInf, py::arg("threads") = py::none(),
           (std::string(R"(How many primitives each ray crosses (uint32 array).

A ray through an edge or vertex shared by triangles counts one crossing there (a consistent
tie rule), so a ray from outside that leaves a closed mesh crosses it an even number of times.
Exact with "bvh" and "brute"; the other structures count two crossings at exactly the same
distance as one.
)") + rays_doc)
               .c_str())
      .def("contains", &contains, py::arg("points"), py::kw_only(), py::arg("threads") = py::none(),
           R"(Whether each point of ``points`` (..., 3) lies inside the closed surfaces of the scene
(bool array of the leading shape): a ray from the point crosses them an odd number of times.
The triangles must form closed surfaces; a point on the surface may go either way.)")
      .def_property_readonly(
          "accel", [](const PyScene& s) { return s.accel; }, "Name of the structure queries use.")
      .def_property_readonly("info", &info,
                             "The structure's build time, memory, node, leaf and primitive counts (builds it if "
                             "needed).")
      .def_property_readonly(
          "primitive_count", [](const PyScene& s) { return s.query.geometry().size(); },
          "Number of primitives (triangle ids come first, in input order).")
      .def_property_readonly(
          "bounds",
          [](const PyScene& s) {
            const Box3 b = s.query.geometry().bounds();
            py::array_t<float> out({2, 3});
            auto w = out.mutable_unchecked<2>();
            for (int a = 0; a < 3; ++a) {
              w(0, a) = b.lo[a];
              w(1, a) = b.hi[a];
            }
            return out;
          },
          "Bounding box as a (2, 3) array: minimum row, then maximum row.")
      .def_property_readonly(
          "vertices", [](const PyScene& s) { return s.vertices; },
          "The vertex array a Mesh was made from, as given (None for a loaded scene).")
      .def_property_readonly(
          "triangles", [](const PyScene& s) { return s.triangles; },
          "The triangle array a Mesh was made from, as given (None for a loaded scene).")
      .def("__repr__", [](const PyScene& s) {
        return "<raylab.Scene " + s.source + ": " + std::to_string(s.query.geometry().size()) + " primitives, accel " +
               s.accel + ">";
      });

  m.def("Mesh", &make_mesh, py::arg("vertices"), py::arg("triangles"),
        R"(A triangle mesh from arrays: ``vertices`` (N, 3) float32 or float64 and ``triangles`` (M, 3) of
vertex indices. Triangle i gets ``prim_id`` i; every triangle is object 0. A C-contiguous float32
``vertices`` and uint32 ``triangles`` are read without a conversion copy (the scene keeps its own
compact copy of the triangles for tracing). Raises TypeError for a non-numeric array and
ValueError, naming the argument, for a wrong shape, an index out of range or a vertex that is
not finite.)");
  m.def("load", &load, py::arg("path"), py::kw_only(), py::arg("allow_outside_paths") = false,
        R"(Loads a scene: a file by its extension (.json, .nff, .obj, .gltf, .glb, .ply, .off, .stl), a
built-in scene ("demo", "cornell", ...) or an SPD generator ("spd:balls?size=3"). Instances are
baked into copies. A scene file may refer to files outside its own folder only with
``allow_outside_paths=True`` (as the command line's --allow-outside-paths). Raises raylab.SceneError (with .file, .line, .column) for a broken file and
ValueError for an unknown name or extension.)");
}

}  // namespace raylab::python
