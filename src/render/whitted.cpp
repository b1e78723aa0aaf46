#include "raylab/render/whitted.h"

#include <algorithm>
#include <cmath>

#include "light/shape_sampling.h"
#include "light/spot.h"
#include "raylab/geometry/shading.h"
#include "raylab/render/optics.h"

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

// Side of the square grid of stratified samples shading takes of `light` (1 for point and
// directional lights).
int sample_grid(const Light& light) {
  if (light.kind != Light::Kind::kSphere && light.kind != Light::Kind::kQuad) return 1;
  return std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<float>(std::max(1, light.samples))))));
}

// Sample (sx, sy) of the `grid` x `grid` stratification of `light` seen from `at`: fills `ls`
// and the shadow ray toward it. Returns false when no shadow ray is cast (no distance to the
// sample, or the surface faces away by rule 10). Draws two numbers from `rng` when
// grid > 1 and none otherwise, which is what lets the packet path precompute the shadow rays of
// single-sample lights. One function for both paths, so that they agree bit for bit.
bool sample_light(const Light& light, int grid, int sx, int sy, const ShadingPoint& at, Pcg32* rng, LightSample& ls,
                  Ray& shadow) {
  const Vec3 p = at.p;
  if (light.kind == Light::Kind::kDirectional) {
    ls.wi = normalize(-light.direction);
    ls.distance = INFINITY;
  } else {
    Vec3 target = light.position;
    if (grid > 1) {
      const float u = (static_cast<float>(sx) + rng->next_float()) / static_cast<float>(grid);
      const float v = (static_cast<float>(sy) + rng->next_float()) / static_cast<float>(grid);
      if (light.kind == Light::Kind::kQuad) {
        target = light.position + light.edge_u * u + light.edge_v * v;
      } else {
        target = detail::point_on_sphere(light.position, light.radius, u, v);
      }
    }
    const Vec3 to = target - p;
    ls.distance = length(to);
    if (!(ls.distance > 0.f)) return false;
    ls.wi = to / ls.distance;
  }
  ls.radiance = light.intensity * (1.f / static_cast<float>(grid * grid));
  if (light.falloff && std::isfinite(ls.distance)) ls.radiance /= ls.distance * ls.distance;
  if (light.kind == Light::Kind::kSpot) {
    const float cone = detail::spot_factor(light, -ls.wi);
    if (!(cone > 0.f)) return false;  // outside the cone: no light, no shadow ray
    ls.radiance *= cone;
  }
  // Only surfaces that face the light cast a shadow ray (SPD testing procedure, rule 10).
  if (dot(at.rule_n, ls.wi) <= 0.f || dot(at.rule_ng, ls.wi) <= 0.f) return false;
  shadow.origin = at.origin_toward(ls.wi);
  shadow.direction = ls.wi;
  shadow.tmin = 0.f;
  shadow.tmax = std::isfinite(ls.distance) ? ls.distance * (1.f - kShadowShorten) : INFINITY;
  return true;
}

