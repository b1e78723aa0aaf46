#include "raylab/io/render_overrides.h"

#include <cmath>
#include <memory>

#include "raylab/core/error.h"
#include "raylab/io/environment_io.h"
#include "raylab/render/image_size.h"
#include "raylab/scene/environment.h"

namespace raylab {

void apply_render_overrides(Scene& scene, const SettingsOverride& settings, const CameraOverride& camera) {
  apply_camera_override(scene, camera);
  SettingsOverride rest = settings;
  rest.width.reset();
  rest.height.reset();
  apply_settings_override(scene.settings, rest);
  set_image_size(scene, settings.width, settings.height);
  if (settings.environment) {
    scene.environment = std::make_shared<Environment>(
        load_environment(*settings.environment, settings.environment_rotate.value_or(0.f)));
  } else if (settings.environment_rotate) {
    if (!scene.environment) {
      throw UsageError("--env-rotate turns the scene's environment, and this scene has none (give one with --env)");
    }
    if (!std::isfinite(*settings.environment_rotate))
      throw UsageError("--env-rotate must be a finite angle in degrees");
    auto turned = std::make_shared<Environment>(*scene.environment);
    turned->rotate_degrees = *settings.environment_rotate;
    scene.environment = std::move(turned);
  }
}

}  // namespace raylab
