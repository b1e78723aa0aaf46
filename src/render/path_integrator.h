#pragma once
// Internal to the render module: the Monte Carlo path tracer (make_integrator("path")).

#include "light/light_sampler.h"
#include "raylab/render/integrator.h"

namespace raylab::detail {

/// Unidirectional path tracing with next-event estimation, combined with BSDF sampling by
/// multiple importance sampling (power heuristic, Veach 1997), and Russian roulette.
///
/// Depth: RenderSettings::max_depth counts path vertices as Whitted counts its ray tree: 1 is
/// direct light only (a camera ray, its hit lit by the lights), each more a bounce (Cycles'
/// "max bounces" is max_depth - 1). At the last vertex the light sample is the only estimate
/// of direct light, so it takes full weight there.
///
/// Dimension layout (SampleSource pairs, sample_dimensions.h): vertex k (k = 0 at the camera
/// ray's hit) uses pairs 1 + 3k to 3 + 3k, whatever it draws:
///   1 + 3k: (which light, which lobe of the BSDF);
///   2 + 3k: the point on the light;
///   3 + 3k: the BSDF direction.
/// Each 2D decision gets a whole pair, so it keeps the sampler's 2D stratification. Russian
/// roulette and a mixed material's choice of model take independent numbers from the path's
/// generator (SampleSource::rng), in that order of need: they gain nothing from stratification,
/// and a pair each would cost a quarter more sampling time.
class PathIntegrator final : public Integrator {
 public:
  /// How direct light is estimated. Each alone is unbiased too (the tests check that all three
  /// converge to one image); MIS is what renders use.
  enum class Strategy : unsigned char {
    kMis,         ///< light samples and BSDF samples, weighted by the power heuristic
    kLightsOnly,  ///< light samples only (light that a bounce ray finds counts only after a delta bounce)
    kBsdfOnly,    ///< BSDF samples only (point and directional lights then give nothing)
  };

  /// The pairs one vertex uses.
  static constexpr int kPairsPerVertex = 3;
  /// Russian roulette starts at this vertex (0-based): earlier ones always continue.
  static constexpr int kRouletteFrom = 3;

  /// A path tracer for `scene` (which must outlive it).
  explicit PathIntegrator(const Scene& scene, Strategy strategy = Strategy::kMis)
      : m_lights(scene), m_strategy(strategy) {}

  /// "path".
  std::string_view name() const override { return "path"; }
  /// See the class comment.
  Color radiance(const TraceContext& ctx, const Ray& ray, SampleSource& samples,
                 PrimaryFeature* feature = nullptr) const override;

 private:
  // The weight of light that a bounce ray found, which the previous vertex's BSDF sampled with
  // density `bsdf_pdf` (`delta`: a specular bounce) and light sampling would have with `light_pdf`.
  float found_light_weight(bool delta, float bsdf_pdf, float light_pdf) const;
  // The weight of a light sample of density `light_pdf` (`delta`: a point or directional light)
  // that the BSDF would sample with `bsdf_pdf`; `last`: no bounce follows this vertex.
  float light_sample_weight(bool delta, bool last, float light_pdf, float bsdf_pdf) const;

  LightSampler m_lights;
  Strategy m_strategy;
};

}  // namespace raylab::detail