// Contribution of `light` at the shading point, averaging stratified positions for area lights:
// a soft shadow is the fraction of the light's samples that the point sees. `decided` replaces
// the sampling and the shadow ray when it is decided (single-sample lights only).
Color shade_light(const TraceContext& ctx, const Light& light, const Material& m, Color base, const ShadingPoint& at,
                  Vec3 view, Pcg32& rng, const DecidedShadow& decided) {
  const int grid = sample_grid(light);
  Color sum{0.f};
  for (int sy = 0; sy < grid; ++sy) {
    for (int sx = 0; sx < grid; ++sx) {
      LightSample ls;
      bool blocked;
      if (decided.answer == ShadowAnswer::kTrace) {
        Ray shadow;
        if (!sample_light(light, grid, sx, sy, at, &rng, ls, shadow)) continue;
        blocked = cast_shadow_ray(ctx, shadow);
      } else {
        ls = decided.sample;  // what sample_light gave the packet path (grid is 1)
        blocked = decided.answer == ShadowAnswer::kBlocked;
      }
      // Light reaches only the side the ray sees (under the outward reading a shadow ray can be
      // cast from a back face toward a light on the other side: it is counted, and adds nothing).
      if (blocked) continue;
      if (ctx.shadow_facing != ShadowFacing::kViewer && (dot(at.n, ls.wi) <= 0.f || dot(at.ng, ls.wi) <= 0.f)) continue;
      sum += phong(m, base, at.n, view, ls.wi, ls.radiance);
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

bool WhittedIntegrator::is_single_sample(const Light& light) { return sample_grid(light) == 1; }

ShadingPoint WhittedIntegrator::shading_point(const SurfaceInteraction& si, ShadowFacing facing) {
  const bool turn = facing == ShadowFacing::kOutward && !si.front_face;
  const Vec3 p = si.position, n = si.shading_normal, ng = si.geometric_normal;
  return {p, n, ng, turn ? -n : n, turn ? -ng : ng, offset_origins(p, ng)};
}

bool WhittedIntegrator::single_sample_shadow_ray(const Light& light, const ShadingPoint& at, Ray& shadow,
                                                 LightSample& sample) {
  return sample_light(light, 1, 0, 0, at, nullptr, sample, shadow);
}

Color WhittedIntegrator::radiance(const TraceContext& ctx, const Ray& ray, SampleSource& samples,
                                  PrimaryFeature* feature) const {
  return trace(ctx, ray, 1, RayKind::kPrimary, samples.rng(), feature);
}

Color WhittedIntegrator::trace(const TraceContext& ctx, Ray ray, int depth, RayKind kind, Pcg32& rng,
                               PrimaryFeature* feature) {
  Hit hit;
  const bool found =
      ctx.count_traversal ? ctx.accel.intersect_counted(ray, hit, ctx.stats.traversal) : ctx.accel.intersect(ray, hit);
  ctx.stats.count(kind, found);
  if (!found) return background(ctx.scene.settings, ray.direction);
  const SurfaceInteraction si = shading_surface_at(ctx.scene, ray, hit);
  return shade(ctx, ray, si, shading_point(si, ctx.shadow_facing), depth, rng, {}, feature);
}

Color WhittedIntegrator::shade(const TraceContext& ctx, const Ray& ray, const SurfaceInteraction& si,
                               const ShadingPoint& at, int depth, Pcg32& rng, std::span<const DecidedShadow> shadows,
                               PrimaryFeature* feature) {
  const Scene& scene = ctx.scene;
  const Material& m = scene.materials[scene.objects[si.object_id].material];
  const Vec3 d = normalize(ray.direction);
  const Vec3 n = si.shading_normal;
  const Vec3 view = -d;
  const Color base = diffuse_color(m, si.u, si.v);
  if (feature) {
    feature->object = static_cast<std::int32_t>(si.object_id);
    feature->normal = n;
  }

  Color result = m.emission + scene.settings.ambient * base * m.kd;
  static constexpr DecidedShadow kUndecided{};
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const DecidedShadow& decided = shadows.empty() ? kUndecided : shadows[l];
    result += shade_light(ctx, scene.lights[l], m, base, at, view, rng, decided);
  }

  // Capped whatever the settings say: each level is a frame of this recursion on the stack.
  if (depth >= std::min(scene.settings.max_depth, WhittedIntegrator::kMaxDepth)) return result;

  // Which rays spawn follows the SPD procedure's rules 8 and 9 and depends only on the material's
  // kind and the geometry, never on a weight: a transmitter reflects at every hit (as a
  // dielectric interface does) and refracts unless total internal reflection occurs.
  float reflect_weight = m.reflectivity;
  float refract_weight = 0.f;
  bool spawn_reflection = m.reflectivity > 0.f;
  bool spawn_refraction = false;
  Vec3 refracted;
  if (m.transmittance > 0.f) {
    spawn_reflection = true;
    const float eta_i = si.front_face ? 1.f : m.ior;
    const float eta_t = si.front_face ? m.ior : 1.f;
    spawn_refraction = refract(d, n, eta_i / eta_t, refracted);
    if (spawn_refraction) {
      const float f = m.fresnel ? fresnel_dielectric(dot(view, n), eta_i, eta_t) : 0.f;
      reflect_weight += m.transmittance * f;
      refract_weight = m.transmittance * (1.f - f);
    } else {
      reflect_weight += m.transmittance;  // total internal reflection
      ++ctx.stats.total_internal_reflections;
    }
  }
  if (spawn_reflection) {
    Ray r;
    r.direction = reflect(d, n);
    r.origin = at.origin_toward(r.direction);
    result += trace(ctx, r, depth + 1, RayKind::kReflection, rng) * reflect_weight;
  }
  if (spawn_refraction) {
    Ray r;
    r.direction = normalize(refracted);
    r.origin = at.origin_toward(r.direction);
    result += trace(ctx, r, depth + 1, RayKind::kRefraction, rng) * refract_weight;
  }
  return result;
}

}  // namespace raylab
