#include "raylab/render/whitted.h"

#include <cmath>

#include "raylab/geometry/shading.h"

namespace raylab {
namespace {

// Shadow rays stop this fraction short of the light sample, so a light lying on a surface
// (an area light on a ceiling) is not shadowed by that surface.
constexpr float kShadowShorten = 1e-3f;

bool cast_shadow_ray(const TraceContext& ctx, const Ray& ray) {
  const bool blocked =
      ctx.count_traversal ? ctx.accel.occluded_counted(ray, ctx.stats.traversal) : ctx.accel.occluded(ray);
  ctx.stats.count(RayKind::kShadow, blocked);
  return blocked;
}

// Phong response to light arriving from unit direction `wi` with radiance scale `li`.
Color phong(const Material& m, Color base, Vec3 n, Vec3 view, Vec3 wi, Color li) {
  const float cos_theta = dot(n, wi);
  Color c = base * (m.kd * cos_theta);
  if (m.ks > 0.f) {
    const float spec = dot(reflect(-wi, n), view);
    if (spec > 0.f) c += Color(m.ks * std::pow(spec, m.shininess));
  }
  return c * li;
}

// One light sample: position (or direction for directional lights) and what arrives from it.
struct LightSample {
  Vec3 wi;         // unit direction to the light
  float distance;  // to the sample point (infinity for directional lights)
  Color radiance;  // intensity share of this sample
};

// Contribution of `light` at the shading point, averaging `samples` stratified positions for
// area lights: a soft shadow is the fraction of the light's samples that the point sees.
Color shade_light(const TraceContext& ctx, const Light& light, const Material& m, Color base, Vec3 p, Vec3 n, Vec3 ng,
                  Vec3 view, Pcg32& rng) {
  int grid = 1;
  if (light.kind == Light::Kind::kSphere || light.kind == Light::Kind::kQuad) {
    grid = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<float>(std::max(1, light.samples))))));
  }
  const float share = 1.f / static_cast<float>(grid * grid);
  Color sum{0.f};
  for (int sy = 0; sy < grid; ++sy) {
    for (int sx = 0; sx < grid; ++sx) {
      Vec3 target;
      LightSample ls;
      if (light.kind == Light::Kind::kDirectional) {
        ls.wi = normalize(-light.direction);
        ls.distance = INFINITY;
      } else {
        target = light.position;
        if (grid > 1) {
          const float u = (static_cast<float>(sx) + rng.next_float()) / static_cast<float>(grid);
          const float v = (static_cast<float>(sy) + rng.next_float()) / static_cast<float>(grid);
          if (light.kind == Light::Kind::kQuad) {
            target = light.position + light.edge_u * u + light.edge_v * v;
          } else {
            // Uniform point on the sphere (z = 1 - 2u, azimuth 2 pi v).
            const float z = 1.f - 2.f * u;
            const float r = std::sqrt(std::max(0.f, 1.f - z * z));
            const float phi = 6.2831853f * v;
            target = light.position + Vec3{r * std::cos(phi), r * std::sin(phi), z} * light.radius;
          }
        }
        const Vec3 to = target - p;
        ls.distance = length(to);
        if (!(ls.distance > 0.f)) continue;
        ls.wi = to / ls.distance;
      }
      ls.radiance = light.intensity * share;
      if (light.falloff && std::isfinite(ls.distance)) ls.radiance /= ls.distance * ls.distance;
      // Only surfaces that face the light cast a shadow ray (SPD testing procedure).
      if (dot(n, ls.wi) <= 0.f || dot(ng, ls.wi) <= 0.f) continue;
      Ray shadow;
      shadow.origin = offset_origin(p, ng, ls.wi);
      shadow.direction = ls.wi;
      shadow.tmin = 0.f;
      shadow.tmax = std::isfinite(ls.distance) ? ls.distance * (1.f - kShadowShorten) : INFINITY;
      if (cast_shadow_ray(ctx, shadow)) continue;
      sum += phong(m, base, n, view, ls.wi, ls.radiance);
    }
  }
  return sum;
}

}  // namespace

