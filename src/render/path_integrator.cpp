#include "path_integrator.h"

#include <algorithm>
#include <cmath>

#include "material_bsdf.h"
#include "raylab/geometry/shading.h"
#include "raylab/render/bsdf.h"
#include "raylab/render/whitted.h"

namespace raylab::detail {
namespace {

// The power heuristic with exponent 2 (Veach 1997): the weight of a sample drawn with density
// `a` when the other strategy would have drawn it with density `b`.
float power_heuristic(float a, float b) {
  const float a2 = a * a;
  const float sum = a2 + b * b;
  return sum > 0.f ? a2 / sum : 0.f;
}

// The local shading frame: z along the shading normal.
struct Frame {
  Vec3 t, b, n;
  Vec3 to_local(Vec3 v) const { return {dot(v, t), dot(v, b), dot(v, n)}; }
  Vec3 to_world(Vec3 v) const { return t * v.x + b * v.y + n * v.z; }
};

Frame frame_of(Vec3 n) {
  Frame f;
  f.n = n;
  orthonormal_basis(n, f.t, f.b);
  return f;
}

bool cast_shadow_ray(const TraceContext& ctx, const Ray& ray) {
  const bool blocked =
      ctx.count_traversal ? ctx.accel.occluded_counted(ray, ctx.stats.traversal) : ctx.accel.occluded(ray);
  ctx.stats.count(RayKind::kShadow, blocked);
  return blocked;
}

// The pairs of one vertex, each computed when first used: an addressed source computes only the
// pairs a vertex reads, which saves the hashing of those it does not (the light choice with one
// light, the lobe of a one-lobe BSDF, the bounce after the last vertex); a plain generator's
// pairs are all drawn up front, in order, so that its stream is the same either way.
class VertexPairs {
 public:
  VertexPairs(SampleSource& source, int first) : m_source(source), m_first(first) {
    if (source.addressed()) return;
    source.seek_pair(first);
    for (Sample2& p : m_pairs) p = source.next_2d();
    m_have = 0b111;
  }
  // Pair `i` (0: light choice and lobe, 1: light point, 2: BSDF direction) of the vertex.
  Sample2 operator[](int i) {
    if ((m_have >> i & 1u) == 0) {
      m_pairs[i] = m_source.pair(m_first + i);
      m_have |= 1u << i;
    }
    return m_pairs[i];
  }

