#include "raylab/io/render_overrides.h"

#include "raylab/render/image_size.h"

namespace raylab {

void apply_render_overrides(Scene& scene, const SettingsOverride& settings, const CameraOverride& camera) {
  apply_camera_override(scene, camera);
  SettingsOverride rest = settings;
  rest.width.reset();
  rest.height.reset();
  apply_settings_override(scene.settings, rest);
  set_image_size(scene, settings.width, settings.height);
}

}  // namespace raylab
