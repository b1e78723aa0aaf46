#include "light_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>

#include "raylab/geometry/planar.h"
#include "raylab/geometry/shading.h"
#include "raylab/geometry/sphere.h"
#include "raylab/render/whitted.h"
#include "raylab/scene/environment.h"
#include "shape_sampling.h"
#include "spot.h"

namespace raylab::detail {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Lat-long resolution of the stand-in for a sky gradient background (no environment given):
// fine enough that the gradient's steps do not show in the lighting.
constexpr int kSkyWidth = 256, kSkyHeight = 128;

// The settings' background as an environment: its colour, or its sky gradient drawn into a
// lat-long image so that it is importance-sampled like any other.
Environment background_environment(const RenderSettings& s) {
  Environment env;
  if (!s.sky_gradient) {
    env.color = s.background;
    return env;
  }
  auto image = std::make_shared<EnvironmentImage>();
  image->width = kSkyWidth;
  image->height = kSkyHeight;
  image->texels.resize(static_cast<std::size_t>(kSkyWidth) * kSkyHeight);
  for (int y = 0; y < kSkyHeight; ++y) {
    // The gradient depends on the height alone: one direction per row.
    const Color c =
        WhittedIntegrator::background(s, lat_long_direction(0.5f, (static_cast<float>(y) + 0.5f) / kSkyHeight));
    for (int x = 0; x < kSkyWidth; ++x) image->texels[static_cast<std::size_t>(y) * kSkyWidth + x] = c;
  }
  env.image = std::move(image);
  return env;
}

bool emits(Color c) { return c.x > 0.f || c.y > 0.f || c.z > 0.f; }

// The mean luminance of `image`'s texels: what an emission map does to its emitter's power.
float mean_luminance(const TextureImage& image) {
  double sum = 0.0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) sum += luminance(image.texel(x, y));
  }
  return static_cast<float>(sum / (static_cast<double>(image.width()) * image.height()));
}

// (a, b) with p - origin = a e1 + b e2, for p in the plane of the two edges: solved by the
// normal equations. (0, 0) when the edges span no area.
Vec2 plane_coordinates(Vec3 p, Vec3 origin, Vec3 e1, Vec3 e2) {
  const Vec3 d = p - origin;
  const float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  const float d1 = dot(d, e1), d2 = dot(d, e2);
  const float det = d11 * d22 - d12 * d12;
  if (!(det > 0.f)) return {0.f, 0.f};
  return {(d22 * d1 - d12 * d2) / det, (d11 * d2 - d12 * d1) / det};
}

// The surface coordinates surface_at gives point `at` of flat or round primitive `prim`: from
// the point's barycentric (triangle), edge (quad) or height (cylinder) coordinates, which
// surface_at reads from the hit, or from the point itself (sphere, disk), seen along its normal.
Vec2 surface_coordinates(const Geometry& g, std::uint32_t prim, const SurfacePoint& at) {
  Hit hit;
  hit.prim_id = prim;
  hit.t = 1.f;
  const ShapeRef ref = g.resolve(prim);
  if (ref.kind == ShapeKind::kCylinder) {
    // surface_at reads a cylinder's height fraction from the hit.
    const Cylinder& c = g.cylinders[ref.index];
    const Vec3 axis = c.apex - c.base;
    hit.v = dot(at.position - c.base, axis) / dot(axis, axis);
  } else if (ref.kind == ShapeKind::kTriangle || ref.kind == ShapeKind::kQuad) {
    Vec3 origin, e1, e2;
    if (ref.kind == ShapeKind::kTriangle) {
      const Triangle& t = g.triangles[ref.index];
      origin = t.p0, e1 = t.p1 - t.p0, e2 = t.p2 - t.p0;
    } else {
      const Quad& q = g.quads[ref.index];
      origin = q.corner, e1 = q.edge_u, e2 = q.edge_v;
    }
    const Vec2 c = plane_coordinates(at.position, origin, e1, e2);
    hit.u = c.x;
    hit.v = c.y;
  }
  Ray ray;
  ray.origin = at.position + at.normal;
  ray.direction = -at.normal;
  const SurfaceInteraction si = surface_at(g, ray, hit);
  return {si.u, si.v};
}

}  // namespace

