#pragma once
/// \file
/// The size of the image when a caller gives its width, its height, both or neither, and the
/// camera that keeps the scene's framing in it: one given, the other follows the scene's shape;
/// both given in another shape, the view widens along the longer side (as pbrt and Mitsuba do),
/// so that what the scene frames is never cropped.

#include <optional>

#include "raylab/scene/scene.h"

namespace raylab {

/// An image size in pixels.
struct ImageSize {
  int width = 0;   ///< pixels per row
  int height = 0;  ///< rows
};

/// The image size for a scene framed at `scene_width` x `scene_height` (its own settings): both
/// or neither of `width`, `height` given, as given (the scene's for a missing one); one given,
/// the other follows the scene's ratio, rounded to the nearest pixel and at least 1.
ImageSize image_size_for(int scene_width, int scene_height, std::optional<int> width, std::optional<int> height);

/// Sets `scene.settings` width and height by image_size_for() from the scene's own, and, when
/// they change, records the scene's shape as the framed aspect of its camera and of every key of
/// its camera path (CameraSpec::framed_aspect), so that a narrower image widens the vertical view
/// and a wider one the horizontal view: the scene's framing is always contained. The one rule of
/// `render`, `compare`, `quality` and the Python `render`.
void set_image_size(Scene& scene, std::optional<int> width, std::optional<int> height);

}  // namespace raylab
