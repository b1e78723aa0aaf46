#include "raylab/render/settings_override.h"

namespace raylab {

void apply_settings_override(RenderSettings& s, const SettingsOverride& over) {
  if (over.width) s.width = *over.width;
  if (over.height) s.height = *over.height;
  if (over.spp) s.spp = *over.spp;
  if (over.max_depth) s.max_depth = *over.max_depth;
  if (over.seed) s.seed = *over.seed;
  if (over.sampler) s.sampler = *over.sampler;
  if (over.filter) s.filter = *over.filter;
  if (over.filter_radius) s.filter_radius = *over.filter_radius;
  if (over.aa_threshold) s.aa_threshold = *over.aa_threshold;
  if (over.aa_depth) s.aa_depth = *over.aa_depth;
}

}  // namespace raylab