LightSampler::LightSampler(const Scene& scene) : m_scene(scene) {
  std::vector<float> power;
  std::unordered_map<const TextureImage*, float> mean_of_map;  // each emission map's mean, once
  // An emitter's power, one side: an emission map scales it by the map's mean (the choice only
  // needs to be roughly proportional to what a light gives; the map varies within each primitive).
  const auto emitter_power = [&](Color radiance, float area, const TextureImage* map) {
    if (map != nullptr && !mean_of_map.contains(map)) mean_of_map[map] = mean_luminance(*map);
    return luminance(radiance) * area * kPi * (map != nullptr ? mean_of_map[map] : 1.f);
  };
  const Box3 bounds = scene.bounds();
  const float radius = !bounds.empty() ? 0.5f * length(bounds.hi - bounds.lo) : 1.f;

  // Emissive primitives of the scene's own geometry.
  const Geometry& g = scene.geometry;
  const std::uint32_t prims = g.size();
  for (std::uint32_t id = 0; id < prims; ++id) {
    const Material& m = scene.materials[scene.objects[g.object_of(id)].material];
    const Color radiance = m.emission * m.emission_strength;
    if (!emits(radiance)) continue;
    const TextureImage* map = m.maps.emission.get();
    if (m_light_of_prim.empty()) m_light_of_prim.assign(prims, -1);
    const ShapeRef ref = g.resolve(id);
    float area = 0.f;
    switch (ref.kind) {
      case ShapeKind::kTriangle:
        area = triangle_area(g.triangles[ref.index]);
        break;
      case ShapeKind::kSphere:
        area = sphere_area(g.spheres[ref.index]);
        break;
      case ShapeKind::kDisk:
        area = disk_area(g.disks[ref.index]);
        break;
      case ShapeKind::kQuad:
        area = quad_area(g.quads[ref.index]);
        break;
      case ShapeKind::kCylinder:
        area = cylinder_area(g.cylinders[ref.index]);
        break;
    }
    if (!(area > 0.f)) continue;
    m_light_of_prim[id] = static_cast<std::int32_t>(m_lights.size());
    m_lights.push_back({Kind::kShape, id, area, radiance, map != nullptr ? &m : nullptr});
    power.push_back(emitter_power(radiance, area, map));
  }

  // Emissive triangles of instanced meshes, carried into the world (an affine map keeps a
  // triangle a triangle, and area sampling uniform). Other instanced shapes glow where a ray
  // hits them but are not sampled (prototypes come from mesh files: triangles).
  for (const Instance& inst : scene.instances) {
    const Geometry& proto = scene.prototypes[inst.prototype];
    for (std::uint32_t local = 0; local < proto.triangles.size(); ++local) {
      const Material& m = scene.materials[scene.objects[inst.first_object + proto.object_of(local)].material];
      const Color radiance = m.emission * m.emission_strength;
      if (!emits(radiance)) continue;
      const Triangle& t = proto.triangles[local];
      const Triangle world{inst.to_world.point(t.p0), inst.to_world.point(t.p1), inst.to_world.point(t.p2)};
      const float area = triangle_area(world);
      const Vec3 normal = inst.to_world.normal(triangle_normal(t));
      if (!(area > 0.f) || !(dot(normal, normal) > 0.f)) continue;
      const TextureImage* map = m.maps.emission.get();
      const std::uint32_t id = g.size() + inst.first_prim_offset + local;
      m_light_of_instanced[id] = static_cast<std::int32_t>(m_lights.size());
      Entry e{Kind::kInstancedTriangle, id, area, radiance, map != nullptr ? &m : nullptr};
      e.instanced = static_cast<std::uint32_t>(m_instanced.size());
      m_instanced.push_back({world, normalize(normal), inst.prototype, local});
      m_lights.push_back(e);
      power.push_back(emitter_power(radiance, area, map));
    }
  }

  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const Light& light = scene.lights[l];
    const auto index = static_cast<std::uint32_t>(l);
    const Color pi_i = light.intensity * kPi;
    switch (light.kind) {
      case Light::Kind::kPoint:
        m_lights.push_back({Kind::kPoint, index, 0.f, pi_i});
        power.push_back(4.f * kPi * luminance(pi_i));
        break;
      case Light::Kind::kSpot: {
        // Its power: the solid angle of the cone (to the middle of the fade) times pi I.
        const float half = std::clamp(light.spot_angle, 0.f, 90.f) * (1.f - 0.5f * light.spot_blend) * kPi / 180.f;
        m_lights.push_back({Kind::kPoint, index, 0.f, pi_i});
        power.push_back(2.f * kPi * (1.f - std::cos(half)) * luminance(pi_i));
        break;
      }
      case Light::Kind::kDirectional:
        m_lights.push_back({Kind::kDirectional, index, 0.f, pi_i});
        power.push_back(kPi * radius * radius * luminance(pi_i));
        break;
      case Light::Kind::kQuad:
      case Light::Kind::kSphere: {
        if (light.object >= 0) break;  // its object is the emitter
        const bool quad = light.kind == Light::Kind::kQuad;
        const float area = quad ? quad_area(Quad{light.position, light.edge_u, light.edge_v})
                                : sphere_area(Sphere{light.position, light.radius});
        if (!(area > 0.f)) break;
        const Color radiance = pi_i / area;
        m_lights.push_back({quad ? Kind::kLightQuad : Kind::kLightSphere, index, area, radiance});
        m_has_light_shapes = true;
        power.push_back(luminance(radiance) * area * (quad ? 2.f : 1.f) * kPi);
        break;
      }
    }
  }

  m_environment.emplace(scene.environment ? *scene.environment : background_environment(scene.settings));
  const float env_power = luminance(m_environment->power_estimate(radius));
  if (env_power > 0.f) {
    m_environment_entry = static_cast<std::int32_t>(m_lights.size());
    m_lights.push_back({Kind::kEnvironment, 0, 0.f, Color{0.f}});
    power.push_back(env_power);
  }
  if (!m_lights.empty()) m_choice.emplace(power);
}

