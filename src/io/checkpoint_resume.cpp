#include "raylab/io/checkpoint_resume.h"

#include <fmt/format.h>

#include <exception>
#include <stdexcept>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/io/setting_names.h"
#include "raylab/scene/up_axis.h"

namespace raylab {
namespace {

// Reads the settings of one checkpoint, converting the numbers they hold.
class SavedSettings {
 public:
  SavedSettings(const RenderCheckpoint& saved, const std::string& path) : m_saved(saved), m_path(path) {}

  // Sets `field`, when empty, to the recorded text converted by `convert` (std::stoi and kin).
  template <class T, class Convert>
  void fill(std::optional<T>& field, const char* name, Convert convert) const {
    const std::string* value = saved_setting(m_saved, name);
    if (field || value == nullptr) return;
    try {
      field = convert(*value);
    } catch (const std::exception&) {
      throw InputError(m_path, std::string("the checkpoint's setting '") + name + "' is not a valid value");
    }
  }

  // Sets `field`, when empty, to the recorded text as it is.
  void fill(std::optional<std::string>& field, const char* name) const {
    fill(field, name, [](const std::string& v) { return v; });
  }

 private:
  const RenderCheckpoint& m_saved;
  const std::string& m_path;
};

int to_int(const std::string& v) { return std::stoi(v); }

// A recorded "X,Y,Z"; throws for the caller to report, as std::stoi does.
Vec3 to_vec3(const std::string& v) {
  const std::optional<Vec3> p = parse_vec3(v);
  if (!p) throw std::invalid_argument(v);
  return *p;
}

Vec3 to_axis(const std::string& v) {
  const std::optional<Vec3> axis = parse_up_axis(v);
  if (!axis) throw std::invalid_argument(v);
  return *axis;
}

float to_float(const std::string& v) { return std::stof(v); }

}  // namespace

void fill_from_checkpoint(ResumableRequest& r, const RenderCheckpoint& saved, const std::string& path) {
  namespace name = setting_name;
  const SavedSettings from(saved, path);
  SettingsOverride& s = r.settings;
  if (!r.scene) r.scene = saved.scene;
  from.fill(s.width, name::kWidth, to_int);
  from.fill(s.height, name::kHeight, to_int);
  from.fill(s.spp, name::kSpp, to_int);
  from.fill(s.max_depth, name::kMaxDepth, to_int);
  from.fill(r.passes, name::kPasses, to_int);
  from.fill(s.seed, name::kSeed, [](const std::string& v) { return std::stoull(v); });
  from.fill(s.sampler, name::kSampler);
  from.fill(s.integrator, name::kIntegrator);
  from.fill(s.environment, name::kEnvironment);
  from.fill(s.environment_rotate, name::kEnvironmentRotate, to_float);
  from.fill(s.filter, name::kFilter);
  from.fill(s.filter_radius, name::kFilterRadius, [](const std::string& v) { return std::stof(v); });
  from.fill(r.accel, name::kAccel);
  CameraOverride& c = r.camera;
  from.fill(c.up_axis, name::kUpAxis, to_axis);
  from.fill(c.from, name::kCameraFrom, to_vec3);
  from.fill(c.at, name::kCameraAt, to_vec3);
  from.fill(c.up, name::kCameraUp, to_vec3);
  from.fill(c.fov_degrees, name::kFov, to_float);
  from.fill(c.orbit_degrees, name::kOrbit, to_float);
}

std::vector<std::pair<std::string, std::string>> environment_settings(const SettingsOverride& s) {
  namespace name = setting_name;
  std::vector<std::pair<std::string, std::string>> out;
  if (s.environment) out.emplace_back(name::kEnvironment, *s.environment);
  if (s.environment_rotate) out.emplace_back(name::kEnvironmentRotate, fmt::format("{}", *s.environment_rotate));
  return out;
}

std::vector<std::pair<std::string, std::string>> camera_settings(const CameraOverride& c) {
  namespace name = setting_name;
  std::vector<std::pair<std::string, std::string>> out;
  // Numbers in the shortest text that reads back to the same float (fmt's default).
  if (c.up_axis) out.emplace_back(name::kUpAxis, up_axis_name(*c.up_axis));
  if (c.from) out.emplace_back(name::kCameraFrom, format_vec3(*c.from));
  if (c.at) out.emplace_back(name::kCameraAt, format_vec3(*c.at));
  if (c.up) out.emplace_back(name::kCameraUp, format_vec3(*c.up));
  if (c.fov_degrees) out.emplace_back(name::kFov, fmt::format("{}", *c.fov_degrees));
  if (c.orbit_degrees) out.emplace_back(name::kOrbit, fmt::format("{}", *c.orbit_degrees));
  return out;
}

void check_resumable(const RenderCheckpoint& saved, const RenderCheckpoint& now, const std::string& path) {
  const std::vector<std::string> differences = checkpoint_differences(saved, now);
  if (differences.empty()) return;
  std::string message = "cannot resume: this render differs from the checkpoint's";
  for (const std::string& d : differences) message += "\n  " + d;
  throw InputError(path, message);
}

}  // namespace raylab
