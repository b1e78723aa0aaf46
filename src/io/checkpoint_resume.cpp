#include "raylab/io/checkpoint_resume.h"

#include <exception>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/io/setting_names.h"

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
  from.fill(s.filter, name::kFilter);
  from.fill(s.filter_radius, name::kFilterRadius, [](const std::string& v) { return std::stof(v); });
  from.fill(r.accel, name::kAccel);
}

void check_resumable(const RenderCheckpoint& saved, const RenderCheckpoint& now, const std::string& path) {
  const std::vector<std::string> differences = checkpoint_differences(saved, now);
  if (differences.empty()) return;
  std::string message = "cannot resume: this render differs from the checkpoint's";
  for (const std::string& d : differences) message += "\n  " + d;
  throw InputError(path, message);
}

}  // namespace raylab
