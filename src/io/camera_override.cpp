#include "raylab/io/camera_override.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/io/scene_loader.h"
#include "raylab/scene/up_axis.h"

namespace raylab {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

// One finite number that is the whole of `text`.
std::optional<float> parse_number(std::string_view text) {
  text = trimmed(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  float v = 0.f;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// Refits the camera, and the lights when they were fitted too, for a mesh standing on `axis`;
// the scene's settings and given lights stay.
void refit_up_axis(Scene& scene, Vec3 axis) {
  if (!scene.camera_fitted) {
    throw UsageError(
        "--up places the fitted camera of a mesh file or of a scene file without a camera; this scene "
        "has its own camera (turn it with --camera-up or --orbit)");
  }
  const std::vector<Light> lights = scene.lights;
  const bool lights_fitted = scene.lights_fitted;
  const RenderSettings settings = scene.settings;
  fit_camera_and_lights(scene, axis);
  scene.settings = settings;
  if (!lights_fitted) {
    scene.lights = lights;
    scene.lights_fitted = false;
  }
}

// The camera turned by `degrees` about its up direction through `at`. Whole turns are exact.
void orbit(CameraSpec& camera, float degrees) {
  const double turn = std::fmod(static_cast<double>(degrees), 360.0);
  if (turn == 0.0) return;
  const double radians = turn * std::numbers::pi / 180.0;
  const double c = std::cos(radians), s = std::sin(radians);
  const Vec3 k = normalize(camera.up);
  const Vec3 v = camera.from - camera.at;
  // Rodrigues' rotation, in double so that a quarter turn lands on the axis.
  const double kv = static_cast<double>(dot(k, v));
  const Vec3 kxv = cross(k, v);
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = static_cast<float>(v[i] * c + kxv[i] * s + k[i] * kv * (1.0 - c));
  camera.from = camera.at + r;
}

// Usage errors of a camera that cannot render, naming the flags that made it.
void check_camera(const CameraSpec& c, const CameraOverride& over) {
  if (over.up && !(dot(*over.up, *over.up) > 0.f)) throw UsageError("--camera-up must not be 0,0,0");
  switch (camera_fault(c)) {
    case CameraFault::kNone:
      return;
    case CameraFault::kEyeAtTarget: {
      const std::string what = over.from && over.at ? "--camera-from and --camera-at are the same point"
                               : over.from
                                   ? "--camera-from " + format_vec3(c.from) + " is the point the camera looks at"
                               : over.at ? "--camera-at " + format_vec3(c.at) + " is the camera's eye"
                                         : "the camera's eye is the point it looks at";
      throw UsageError(what + ": the camera would look nowhere");
    }
    case CameraFault::kUpAlongView:
      throw UsageError(fmt::format(
          "{} {} is parallel to the viewing direction (from {} to {}): give another "
          "--camera-up",
          over.up ? "--camera-up" : "the camera's up", format_vec3(c.up), format_vec3(c.from), format_vec3(c.at)));
  }
}

}  // namespace

std::optional<Vec3> parse_vec3(std::string_view text) {
  Vec3 v;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',');
    if ((i < 2) != (comma != std::string_view::npos)) return std::nullopt;
    const std::optional<float> n = parse_number(text.substr(0, comma));
    if (!n) return std::nullopt;
    v[i] = *n;
    text = i < 2 ? text.substr(comma + 1) : std::string_view();
  }
  return v;
}

std::string format_vec3(Vec3 v) { return fmt::format("{},{},{}", v.x, v.y, v.z); }

std::string fov_problem(float degrees) {
  if (degrees > 0.f && degrees < 180.f) return "";
  return fmt::format("--fov expects a vertical field of view in (0, 180) degrees, not {}", degrees);
}

void apply_camera_override(Scene& scene, const CameraOverride& over) {
  if (over.fov_degrees) {
    if (const std::string problem = fov_problem(*over.fov_degrees); !problem.empty()) throw UsageError(problem);
  }
  if (over.orbit_degrees && !std::isfinite(*over.orbit_degrees)) throw UsageError("--orbit expects a finite angle");
  if (over.up_axis) refit_up_axis(scene, *over.up_axis);
  CameraSpec& c = scene.camera;
  if (over.from) c.from = *over.from;
  if (over.at) c.at = *over.at;
  if (over.up) c.up = *over.up;
  if (over.fov_degrees) c.vfov_degrees = *over.fov_degrees;
  check_camera(c, over);
  if (over.orbit_degrees) orbit(c, *over.orbit_degrees);
}

std::string describe_camera_override(const CameraOverride& over) {
  std::string out;
  const auto add = [&out](const std::string& part) { out += (out.empty() ? "" : ", ") + part; };
  if (over.up_axis) add("up " + up_axis_name(*over.up_axis));
  if (over.from) add("from " + format_vec3(*over.from));
  if (over.at) add("at " + format_vec3(*over.at));
  if (over.up) add("camera up " + format_vec3(*over.up));
  if (over.fov_degrees) add(fmt::format("fov {}", *over.fov_degrees));
  if (over.orbit_degrees) add(fmt::format("orbit {}", *over.orbit_degrees));
  return out;
}

}  // namespace raylab
