#include "raylab/scene/builtin_scenes.h"

#include <array>
#include <string>

#include "raylab/core/error.h"

namespace raylab {
namespace {

constexpr std::array<std::string_view, 2> kNames = {"demo", "cornell"};

}  // namespace

std::span<const std::string_view> builtin_scene_names() { return kNames; }

bool is_builtin_scene(std::string_view name) {
  for (auto n : kNames) {
    if (n == name) return true;
  }
  return false;
}

Scene make_builtin_scene(std::string_view name) {
  if (name == "demo") return make_demo_scene();
  if (name == "cornell") return make_cornell_scene();
  std::string valid;
  for (auto n : kNames) valid += (valid.empty() ? "" : ", ") + std::string(n);
  throw UsageError("unknown built-in scene '" + std::string(name) + "' (valid: " + valid + ")");
}

}  // namespace raylab
