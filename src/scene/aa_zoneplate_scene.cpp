// aa-zoneplate: the zone plate, the chart whose frequency grows linearly across the image.

#include "aa_common.h"
#include "raylab/scene/aa_scenes.h"

namespace raylab {

Scene make_aa_zoneplate_scene() {
  // The background is never seen: the quad covers the frame.
  Scene scene = aa_detail::unlit_chart({0.5f, 0.5f, 0.5f});

  // The quad reaches kMargin px past every side of the frame, so no edge of it shows. Its
  // (u, v) are world units along its edges from its corner, i.e. the world x and y of the hit
  // plus kMargin: pixels, with v counting upwards (the plate is centred, where that flip does
  // not matter).
  constexpr float kMargin = 8.f;
  Material plate;
  plate.name = "zone plate";
  plate.color = {1.f, 1.f, 1.f};
  plate.kd = 1.f;
  const Vec2 centre_uv{0.5f * kAaWidth + kMargin, 0.5f * kAaHeight + kMargin};
  plate.texture = Texture::zone_plate({0.f, 0.f, 0.f}, centre_uv, kAaZonePlateK, kAaZonePlateRadius);
  const auto plate_obj = scene.add_object("zone plate", scene.add_material(plate));
  scene.geometry.add(
      Quad{{-kMargin, -kMargin, 0.f}, {kAaWidth + 2.f * kMargin, 0.f, 0.f}, {0.f, kAaHeight + 2.f * kMargin, 0.f}},
      plate_obj);
  scene.camera = aa_pixel_camera();
  return scene;
}

}  // namespace raylab
