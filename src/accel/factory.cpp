#include "raylab/accel/factory.h"
#include "raylab/core/isa.h"

#include <array>

#include "raylab/accel/brute_force.h"
#include "raylab/accel/embree_accel.h"
#include "raylab/accel/wide_bvh.h"
#include "raylab/core/error.h"

namespace raylab {
namespace {

// "bvh" is the wide BVH at the width the active instruction set tests natively (16 with
// AVX-512, else 8: native_box_width);
// the explicit widths are there to compare them side by side.
constexpr std::array<std::string_view, 11> kNames = {"bvh",   "bvh2",   "bvh4",      "bvh8",  "bvh16", "grid",
                                                     "grid2", "octree", "irregular", "brute", "embree"};

}  // namespace

std::span<const std::string_view> accelerator_names() {
  return std::span<const std::string_view>(kNames).first(embree_available() ? kNames.size() : kNames.size() - 1);
}

std::string accelerator_name_list() {
  std::string valid;
  for (auto n : accelerator_names()) valid += (valid.empty() ? "" : ", ") + std::string(n);
  return valid;
}

std::unique_ptr<Accelerator> make_accelerator(std::string_view name, const Geometry& geometry,
                                              const AccelConfig& config) {
  const std::vector<std::uint32_t> ids = geometry.primitive_ids();
  return make_accelerator(name, geometry, ids, config);
}

std::unique_ptr<Accelerator> make_accelerator(std::string_view name, const Geometry& geometry,
                                              std::span<const std::uint32_t> ids, const AccelConfig& config) {
  if (name == "bvh") {
    // The node width the active set tests with one instruction per plane.
    if (native_box_width(active_isa()) == 16) return std::make_unique<WideBvh<16>>(geometry, ids, config.bvh);
    return std::make_unique<WideBvh<8>>(geometry, ids, config.bvh);
  }
  if (name == "bvh4") return std::make_unique<WideBvh<4>>(geometry, ids, config.bvh);
  if (name == "bvh8") return std::make_unique<WideBvh<8>>(geometry, ids, config.bvh);
  if (name == "bvh16") return std::make_unique<WideBvh<16>>(geometry, ids, config.bvh);
  if (name == "bvh2") return std::make_unique<Bvh>(geometry, ids, config.bvh);
  if (name == "grid") return std::make_unique<UniformGrid>(geometry, ids, config.grid);
  if (name == "grid2") return std::make_unique<TwoLevelGrid>(geometry, ids, config.grid2);
  if (name == "octree") return std::make_unique<Octree>(geometry, ids, config.octree);
  if (name == "irregular") return std::make_unique<IrregularGrid>(geometry, ids, config.irregular);
  if (name == "brute") return std::make_unique<BruteForce>(geometry, ids);
  if (name == "embree" && embree_available()) return make_embree_accelerator(geometry, ids);
  throw UsageError("unknown accelerator '" + std::string(name) + "' (valid: " + accelerator_name_list() + ")");
}

}  // namespace raylab
