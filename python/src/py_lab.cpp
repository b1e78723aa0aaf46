// The lab's measurements from Python: the figures of `raylab compare --json` and
// `raylab quality --json`, as Python data.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>

#include "numpy_views.h"
#include "py_render.h"
#include "py_scene.h"
#include "raylab/accel/two_level.h"
#include "raylab/lab/accel_compare.h"
#include "raylab/lab/quality_reference.h"
#include "raylab/lab/quality_study.h"

namespace raylab::python {

namespace py = pybind11;

namespace {

// A JSON report as Python data.
py::object parsed(const std::string& json) { return py::module_::import("json").attr("loads")(json); }

py::object compare(const py::object& scene_or_path, std::optional<std::vector<std::string>> accels, int width,
                   int height, int repeat, const py::object& threads) {
  const Scene scene = scene_of(scene_or_path);
  CompareOptions options;
  options.accels = accels ? *accels : default_compare_accels();
  options.rays.width = width;
  options.rays.height = height;
  options.repeat = repeat;
  options.threads = thread_count(threads);
  std::string json;
  {
    const py::gil_scoped_release released;
    json = format_compare_json(compare_accelerators(scene, options), "scene");
  }
  return parsed(json);
}

// The reference image of a study: an (H, W, 3) array, an image file, or None for one rendered
// here with `options.reference_spp` jittered samples.
Film study_reference(const py::object& reference, const Scene& scene, const Accelerator& accel,
                     const QualityOptions& options) {
  if (reference.is_none()) {
    const py::gil_scoped_release released;
    return obtain_reference(scene, accel, options).film;
  }
  if (py::isinstance<py::str>(reference) || py::hasattr(reference, "__fspath__")) {
    return load_reference_file(py::str(py::module_::import("os").attr("fspath")(reference)));
  }
  return film_of(reference, "reference");
}

py::object quality(const py::object& scene_or_path, std::optional<std::vector<std::string>> samplers,
                   const std::vector<int>& budgets, int seeds, const py::object& reference, int reference_spp,
                   std::optional<int> width, std::optional<int> height, const py::object& threads) {
  Scene scene = scene_of(scene_or_path);
  if (width) scene.settings.width = *width;
  if (height) scene.settings.height = *height;
  QualityOptions options;
  if (samplers) options.samplers = *samplers;
  options.budgets = budgets;
  options.seeds = seeds;
  options.reference_spp = reference_spp;
  options.threads = thread_count(threads);
  validate_quality_options(options);
  const auto accel = make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, SceneAccelOptions{});
  const Film ref = study_reference(reference, scene, *accel, options);
  if (ref.width() != scene.settings.width || ref.height() != scene.settings.height) {
    throw py::value_error("reference: the image is " + std::to_string(ref.width()) + "x" +
                          std::to_string(ref.height()) + " but the study renders " +
                          std::to_string(scene.settings.width) + "x" + std::to_string(scene.settings.height));
  }
  std::string json;
  {
    const py::gil_scoped_release released;
    QualityResult result = run_quality_study(scene, *accel, ref, options);
    result.reference = reference.is_none() ? "auto: " + std::to_string(reference_spp) + " spp jittered" : "given";
    json = format_quality_json(result, "scene");
  }
  return parsed(json);
}

}  // namespace

void bind_lab(py::module_& m) {
  m.def("compare", &compare, py::arg("scene"), py::kw_only(), py::arg("accels") = py::none(), py::arg("width") = 256,
        py::arg("height") = 256, py::arg("repeat") = 3, py::arg("threads") = py::none(),
        R"(The lab's side-by-side comparison of acceleration structures on one scene (primary, shadow and
diffuse rays from a width x height camera): the figures of ``raylab compare --json``, as Python data.)");
  m.def("quality", &quality, py::arg("scene"), py::kw_only(), py::arg("samplers") = py::none(),
        py::arg("budgets") = std::vector<int>{1, 4, 16, 64}, py::arg("seeds") = 5, py::arg("reference") = py::none(),
        py::arg("reference_spp") = 1024, py::arg("width") = py::none(), py::arg("height") = py::none(),
        py::arg("threads") = py::none(),
        R"(The lab's sampler study: every sampler at every budget against a reference image (an (H, W, 3)
array, an .exr/.pfm file, or None to render one with ``reference_spp`` jittered samples): the
figures of ``raylab quality --json`` (RMSE, percentiles, rays, time per row), as Python data.)");
}

}  // namespace raylab::python
