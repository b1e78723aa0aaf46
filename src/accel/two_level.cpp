#include "raylab/accel/two_level.h"

#include "raylab/core/error.h"

// PLACEHOLDER, being written.

namespace raylab {

WrapMode parse_wrap_mode(std::string_view name) {
  if (name == "none") return WrapMode::kNone;
  if (name == "box") return WrapMode::kBox;
  if (name == "sphere") return WrapMode::kSphere;
  throw UsageError("unknown wrap mode '" + std::string(name) + "' (valid: none, box, sphere)");
}

std::string_view wrap_mode_name(WrapMode mode) {
  switch (mode) {
    case WrapMode::kNone:
      return "none";
    case WrapMode::kBox:
      return "box";
    case WrapMode::kSphere:
      return "sphere";
  }
  return "none";
}

std::unique_ptr<Accelerator> make_scene_accelerator(const Geometry& flat, std::span<const Geometry>,
                                                    std::span<const Instance>, const SceneAccelOptions& options) {
  return make_accelerator(options.top, flat, options.config);
}

}  // namespace raylab
