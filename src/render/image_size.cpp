#include "raylab/render/image_size.h"

#include <algorithm>
#include <cmath>

namespace raylab {

ImageSize image_size_for(int scene_width, int scene_height, std::optional<int> width, std::optional<int> height) {
  // Double: a 32768-pixel side keeps its ratio to the pixel.
  const double aspect = static_cast<double>(std::max(scene_width, 1)) / static_cast<double>(std::max(scene_height, 1));
  const auto rounded = [](double v) { return std::max(1, static_cast<int>(std::lround(v))); };
  if (width && !height) return {*width, rounded(*width / aspect)};
  if (height && !width) return {rounded(*height * aspect), *height};
  return {width.value_or(scene_width), height.value_or(scene_height)};
}

void set_image_size(Scene& scene, std::optional<int> width, std::optional<int> height) {
  RenderSettings& s = scene.settings;
  const ImageSize size = image_size_for(s.width, s.height, width, height);
  // A side rounded to the pixel may leave the image a fraction of a pixel narrower than the
  // scene: the framed aspect covers that too. The scene's own size keeps the camera bit for bit.
  if (size.width != s.width || size.height != s.height) {
    const float framed = static_cast<float>(s.width) / static_cast<float>(s.height);
    scene.camera.framed_aspect = framed;
    for (CameraKey& key : scene.camera_path.keys) key.camera.framed_aspect = framed;
  }
  s.width = size.width;
  s.height = size.height;
}

}  // namespace raylab
