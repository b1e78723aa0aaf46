#include "raylab/accel/factory.h"

#include <array>

#include "raylab/accel/brute_force.h"
#include "raylab/accel/bvh4.h"
#include "raylab/core/error.h"

namespace raylab {
namespace {

constexpr std::array<std::string_view, 3> kNames = {"bvh", "bvh2", "brute"};

}  // namespace

std::span<const std::string_view> accelerator_names() { return kNames; }

std::unique_ptr<Accelerator> make_accelerator(std::string_view name, const Geometry& geometry,
                                              const AccelConfig& config) {
  if (name == "bvh") return std::make_unique<Bvh4>(geometry, config.bvh);
  if (name == "bvh2") return std::make_unique<Bvh>(geometry, config.bvh);
  if (name == "brute") return std::make_unique<BruteForce>(geometry);
  std::string valid;
  for (auto n : kNames) valid += (valid.empty() ? "" : ", ") + std::string(n);
  throw UsageError("unknown accelerator '" + std::string(name) + "' (valid: " + valid + ")");
}

}  // namespace raylab
