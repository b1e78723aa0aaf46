#include "raylab/scene/normal_maps.h"

#include <cmath>

namespace raylab {
namespace {

// The least cosine a mapped shading normal keeps with the geometric normal (about 87 degrees).
constexpr float kMinCosine = 0.05f;

Vec3 normal_map_normal(const TextureImage& map, float scale, Vec3 n, const SurfaceTangents& tangents, float u,
                       float v) {
  const Vec3 t_raw = tangents.dpdu - n * dot(n, tangents.dpdu);
  if (!(dot(t_raw, t_raw) > 0.f)) return n;
  const Vec3 t = normalize(t_raw);
  Vec3 b = cross(n, t);
  // Texture space may be mirrored relative to the surface (a flipped UV island): b follows dp/dv.
  if (dot(b, tangents.dpdv) < 0.f) b = -b;
  const Color c = map.sample(u, v);
  const Vec3 local{(2.f * c.x - 1.f) * scale, (2.f * c.y - 1.f) * scale, 2.f * c.z - 1.f};
  const Vec3 mapped = t * local.x + b * local.y + n * local.z;
  return dot(mapped, mapped) > 0.f ? normalize(mapped) : n;
}

Vec3 bump_map_normal(const TextureImage& map, float scale, Vec3 n, const SurfaceTangents& tangents, float u, float v) {
  const float du = 1.f / static_cast<float>(map.width());
  const float dv = 1.f / static_cast<float>(map.height());
  const auto height = [&](float uu, float vv) { return scale * map.sample(uu, vv).x; };
  const float dh_du = (height(u + du, v) - height(u - du, v)) / (2.f * du);
  const float dh_dv = (height(u, v + dv) - height(u, v - dv)) / (2.f * dv);
  const Vec3 bumped = cross(tangents.dpdu + n * dh_du, tangents.dpdv + n * dh_dv);
  if (!(dot(bumped, bumped) > 0.f) || !std::isfinite(dot(bumped, bumped))) return n;
  const Vec3 unit = normalize(bumped);
  // The cross product follows the handedness of (u, v) on the surface: keep n's side.
  return dot(unit, n) < 0.f ? -unit : unit;
}

}  // namespace

Vec3 mapped_normal(const MaterialMaps& maps, Vec3 n, const SurfaceTangents& tangents, float u, float v) {
  if (maps.normal) return normal_map_normal(*maps.normal, maps.normal_scale, n, tangents, u, v);
  if (maps.bump) return bump_map_normal(*maps.bump, maps.bump_scale, n, tangents, u, v);
  return n;
}

bool looks_like_normal_map(const TextureImage& image) {
  double r = 0.0, g = 0.0, b = 0.0, blue_excess = 0.0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const Color c = image.texel(x, y);
      r += c.x, g += c.y, b += c.z;
      blue_excess += c.z - 0.5 * (c.x + c.y);
    }
  }
  const double n = static_cast<double>(image.width()) * image.height();
  r /= n, g /= n, b /= n, blue_excess /= n;
  // A normal map's mean is near (0.5, 0.5, 1): z dominates and x, y scatter around zero.
  return b > 0.6 && std::fabs(r - 0.5) < 0.2 && std::fabs(g - 0.5) < 0.2 && blue_excess > 0.2;
}

void apply_normal_maps(const MaterialMaps& maps, const SurfaceTangents& tangents, SurfaceInteraction& si) {
  // The maps are written for the outward side; si's normals face the ray.
  const float side = si.front_face ? 1.f : -1.f;
  Vec3 mapped = mapped_normal(maps, si.shading_normal * side, tangents, si.u, si.v) * side;
  const float cosine = dot(mapped, si.geometric_normal);
  if (cosine < kMinCosine) mapped = normalize(mapped + si.geometric_normal * (kMinCosine - cosine));
  si.shading_normal = mapped;
}

}  // namespace raylab
