#include "raylab/core/cpu_features.h"

#include "cpu_feature_table.h"

namespace raylab {

namespace {

// The names of the features the library requires, those the CPU lacks only when `only_missing`.
std::vector<std::string> features(bool only_missing) {
  std::vector<std::string> names;
  for (int i = 0; i < cpu::kFeatureCount; ++i) {
    const auto f = static_cast<cpu::Feature>(i);
    if (((cpu::kBuildFeatures >> f) & 1u) == 0) continue;
    if (only_missing && cpu::cpu_supports(f)) continue;
    names.emplace_back(cpu::feature_name(f));
  }
  return names;
}

}  // namespace

std::vector<std::string> required_cpu_features() { return features(false); }

std::vector<std::string> missing_cpu_features() { return features(true); }

const char* build_cpu_arch() { return cpu::kBuildArch; }

}  // namespace raylab
