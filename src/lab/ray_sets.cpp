#include "raylab/lab/ray_sets.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "raylab/core/error.h"
#include "raylab/core/rng.h"
#include "raylab/geometry/shading.h"
#include "raylab/render/camera.h"
#include "raylab/sampling/seed_salts.h"

namespace raylab {
namespace {

// Shadow rays stop this fraction short of the light, as in the Whitted integrator, so that a
// light lying on a surface is not shadowed by that surface.
constexpr float kShadowShorten = 1e-3f;
constexpr float kTwoPi = 6.2831853f;

// A point on `light` seen from `p`, chosen by `rng`; for a sphere, on the half facing `p`.
Vec3 light_point(const Light& light, Vec3 p, Pcg32& rng) {
  const float u = rng.next_float();
  const float v = rng.next_float();
  if (light.kind == Light::Kind::kQuad) return light.position + light.edge_u * u + light.edge_v * v;
  if (light.kind == Light::Kind::kSphere) {
    const float z = 1.f - 2.f * u;
    const float r = std::sqrt(std::max(0.f, 1.f - z * z));
    Vec3 d{r * std::cos(kTwoPi * v), r * std::sin(kTwoPi * v), z};
    if (dot(d, p - light.position) < 0.f) d = -d;
    return light.position + d * light.radius;
  }
  return light.position;
}

// The shadow ray from hit point `p` (geometric normal `ng`, facing the viewer) toward `light`;
// false when the surface faces away from the light, where a renderer casts no shadow ray.
bool shadow_ray(const Light& light, Vec3 p, Vec3 ng, Pcg32& rng, Ray& out) {
  Vec3 wi;
  float distance = INFINITY;
  if (light.kind == Light::Kind::kDirectional) {
    wi = normalize(-light.direction);
  } else {
    const Vec3 to = light_point(light, p, rng) - p;
    distance = length(to);
    if (!(distance > 0.f)) return false;
    wi = to / distance;
  }
  if (!(dot(ng, wi) > 0.f)) return false;
  out.origin = offset_origin(p, ng, wi);
  out.direction = wi;
  out.tmin = 0.f;
  out.tmax = std::isfinite(distance) ? distance * (1.f - kShadowShorten) : INFINITY;
  return true;
}

// A cosine-weighted direction about unit `n` (Malley's method: a uniform disk point lifted
// onto the hemisphere).
Vec3 cosine_direction(Vec3 n, Pcg32& rng) {
  const float u = rng.next_float();
  const float v = rng.next_float();
  const float r = std::sqrt(u);
  const float phi = kTwoPi * v;
  Vec3 t, b;
  orthonormal_basis(n, t, b);
  return normalize(t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(std::max(0.f, 1.f - u)));
}

// Appends the rays whose slot is set, in the order of the primary rays, each tagged with the
// pixel of its primary ray.
void compact(const std::vector<Ray>& slots, const std::vector<std::uint8_t>& used,
             const std::vector<std::uint32_t>& pixel, RaySet& set) {
  for (std::size_t i = 0; i < slots.size(); ++i) {
    if (!used[i]) continue;
    set.rays.push_back(slots[i]);
    set.pixel.push_back(pixel[i]);
  }
}

}  // namespace

const char* bench_ray_kind_name(BenchRayKind kind) {
  // A table, indexed by BenchRayKind: the names are data, not a switch to keep in step.
  static constexpr const char* kNames[kBenchRayKinds] = {"primary", "shadow", "diffuse"};
  const int k = static_cast<int>(kind);
  return k >= 0 && k < kBenchRayKinds ? kNames[k] : "?";
}

std::size_t RaySets::total_rays() const {
  std::size_t n = 0;
  for (const RaySet& s : sets) n += s.rays.size();
  return n;
}

std::vector<Ray> primary_rays(const Scene& scene, int width, int height) {
  if (width < 1 || height < 1) {
    throw UsageError("ray set size must be at least 1x1, not " + std::to_string(width) + "x" + std::to_string(height));
  }
  return pixel_centre_rays(scene.camera, width, height);
}

RaySets make_ray_sets(const Scene& scene, const Accelerator& reference, const RaySetOptions& options) {
  RaySets sets;
  sets.width = options.width;
  sets.height = options.height;
  RaySet& primary = sets.sets[static_cast<int>(BenchRayKind::kPrimary)];
  primary.rays = primary_rays(scene, options.width, options.height);
  const std::size_t n = primary.rays.size();
  primary.pixel.resize(n);
  for (std::size_t i = 0; i < n; ++i) primary.pixel[i] = static_cast<std::uint32_t>(i);
  add_secondary_rays(scene, reference, scene.lights.empty() ? nullptr : &scene.lights.front(), options.seed, sets);
  return sets;
}

void add_secondary_rays(const Scene& scene, const Accelerator& reference, const Light* light, std::uint64_t seed,
                        RaySets& sets) {
  const RaySet& primary = sets.sets[static_cast<int>(BenchRayKind::kPrimary)];
  const std::size_t n = primary.rays.size();
  // Each primary ray fills its own slots (in parallel), then the used slots are gathered in
  // primary-ray order: the result is the same whatever the thread count.
  std::vector<Ray> shadow(n), diffuse(n);
  std::vector<std::uint8_t> has_shadow(n, 0), has_diffuse(n, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      Ray ray = primary.rays[i];
      Hit hit;
      if (!reference.intersect(ray, hit)) continue;
      const SurfaceInteraction si = surface_at(scene, ray, hit);
      const Vec3 ng = si.geometric_normal;
      const std::uint64_t pixel = primary.pixel[i];
      if (light) {
        Pcg32 rng(hash_seed(pixel, seed, kRaySetLightStream));
        has_shadow[i] = shadow_ray(*light, si.position, ng, rng, shadow[i]) ? 1 : 0;
      }
      Pcg32 rng(hash_seed(pixel, seed, kRaySetBounceStream));
      const Vec3 dir = cosine_direction(ng, rng);
      diffuse[i].origin = offset_origin(si.position, ng, dir);
      diffuse[i].direction = dir;
      diffuse[i].tmin = 0.f;
      diffuse[i].tmax = INFINITY;
      has_diffuse[i] = 1;
    }
  });
  RaySet& shadows = sets.sets[static_cast<int>(BenchRayKind::kShadow)];
  RaySet& diffuses = sets.sets[static_cast<int>(BenchRayKind::kDiffuse)];
  shadows = {};
  diffuses = {};
  compact(shadow, has_shadow, primary.pixel, shadows);
  compact(diffuse, has_diffuse, primary.pixel, diffuses);
}

}  // namespace raylab