Color WhittedIntegrator::background(const RenderSettings& s, Vec3 dir) {
  if (!s.sky_gradient) return s.background;
  const float up = dir.y / std::max(length(dir), 1e-30f);
  if (up <= 0.f) return s.horizon;
  return lerp(s.horizon, s.background, std::sqrt(up));
}

float WhittedIntegrator::fresnel_dielectric(float cos_i, float eta_i, float eta_t) {
  cos_i = std::clamp(cos_i, 0.f, 1.f);
  const float sin_t = eta_i / eta_t * std::sqrt(std::max(0.f, 1.f - cos_i * cos_i));
  if (sin_t >= 1.f) return 1.f;
  const float cos_t = std::sqrt(std::max(0.f, 1.f - sin_t * sin_t));
  const float r_parallel = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
  const float r_perpendicular = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
  return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

bool WhittedIntegrator::refract(Vec3 d, Vec3 n, float eta, Vec3& out) {
  const float cos_i = -dot(d, n);
  const float sin2_t = eta * eta * std::max(0.f, 1.f - cos_i * cos_i);
  if (sin2_t >= 1.f) return false;
  out = d * eta + n * (eta * cos_i - std::sqrt(1.f - sin2_t));
  return true;
}

Color WhittedIntegrator::trace(const TraceContext& ctx, Ray ray, int depth, RayKind kind, Pcg32& rng,
                               PrimaryFeature* feature) {
  Hit hit;
  const bool found =
      ctx.count_traversal ? ctx.accel.intersect_counted(ray, hit, ctx.stats.traversal) : ctx.accel.intersect(ray, hit);
  ctx.stats.count(kind, found);
  if (!found) return background(ctx.scene.settings, ray.direction);

  const Scene& scene = ctx.scene;
  const SurfaceInteraction si = surface_at(scene, ray, hit);
  const Material& m = scene.materials[scene.objects[si.object_id].material];
  const Vec3 d = normalize(ray.direction);
  const Vec3 n = si.shading_normal;
  const Vec3 ng = si.geometric_normal;
  const Vec3 view = -d;
  const Color base = diffuse_color(m, si.u, si.v);
  if (feature) {
    feature->object = static_cast<std::int32_t>(si.object_id);
    feature->normal = n;
  }

  Color result = m.emission + scene.settings.ambient * base * m.kd;
  for (const Light& light : scene.lights) result += shade_light(ctx, light, m, base, si.position, n, ng, view, rng);

  if (depth >= scene.settings.max_depth) return result;

  float reflect_weight = m.reflectivity;
  float refract_weight = 0.f;
  Vec3 refracted;
  if (m.transmittance > 0.f) {
    const float eta_i = si.front_face ? 1.f : m.ior;
    const float eta_t = si.front_face ? m.ior : 1.f;
    if (refract(d, n, eta_i / eta_t, refracted)) {
      const float f = m.fresnel ? fresnel_dielectric(dot(view, n), eta_i, eta_t) : 0.f;
      reflect_weight += m.transmittance * f;
      refract_weight = m.transmittance * (1.f - f);
    } else {
      reflect_weight += m.transmittance;  // total internal reflection
    }
  }
  if (reflect_weight > 0.f) {
    Ray r;
    r.direction = reflect(d, n);
    r.origin = offset_origin(si.position, ng, r.direction);
    result += trace(ctx, r, depth + 1, RayKind::kReflection, rng) * reflect_weight;
  }
  if (refract_weight > 0.f) {
    Ray r;
    r.direction = normalize(refracted);
    r.origin = offset_origin(si.position, ng, r.direction);
    result += trace(ctx, r, depth + 1, RayKind::kRefraction, rng) * refract_weight;
  }
  return result;
}

}  // namespace raylab
