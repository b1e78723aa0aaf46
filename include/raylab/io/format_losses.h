#pragma once
/// \file
/// What a scene loses when `raylab convert` writes it in a format that cannot say everything.

#include <string>
#include <string_view>
#include <vector>

#include "raylab/scene/scene.h"

namespace raylab {

/// What writing `scene` as `extension` (".nff", ".obj", ".ply" or ".json", as convert writes
/// them) leaves out or approximates, one item each, e.g. {"camera", "3 lights", "5 materials",
/// "2 spheres (tessellated)"}; empty when nothing is lost. `scene` is as loaded, instances baked
/// and nothing tessellated yet. `fitted_view` says the camera and lights were made up by the
/// loader (a bare mesh): a format that drops them loses nothing the source had.
std::vector<std::string> format_losses(const Scene& scene, std::string_view extension, bool fitted_view);

/// The one-line warning for `losses` of `output`: "OUTPUT cannot carry: a, b, c" (without the
/// "warning: " prefix); empty when `losses` is empty.
std::string losses_message(const std::string& output, const std::vector<std::string>& losses);

}  // namespace raylab
