#include "raylab/scene/builtin_scenes.h"

#include <array>
#include <string>

#include "raylab/core/error.h"
#include "raylab/scene/aa_scenes.h"

namespace raylab {
namespace {

constexpr std::array<std::string_view, 8> kNames = {"demo",         "cornell",       "aa-checker", "aa-lines",
                                                    "aa-zoneplate", "aa-highlights", "aa-edges",   "aa-whitted"};

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
  if (name == "aa-checker") return make_aa_checker_scene();
  if (name == "aa-lines") return make_aa_lines_scene();
  if (name == "aa-zoneplate") return make_aa_zoneplate_scene();
  if (name == "aa-highlights") return make_aa_highlights_scene();
  if (name == "aa-edges") return make_aa_edges_scene();
  if (name == "aa-whitted") return make_aa_whitted_scene();
  std::string valid;
  for (auto n : kNames) valid += (valid.empty() ? "" : ", ") + std::string(n);
  throw UsageError("unknown built-in scene '" + std::string(name) + "' (valid: " + valid + ")");
}

}  // namespace raylab
