#include "raylab/scene/material.h"

#include <cmath>

namespace raylab {

Color diffuse_color(const Material& m, float u, float v) {
  if (m.texture.kind == Texture::Kind::kChecker) {
    const float s = m.texture.scale > 0.f ? m.texture.scale : 1.f;
    const auto iu = static_cast<long long>(std::floor(u / s));
    const auto iv = static_cast<long long>(std::floor(v / s));
    return ((iu + iv) & 1) == 0 ? m.color : m.texture.color2;
  }
  return m.color;
}

}  // namespace raylab