float LightSampler::choice_probability(std::size_t i) const {
  if (m_lights.size() == 1) return 1.f;  // as sample() takes it
  // The density of a bin's points over [0, 1) is n times the bin's probability.
  const auto n = static_cast<float>(m_choice->size());
  return m_choice->pdf((static_cast<float>(i) + 0.5f) / n) / n;
}

float LightSampler::area_pdf(Vec3 from, Vec3 at, Vec3 normal, float area, float choice) {
  const Vec3 d = at - from;
  const float dist2 = dot(d, d);
  const float cos_light = std::fabs(dot(normal, d)) / std::sqrt(dist2);
  if (!(cos_light > 0.f)) return 0.f;
  return choice * dist2 / (cos_light * area);
}

std::optional<LightSample> LightSampler::sample(Vec3 p, float u_choice, Sample2 u) const {
  if (m_lights.empty()) return std::nullopt;
  // One light needs no choice (the common case of a lamp or a sky: a CDF search saved per vertex).
  std::size_t index = 0;
  float choice = 1.f;
  if (m_lights.size() > 1) {
    const Distribution1D::Sample picked = m_choice->sample_continuous(u_choice);
    index = static_cast<std::size_t>(picked.index);
    choice = picked.pdf / static_cast<float>(m_choice->size());
  }
  const Entry& e = m_lights[index];
  LightSample ls;
  switch (e.kind) {
    case Kind::kPoint: {
      const Light& light = m_scene.lights[e.index];
      const Vec3 to = light.position - p;
      ls.distance = length(to);
      if (!(ls.distance > 0.f)) return std::nullopt;
      ls.wi = to / ls.distance;
      ls.li = light.falloff ? e.radiance / (ls.distance * ls.distance) : e.radiance;
      if (light.kind == Light::Kind::kSpot) ls.li = ls.li * spot_factor(light, -ls.wi);
      ls.pdf = choice;
      ls.delta = true;
      return ls;
    }
    case Kind::kDirectional: {
      const Light& light = m_scene.lights[e.index];
      ls.wi = normalize(-light.direction);
      ls.distance = std::numeric_limits<float>::infinity();
      ls.li = e.radiance;
      ls.pdf = choice;
      ls.delta = true;
      return ls;
    }
    case Kind::kEnvironment: {
      const std::optional<EnvironmentLight::Sample> s = m_environment->sample(u);
      if (!s || !(s->pdf > 0.f)) return std::nullopt;
      ls.wi = s->wi;
      ls.distance = std::numeric_limits<float>::infinity();
      ls.li = s->radiance;
      ls.pdf = s->pdf * choice;
      return ls;
    }
    case Kind::kShape:
    case Kind::kInstancedTriangle:
    case Kind::kLightQuad:
    case Kind::kLightSphere:
      break;
  }
  SurfacePoint at;
  if (e.kind == Kind::kShape) {
    const Geometry& g = m_scene.geometry;
    const ShapeRef ref = g.resolve(e.index);
    switch (ref.kind) {
      case ShapeKind::kTriangle:
        at = sample_triangle(g.triangles[ref.index], u);
        break;
      case ShapeKind::kSphere:
        at = sample_sphere(g.spheres[ref.index], u);
        break;
      case ShapeKind::kDisk:
        at = sample_disk(g.disks[ref.index], u);
        break;
      case ShapeKind::kQuad:
        at = sample_quad(g.quads[ref.index], u);
        break;
      case ShapeKind::kCylinder:
        at = sample_cylinder(g.cylinders[ref.index], u);
        break;
    }
  } else if (e.kind == Kind::kInstancedTriangle) {
    const InstancedTriangle& t = m_instanced[e.instanced];
    at = {sample_triangle(t.world, u).position, t.normal};
  } else {
    const Light& light = m_scene.lights[e.index];
    at = e.kind == Kind::kLightQuad ? sample_quad(Quad{light.position, light.edge_u, light.edge_v}, u)
                                    : sample_sphere(Sphere{light.position, light.radius}, u);
  }
  const Vec3 to = at.position - p;
  // An emitter of the scene lights the side its normal points to (a sphere or quad light that
  // is not geometry, both sides).
  const bool geometry = e.kind == Kind::kShape || e.kind == Kind::kInstancedTriangle;
  if (geometry && !(dot(at.normal, to) < 0.f)) return std::nullopt;
  ls.distance = length(to);
  if (!(ls.distance > 0.f)) return std::nullopt;
  ls.wi = to / ls.distance;
  ls.pdf = area_pdf(p, at.position, at.normal, e.area, choice);
  if (!(ls.pdf > 0.f) || !std::isfinite(ls.pdf)) return std::nullopt;
  ls.li = e.radiance;
  if (e.textured != nullptr) {
    Vec2 uv;
    if (e.kind == Kind::kInstancedTriangle) {
      // An affine map keeps barycentric coordinates: the world point's are the prototype's.
      const InstancedTriangle& t = m_instanced[e.instanced];
      const Triangle& w = t.world;
      const Vec2 b = plane_coordinates(at.position, w.p0, w.p1 - w.p0, w.p2 - w.p0);
      const Geometry& proto = m_scene.prototypes[t.prototype];
      const Triangle& local = proto.triangles[t.local];
      uv = surface_coordinates(
          proto, t.local,
          {local.p0 + (local.p1 - local.p0) * b.x + (local.p2 - local.p0) * b.y, normalize(triangle_normal(local))});
    } else {
      uv = surface_coordinates(m_scene.geometry, e.index, at);
    }
    ls.li = emitted_radiance(*e.textured, uv.x, uv.y);
  }
  return ls;
}

