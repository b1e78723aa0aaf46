#include "camera_options.h"

#include <exception>
#include <optional>
#include <string>

#include "raylab/scene/up_axis.h"

namespace raylab::cli {
namespace {

// --camera-from and its kin: "X,Y,Z" into `target`.
void add_vector_option(CLI::App& cmd, const std::string& name, std::optional<Vec3>& target,
                       const std::string& description) {
  cmd.add_option_function<std::string>(
         name, [&target](const std::string& v) { target = parse_vec3(v); }, description)
      ->type_name("X,Y,Z")
      ->check([](const std::string& v) {
        return parse_vec3(v) ? std::string() : "expects X,Y,Z (three numbers separated by commas), not '" + v + "'";
      });
}

// The number in `v`, as CLI11 will convert it, or a message.
std::string number_problem(const std::string& v) {
  try {
    std::size_t used = 0;
    (void)std::stof(v, &used);
    if (used == v.size()) return "";
  } catch (const std::exception&) {
  }
  return "expects a number of degrees, not '" + v + "'";
}

}  // namespace

void add_camera_options(CLI::App& cmd, CameraOverride& camera) {
  cmd.add_option_function<std::string>(
         "--up", [&camera](const std::string& v) { camera.up_axis = parse_up_axis(v); },
         "Mesh files and scenes without a camera: the axis the object stands on, y z x -y -z -x "
         "(default: detected from a flat cut base, else y)")
      ->type_name("AXIS")
      ->check([](const std::string& v) {
        return parse_up_axis(v) ? std::string() : "expects one of y, z, x, -y, -z, -x, not '" + v + "'";
      });
  add_vector_option(cmd, "--camera-from", camera.from, "Eye position (default: the scene's or the fitted camera's)");
  add_vector_option(cmd, "--camera-at", camera.at, "Point looked at");
  add_vector_option(cmd, "--camera-up", camera.up, "Up direction of the image");
  cmd.add_option("--fov", camera.fov_degrees, "Vertical field of view in degrees, in (0, 180), as the scene's")
      ->type_name("DEG")
      ->check([](const std::string& v) {
        const std::string problem = number_problem(v);
        if (!problem.empty()) return problem;
        const std::string fov = fov_problem(std::stof(v));
        // fov_problem names the flag already; CLI11 puts the flag's name before the message.
        return fov.empty() ? fov : fov.substr(fov.find("expects"));
      });
  cmd.add_option("--orbit", camera.orbit_degrees,
                 "Turn the camera about its up direction through the point looked at, by this many degrees "
                 "(counter-clockwise seen from above)")
      ->type_name("DEG")
      ->check([](const std::string& v) { return number_problem(v); });
  for (const char* name : {"--up", "--camera-from", "--camera-at", "--camera-up", "--fov", "--orbit"}) {
    cmd.get_option(name)->group("Camera");
  }
}

}  // namespace raylab::cli
