#pragma once
// Internal to the render module: where the image shows objects so small that samples spaced a
// pixel apart can miss them entirely (a sphere of half a pixel, a sub-pixel light). Adaptive
// sampling refines these footprints from the start instead of hoping a sample lands on them.

#include <vector>

#include "raylab/render/camera.h"
#include "raylab/scene/scene.h"
#include "render_workers.h"

namespace raylab::detail {

/// The pixels (clipped to the image, grown by one pixel on every side) covered by the projected
/// bounds of every object, and every instance, whose projection is at most `max_pixels` wide
/// and tall. Objects partly behind the eye are never small. Only what the eye sees directly:
/// a small object seen in a mirror is left to the other triggers.
std::vector<PixelRect> small_object_footprints(const Scene& scene, const Camera& camera, int width, int height,
                                               float max_pixels);

}  // namespace raylab::detail