float LightSampler::emitter_pdf(Vec3 from, std::uint32_t prim, Vec3 at, Vec3 normal) const {
  std::int32_t light = -1;
  if (prim < m_light_of_prim.size()) {
    light = m_light_of_prim[prim];
  } else if (const auto it = m_light_of_instanced.find(prim); it != m_light_of_instanced.end()) {
    light = it->second;
  }
  if (light < 0) return 0.f;
  const auto entry = static_cast<std::size_t>(light);
  return area_pdf(from, at, normal, m_lights[entry].area, choice_probability(entry));
}

std::optional<LightShapeHit> LightSampler::hit_light_shape(const Ray& ray, float tmax) const {
  std::optional<LightShapeHit> best;
  if (!m_has_light_shapes) return best;
  for (std::size_t i = 0; i < m_lights.size(); ++i) {
    const Entry& e = m_lights[i];
    if (e.kind != Kind::kLightQuad && e.kind != Kind::kLightSphere) continue;
    const Light& light = m_scene.lights[e.index];
    float t = 0.f;
    Vec3 normal;
    if (e.kind == Kind::kLightQuad) {
      const Quad q{light.position, light.edge_u, light.edge_v};
      float s = 0.f, v = 0.f;
      if (!intersect_quad(q, ray, ray.tmin, tmax, t, s, v)) continue;
      normal = normalize(cross(q.edge_u, q.edge_v));
    } else {
      const Sphere sphere{light.position, light.radius};
      if (!intersect_sphere(sphere, ray, ray.tmin, tmax, t)) continue;
      normal = normalize(ray.origin + ray.direction * t - sphere.center);
    }
    tmax = t;
    best = LightShapeHit{t, e.radiance, static_cast<std::uint32_t>(i), normal};
  }
  return best;
}

float LightSampler::light_shape_pdf(Vec3 from, std::uint32_t light, Vec3 at, Vec3 normal) const {
  return area_pdf(from, at, normal, m_lights[light].area, choice_probability(light));
}

Color LightSampler::environment(Vec3 dir) const { return m_environment->radiance(dir); }

float LightSampler::environment_pdf(Vec3 dir) const {
  if (m_environment_entry < 0) return 0.f;
  return m_environment->pdf(dir) * choice_probability(static_cast<std::size_t>(m_environment_entry));
}

}  // namespace raylab::detail
