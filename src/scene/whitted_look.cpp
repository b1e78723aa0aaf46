// The sky and the two balls of Whitted's 1980 image, as the demo and aa-whitted show them.

#include "whitted_look.h"

namespace raylab::whitted_detail {

void set_whitted_sky(RenderSettings& settings) {
  settings.sky_gradient = true;
  settings.background = {0.22f, 0.42f, 0.78f};  // zenith
  settings.horizon = {0.78f, 0.86f, 0.95f};
}

Material whitted_mirror(float ks) {
  return {
      .name = "mirror", .color = {0.9f, 0.9f, 0.95f}, .kd = 0.05f, .ks = ks, .shininess = 400.f, .reflectivity = 0.88f};
}

Material whitted_glass(float ks) {
  return {.name = "glass",
          .color = {1.f, 1.f, 1.f},
          .kd = 0.f,
          .ks = ks,
          .shininess = 600.f,
          .transmittance = 0.95f,
          .ior = 1.5f};
}

}  // namespace raylab::whitted_detail
