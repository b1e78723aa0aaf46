#include "raylab/render/integrator.h"

#include <array>

#include "path_integrator.h"
#include "raylab/core/error.h"
#include "raylab/render/whitted.h"

namespace raylab {
namespace {

constexpr std::array<std::string_view, 2> kNames = {"whitted", "path"};

}  // namespace

std::span<const std::string_view> integrator_names() { return kNames; }

void check_integrator_name(std::string_view name) {
  for (std::string_view n : kNames) {
    if (n == name) return;
  }
  std::string list;
  for (std::string_view n : kNames) list += (list.empty() ? "" : ", ") + std::string(n);
  throw UsageError("unknown integrator '" + std::string(name) + "' (valid: " + list + ")");
}

std::unique_ptr<Integrator> make_integrator(std::string_view name, const Scene& scene) {
  check_integrator_name(name);
  if (name == "path") return std::make_unique<detail::PathIntegrator>(scene);
  return std::make_unique<WhittedIntegrator>();
}

}  // namespace raylab
