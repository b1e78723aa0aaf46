#include "py_render.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>

#include "numpy_views.h"
#include "py_scene.h"
#include "raylab/accel/two_level.h"
#include "raylab/core/error.h"
#include "raylab/io/image_io.h"
#include "raylab/io/render_overrides.h"
#include "raylab/io/scene_loader.h"
#include "raylab/query/camera_rays.h"
#include "raylab/render/film.h"
#include "raylab/render/image_size.h"
#include "raylab/render/integrator.h"
#include "raylab/render/renderer.h"

namespace raylab::python {

namespace py = pybind11;

Film film_of(const py::object& image, const char* name) {
  const FloatRows rows = float_rows(image, name, 3);
  if (rows.shape.size() != 2) throw py::value_error(std::string(name) + ": expected shape (H, W, 3)");
  const int height = static_cast<int>(rows.shape[0]), width = static_cast<int>(rows.shape[1]);
  Film film(width, height);
  for (std::size_t i = 0; i < rows.count; ++i) {
    const float* p = rows.data + static_cast<std::ptrdiff_t>(i) * rows.row_stride;
    film.at(static_cast<int>(i) % width, static_cast<int>(i) / width) = {p[0], p[1], p[2]};
  }
  return film;
}

Scene scene_of(const py::object& scene_or_path) {
  if (py::isinstance<PyScene>(scene_or_path)) {
    Scene scene = scene_or_path.cast<const PyScene&>().query.scene();
    if (scene.lights.empty() && !scene.camera_from_file) fit_camera_and_lights(scene);
    return scene;
  }
  const std::string path = py::str(py::module_::import("os").attr("fspath")(scene_or_path));
  const py::gil_scoped_release released;
  return load_scene(path);
}

namespace {

py::array_t<float> render_image(const py::object& scene_or_path, std::optional<int> width, std::optional<int> height,
                                std::optional<int> spp, std::optional<std::string> sampler,
                                std::optional<std::string> integrator, std::optional<int> max_depth,
                                const py::object& env, std::optional<float> env_rotate, const std::string& accel,
                                const py::object& threads) {
  Scene scene = scene_of(scene_or_path);
  // One side given: the other follows the scene's shape; both: the view widens, never crops.
  set_image_size(scene, width, height);
  RenderSettings& s = scene.settings;
  if (spp) s.spp = *spp;
  if (sampler) s.sampler = *sampler;
  if (integrator) {
    try {
      check_integrator_name(*integrator);
    } catch (const UsageError& e) {
      throw py::value_error(std::string("integrator: ") + e.what());
    }
    s.integrator = *integrator;
  }
  if (!env.is_none() || env_rotate) {
    SettingsOverride over;
    if (!env.is_none()) over.environment = py::str(py::module_::import("os").attr("fspath")(env));
    over.environment_rotate = env_rotate;
    try {
      apply_render_overrides(scene, over, CameraOverride{});
    } catch (const UsageError& e) {
      throw py::value_error(std::string("env: ") + e.what());
    }
  }
  if (max_depth) {
    if (*max_depth < 1 || *max_depth > 64) throw py::value_error("max_depth: must be 1 to 64");
    s.max_depth = *max_depth;
  }
  if (s.width < 1 || s.height < 1) throw py::value_error("width, height: must be at least 1");
  if (s.spp < 1) throw py::value_error("spp: must be at least 1");
  check_sampling_settings(s);
  RenderOptions options;
  options.threads = thread_count(threads);
  options.should_stop = [] {
    const py::gil_scoped_acquire gil;
    return PyErr_CheckSignals() != 0;
  };
  Film film(s.width, s.height);
  RenderResult result;
  {
    const py::gil_scoped_release released;
    SceneAccelOptions accel_options;
    accel_options.top = accel;
    const auto structure = make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, accel_options);
    result = render(scene, *structure, film, options);
  }
  if (result.interrupted) throw py::error_already_set();  // the KeyboardInterrupt the check saw
  py::array_t<float> image({s.height, s.width, 3});
  float* out = image.mutable_data();
  for (const Color& c : film.pixels()) {
    *out++ = c.x;
    *out++ = c.y;
    *out++ = c.z;
  }
  return image;
}

py::array_t<float> read(const py::object& path) {
  const std::string file = py::str(py::module_::import("os").attr("fspath")(path));
  Film film(1, 1);
  {
    const py::gil_scoped_release released;
    film = read_image(file);
  }
  py::array_t<float> image({film.height(), film.width(), 3});
  float* out = image.mutable_data();
  for (const Color& c : film.pixels()) {
    *out++ = c.x;
    *out++ = c.y;
    *out++ = c.z;
  }
  return image;
}

void write(const py::object& path, const py::object& image) {
  const Film film = film_of(image, "image");
  const std::string file = py::str(py::module_::import("os").attr("fspath")(path));
  const py::gil_scoped_release released;
  write_image(film, file);
}

py::array_t<float> pinhole(int width, int height, const std::array<float, 3>& eye, const std::array<float, 3>& at,
                           const std::array<float, 3>& up, float fov) {
  if (width < 1 || height < 1) throw py::value_error("width, height: must be at least 1");
  if (!(fov > 0.f && fov < 180.f)) throw py::value_error("fov: expected a vertical field of view in (0, 180) degrees");
  CameraSpec cam;
  cam.from = {eye[0], eye[1], eye[2]};
  cam.at = {at[0], at[1], at[2]};
  cam.up = {up[0], up[1], up[2]};
  cam.vfov_degrees = fov;
  py::array_t<float> rays({height, width, 6});
  pinhole_rays(cam, width, height, std::span<float>(rays.mutable_data(), static_cast<std::size_t>(rays.size())));
  return rays;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("render", &render_image, py::arg("scene"), py::kw_only(), py::arg("width") = py::none(),
        py::arg("height") = py::none(), py::arg("spp") = py::none(), py::arg("sampler") = py::none(),
        py::arg("integrator") = py::none(), py::arg("max_depth") = py::none(), py::arg("env") = py::none(),
        py::arg("env_rotate") = py::none(), py::arg("accel") = "bvh", py::arg("threads") = py::none(),
        R"(Renders a scene (a Scene, a path or a built-in name) and returns the linear radiance as a
float32 (H, W, 3) array. Settings not given are the scene's own; ``width``
or ``height`` alone keeps the scene's shape, and both in another shape widen the view (never crop).
``sampler``, ``integrator`` ("whitted" or "path"), ``max_depth``: as the command line's --sampler,
--integrator and --max-depth; ``env`` ("R,G,B" or a lat-long image path) and ``env_rotate``
(degrees) as --env and --env-rotate. Ctrl-C interrupts (KeyboardInterrupt).)");
  m.def("read_image", &read, py::arg("path"),
        R"(Reads a PNG (decoded to linear), EXR or PFM file as a linear float32 (H, W, 3) array.)");
  m.def("write_image", &write, py::arg("path"), py::arg("image"),
        R"(Writes a linear (H, W, 3) image: PNG (8-bit sRGB), EXR (float) or PFM by the extension. The file
appears whole or not at all.)");
  m.def("pinhole_rays", &pinhole, py::arg("width"), py::arg("height"), py::arg("eye"), py::arg("at"),
        py::arg("up") = std::array<float, 3>{0.f, 1.f, 0.f}, py::arg("fov") = 45.f,
        R"(The rays of a pinhole camera through every pixel centre: a float32 (height, width, 6) array of
origin and unit direction, row 0 at the top, exactly as the renderer generates them. ``fov`` is
the vertical field of view in degrees.)");
}

}  // namespace raylab::python
