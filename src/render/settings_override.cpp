#include "raylab/render/settings_override.h"

#include "raylab/sampling/pixel_sampler.h"

namespace raylab {

void apply_settings_override(RenderSettings& s, const SettingsOverride& over) {
  if (over.width) s.width = *over.width;
  if (over.height) s.height = *over.height;
  if (over.spp) s.spp = *over.spp;
  if (over.max_depth) s.max_depth = *over.max_depth;
  if (over.seed) s.seed = *over.seed;
  if (over.sampler) s.sampler = *over.sampler;
  if (over.integrator) s.integrator = *over.integrator;
  if (over.filter) s.filter = *over.filter;
  if (over.filter_radius) s.filter_radius = *over.filter_radius;
  if (over.aa_threshold) s.aa_threshold = *over.aa_threshold;
  if (over.aa_depth) s.aa_depth = *over.aa_depth;
  // Asking for a one-sample sampler (center) without --spp asks for one sample: the scene's count
  // (a bare mesh's default of 4, say) is not the caller's, so it gets no rounding notice.
  if (over.sampler && !over.spp && is_pixel_sampler(*over.sampler) && valid_spp(*over.sampler, 2) == 1) s.spp = 1;
}

}  // namespace raylab