 private:
  SampleSource& m_source;
  int m_first;
  Sample2 m_pairs[3]{};
  unsigned m_have = 0;
};

// Shadow rays stop this fraction short of a light point, so that the emitter's own surface
// does not block the ray that reaches it.
constexpr float kShadowShorten = 1e-3f;

}  // namespace

float PathIntegrator::found_light_weight(bool delta, float bsdf_pdf, float light_pdf) const {
  if (delta) return 1.f;  // no light sample could have found it
  switch (m_strategy) {
    case Strategy::kMis:
      return power_heuristic(bsdf_pdf, light_pdf);
    case Strategy::kLightsOnly:
      return light_pdf > 0.f ? 0.f : 1.f;  // a light no sample reaches still counts
    case Strategy::kBsdfOnly:
      return 1.f;
  }
  return 1.f;
}

float PathIntegrator::light_sample_weight(bool delta, bool last, float light_pdf, float bsdf_pdf) const {
  if (delta || last) return 1.f;  // no bounce ray could find it (or none follows)
  switch (m_strategy) {
    case Strategy::kMis:
      return power_heuristic(light_pdf, bsdf_pdf);
    case Strategy::kLightsOnly:
      return 1.f;
    case Strategy::kBsdfOnly:
      return 0.f;
  }
  return 1.f;
}

Color PathIntegrator::radiance(const TraceContext& ctx, const Ray& camera_ray, SampleSource& samples,
                               PrimaryFeature* feature) const {
  const Scene& scene = ctx.scene;
  const int max_depth = std::clamp(scene.settings.max_depth, 1, WhittedIntegrator::kMaxDepth);
  Color radiance{0.f};
  Color throughput{1.f};
  Ray ray = camera_ray;
  // What the previous vertex's BSDF sample was, for the MIS weight of light found by this ray.
  bool previous_delta = true;  // the camera ray: nothing else could have found what it sees
  float previous_pdf = 0.f;
  Vec3 previous_position = ray.origin;

  for (int vertex = 0;; ++vertex) {
    Hit hit;
    const RayKind kind = vertex == 0 ? RayKind::kPrimary : RayKind::kReflection;
    const bool found = ctx.count_traversal ? ctx.accel.intersect_counted(ray, hit, ctx.stats.traversal)
                                           : ctx.accel.intersect(ray, hit);
    ctx.stats.count(kind, found);
    const float t_hit = found ? hit.t : ray.tmax;

    // Light shapes that are not geometry (sphere and quad lights without an object).
    if (const std::optional<LightShapeHit> lh = m_lights.hit_light_shape(ray, t_hit)) {
      const Vec3 at = ray.origin + ray.direction * lh->t;
      const float w = found_light_weight(previous_delta, previous_pdf,
                                         m_lights.light_shape_pdf(previous_position, lh->light, at, lh->normal));
      radiance += throughput * lh->radiance * w;
      break;
    }
    if (!found) {
      const Vec3 dir = normalize(ray.direction);
      // Seen directly, the background is the settings' own function (or the environment).
      const Color env = vertex == 0 && !scene.environment ? WhittedIntegrator::background(scene.settings, dir)
                                                          : m_lights.environment(dir);
      const float w = found_light_weight(previous_delta, previous_pdf, m_lights.environment_pdf(dir));
      radiance += throughput * env * w;
      break;
    }

    const SurfaceInteraction si = shading_surface_at(scene, ray, hit);
    if (feature && vertex == 0) {
      feature->object = static_cast<std::int32_t>(si.object_id);
      feature->normal = si.shading_normal;
    }
    const Material& material = scene.materials[scene.objects[si.object_id].material];

    // Light emitted by the surface found: emitters emit on the side their normal points to.
    const Color emitted = si.front_face ? emitted_radiance(material, si.u, si.v) : Color{0.f};
    if (emitted.x > 0.f || emitted.y > 0.f || emitted.z > 0.f) {
      const float light_pdf =
          previous_delta ? 0.f : m_lights.emitter_pdf(previous_position, hit.prim_id, si.position, si.geometric_normal);
      radiance += throughput * emitted * found_light_weight(previous_delta, previous_pdf, light_pdf);
    }

    static_assert(kPairsPerVertex == 3, "VertexPairs holds the three pairs of a vertex");
    VertexPairs pairs(samples, 1 + kPairsPerVertex * vertex);  // (light and lobe choice, light point, BSDF)

    const MaterialPoint at = material_at(material, si.u, si.v);
    const Bsdf bsdf = material.model == MaterialModel::kMetallicRoughness
                          ? material_bsdf(material, at, samples.rng().next_float())
                          : material_bsdf(material, at, 0.f);
    // Reflectors are shaded on the side the ray arrived from (the shading normal faces it); a
    // dielectric needs its outside as +z, so that a ray inside sees wo.z < 0 and the inverse index.
    const bool outward = bsdf.model() == Bsdf::Model::kDielectric && !si.front_face;
    const Frame frame = frame_of(outward ? -si.shading_normal : si.shading_normal);
    const Vec3 wo_world = -normalize(ray.direction);
    const Vec3 wo = frame.to_local(wo_world);
    const bool last = vertex + 1 >= max_depth;

    // Next-event estimation: a point on a light, its shadow ray, weighted against the chance
    // that the BSDF sample finds the same light (unless this is the last vertex, where the
    // light sample is the only estimate).
    if (!bsdf.is_delta() && !m_lights.empty()) {
      const float u_which = m_lights.chooses() ? pairs[0].x : 0.f;
      if (const std::optional<LightSample> ls = m_lights.sample(si.position, u_which, pairs[1])) {
        const Vec3 wi = frame.to_local(ls->wi);
        // A light behind the geometric surface (seen from the side the ray arrived on) can only
        // reach it through it: only transmitting models may use it.
        const bool same_side = dot(ls->wi, si.geometric_normal) > 0.f;
        const Color f = bsdf.eval(wo, wi);
        if ((f.x > 0.f || f.y > 0.f || f.z > 0.f) && (same_side || bsdf.model() == Bsdf::Model::kDielectric)) {
          Ray shadow;
          shadow.origin = offset_origin(si.position, si.geometric_normal, ls->wi);
          shadow.direction = ls->wi;
          shadow.tmin = 0.f;
          shadow.tmax = std::isfinite(ls->distance) ? ls->distance * (1.f - kShadowShorten) : INFINITY;
          if (!cast_shadow_ray(ctx, shadow)) {
            const float w = light_sample_weight(ls->delta, last, ls->pdf, bsdf.pdf(wo, wi));
            radiance += throughput * f * (std::fabs(wi.z) * w / ls->pdf) * ls->li;
          }
        }
      }
    }
    if (last) break;

    // The next direction, from the BSDF.
    const std::optional<BsdfSample> bs = bsdf.sample(wo, bsdf.chooses_lobe() ? pairs[0].y : 0.f, pairs[2]);
    if (!bs || !(bs->pdf > 0.f)) break;
    throughput = throughput * bs->weight;
    if (!(max_component(throughput) > 0.f)) break;
    const Vec3 wi_world = normalize(frame.to_world(bs->wi));
    previous_delta = bs->delta;
    previous_pdf = bs->pdf;
    previous_position = si.position;
    ray = Ray{};
    ray.origin = offset_origin(si.position, si.geometric_normal, wi_world);
    ray.direction = wi_world;

    // Russian roulette: a path whose throughput has fallen continues with probability equal to
    // it (at most 1), and is weighted up when it does, which keeps the estimate unbiased.
    if (vertex + 1 >= kRouletteFrom) {
      const float keep = std::min(1.f, max_component(throughput));
      if (samples.rng().next_float() >= keep) break;
      throughput = throughput / keep;
    }
  }
  return radiance;
}

}  // namespace raylab::detail
