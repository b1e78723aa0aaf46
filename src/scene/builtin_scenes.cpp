#include "raylab/scene/builtin_scenes.h"

#include <array>
#include <string>

#include "raylab/core/error.h"
#include "raylab/scene/aa_scenes.h"

namespace raylab {
namespace {

// One line each for --list-scenes (at most 63 characters, to fit 80 columns beside the names):
// what the scene shows; AA charts are the antialiasing scenes of `raylab quality`.
constexpr std::array<BuiltinScene, 9> kScenes = {{
    {"demo", "Whitted revisited: mirror, glass and Phong spheres, a torus"},
    {"cornell", "the Cornell box: published sizes, colours and area light"},
    {"showcase", "every material and metal under a sky with a sun (path)"},
    {"aa-checker", "AA chart: a checkerboard to the horizon (moire)"},
    {"aa-lines", "AA chart: thin lines 0.1 to 1.5 px wide and a Siemens star"},
    {"aa-zoneplate", "AA chart: a zone plate, rings up to 0.75 cycles per pixel"},
    {"aa-highlights", "AA chart: tiny shiny spheres and sub-pixel emissive dots"},
    {"aa-edges", "AA chart: long straight edges at high and low contrast"},
    {"aa-whitted", "AA chart: Whitted's mirror and glass spheres with shadows"},
}};

// The names alone, in the same order, for builtin_scene_names().
constexpr std::array<std::string_view, kScenes.size()> kNames = [] {
  std::array<std::string_view, kScenes.size()> names{};
  for (std::size_t i = 0; i < kScenes.size(); ++i) names[i] = kScenes[i].name;
  return names;
}();

}  // namespace

std::span<const std::string_view> builtin_scene_names() { return kNames; }

std::span<const BuiltinScene> builtin_scenes() { return kScenes; }

bool is_builtin_scene(std::string_view name) {
  for (auto n : kNames) {
    if (n == name) return true;
  }
  return false;
}

Scene make_builtin_scene(std::string_view name) {
  if (name == "demo") return make_demo_scene();
  if (name == "cornell") return make_cornell_scene();
  if (name == "showcase") return make_showcase_scene();
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
