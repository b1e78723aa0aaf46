#include "raylab/scene/material.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace raylab {
namespace {

// `i` wrapped into [0, n) (repeat addressing); `i` may be one step outside on either side.
int wrap(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

// The zone plate of `t` over the material colour `color` at (u, v). In double: the phase reaches
// hundreds of radians at the rim, where float would lose the fraction that matters.
Color zone_plate_color(const Texture& t, Color color, float u, float v) {
  const double du = double(u) - double(t.zone_center.x);
  const double dv = double(v) - double(t.zone_center.y);
  const double r2 = du * du + dv * dv;
  const double radius = t.zone_radius;
  if (!(r2 <= radius * radius)) return lerp(t.color2, color, 0.5f);
  const double s = 0.5 + 0.5 * std::cos(std::numbers::pi * double(t.zone_k) * r2);
  return lerp(t.color2, color, static_cast<float>(s));
}

}  // namespace

TextureImage::TextureImage(int width, int height, std::vector<Color> texels)
    : m_width(width), m_height(height), m_texels(std::move(texels)) {
  if (width <= 0 || height <= 0 ||
      m_texels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("TextureImage: " + std::to_string(m_texels.size()) + " texels for " +
                                std::to_string(width) + " x " + std::to_string(height));
  }
}

Color TextureImage::sample(float u, float v) const {
  if (!std::isfinite(u) || !std::isfinite(v)) return texel(0, 0);
  // Reduce to [0, 1] first (in double, so that large coordinates keep their fraction) so the
  // texel positions below stay small integers whatever u and v were.
  const double fu = double(u) - std::floor(double(u));
  const double fv = double(v) - std::floor(double(v));
  // Position in texel units relative to the centre of the top-left texel; v counts upwards
  // while rows count downwards, hence 1 - v.
  const double x = fu * m_width - 0.5;
  const double y = (1.0 - fv) * m_height - 0.5;
  const double x_floor = std::floor(x);
  const double y_floor = std::floor(y);
  const float tx = static_cast<float>(x - x_floor);
  const float ty = static_cast<float>(y - y_floor);
  const int x0 = wrap(static_cast<int>(x_floor), m_width);
  const int y0 = wrap(static_cast<int>(y_floor), m_height);
  const int x1 = wrap(x0 + 1, m_width);
  const int y1 = wrap(y0 + 1, m_height);
  const Color top = texel(x0, y0) * (1.f - tx) + texel(x1, y0) * tx;
  const Color bottom = texel(x0, y1) * (1.f - tx) + texel(x1, y1) * tx;
  return top * (1.f - ty) + bottom * ty;
}

Color diffuse_color(const Material& m, float u, float v) {
  if (m.texture.kind == Texture::Kind::kChecker) {
    const float s = m.texture.scale > 0.f ? m.texture.scale : 1.f;
    const auto iu = static_cast<long long>(std::floor(u / s));
    const auto iv = static_cast<long long>(std::floor(v / s));
    return ((iu + iv) & 1) == 0 ? m.color : m.texture.color2;
  }
  if (m.texture.kind == Texture::Kind::kImage && m.texture.image) return m.color * m.texture.image->sample(u, v);
  if (m.texture.kind == Texture::Kind::kZonePlate) return zone_plate_color(m.texture, m.color, u, v);
  return m.color;
}

MaterialPoint material_at(const Material& m, float u, float v) {
  MaterialPoint p;
  p.base = diffuse_color(m, u, v);
  p.roughness = m.roughness;
  p.metallic = m.metallic;
  p.transmission = m.transmission;
  if (m.maps.metallic_roughness) {
    const Color mr = m.maps.metallic_roughness->sample(u, v);
    p.roughness *= mr.y;
    p.metallic *= mr.z;
  }
  if (m.maps.transmission) p.transmission *= m.maps.transmission->sample(u, v).x;
  return p;
}

bool reads_surface_coordinates(const Material& m) { return m.texture.kind != Texture::Kind::kNone || !m.maps.empty(); }

Color emitted_radiance(const Material& m, float u, float v) {
  const Color e = m.emission * m.emission_strength;
  return m.maps.emission ? e * m.maps.emission->sample(u, v) : e;
}

}  // namespace raylab
