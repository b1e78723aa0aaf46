// The path integrator against answers known without it: white furnaces (a closed energy
// balance), Whitted's direct light at depth 1, the three direct-light strategies converging to
// one value, and images that do not depend on the thread count.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "../../src/render/path_integrator.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/render/renderer.h"
#include "raylab/render/whitted.h"
#include "raylab/sampling/pixel_sampler.h"
#include "raylab/sampling/sample_dimensions.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {
namespace {

using detail::PathIntegrator;

// Mean and variance of the mean of n independent estimates.
struct Estimate {
  Color mean{0.f};
  Color variance_of_mean{0.f};
};

// `n` path samples along rays from `eye` toward points spread over the disc of radius `spread`
// around `target` (perpendicular to the view), each with its own stratified sample index.
Estimate estimate(const Scene& scene, const Integrator& integrator, Vec3 eye, Vec3 target, float spread, int n) {
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  RenderStats stats;
  const TraceContext ctx{scene, *accel, stats, false, ShadowFacing::kViewer, &integrator};
  const std::unique_ptr<PixelSampler> sampler = make_pixel_sampler("sobol", n, 11);
  const SampleDimensions dims(*sampler);
  Vec3 t, b;
  const Vec3 view = normalize(target - eye);
  orthonormal_basis(view, t, b);
  std::vector<Color> values;
  for (int i = 0; i < sampler->spp(); ++i) {
    const Sample2 u = sampler->sample(0, 0, i);
    const float r = spread * std::sqrt(u.x), phi = 2.f * std::numbers::pi_v<float> * u.y;
    Ray ray;
    ray.origin = eye;
    ray.direction = normalize(target + (t * std::cos(phi) + b * std::sin(phi)) * r - eye);
    SampleSource samples(sample_path_seed(11, 0, 0, i), dims, 0, 0, i);
    values.push_back(integrator.radiance(ctx, ray, samples));
  }
  Estimate e;
  for (const Color& v : values) e.mean += v;
  e.mean = e.mean / static_cast<float>(values.size());
  for (const Color& v : values) e.variance_of_mean += (v - e.mean) * (v - e.mean);
  const auto count = static_cast<float>(values.size());
  e.variance_of_mean = e.variance_of_mean / (count * (count - 1.f));
  return e;
}

// A sphere of `material` in a uniform white environment (the settings' background).
Scene furnace(const Material& material) {
  Scene s;
  s.settings.background = Color{1.f};
  s.settings.max_depth = 64;
  s.geometry.add(Sphere{Vec3{0.f}, 1.f}, s.add_object("sphere", s.add_material(material)));
  return s;
}

Color furnace_value(const Material& m, int n = 4096) {
  const Scene s = furnace(m);
  const PathIntegrator path(s);
  const Estimate e = estimate(s, path, Vec3{0.f, 0.f, 5.f}, Vec3{0.f}, 0.95f, n);
  return e.mean;
}

Material model(MaterialModel kind, Color color, float roughness = 0.f, float ior = 1.5f) {
  Material m;
  m.model = kind;
  m.color = color;
  m.roughness = roughness;
  m.ior = ior;
  return m;
}

TEST(PathIntegrator, DiffuseSphereInWhiteFurnaceReturnsItsAlbedo) {
  // A convex sphere sees only the environment: what it sends back is albedo x 1, exactly.
  for (float rho : {1.f, 0.5f, 0.2f}) {
    const Color got = furnace_value(model(MaterialModel::kDiffuse, Color{rho}));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], rho, 0.01f * rho + 1e-3f) << "albedo " << rho;
  }
}

TEST(PathIntegrator, LosslessMaterialsReturnOneInWhiteFurnace) {
  // Glass sends every ray on after any number of internal bounces; a perfect smooth mirror
  // reflects everything.
  Material mirror = model(MaterialModel::kConductor, Color{1.f});
  mirror.conductor_eta = Color{1e-4f};
  mirror.conductor_k = Color{1e4f};
  for (const Material& m : {model(MaterialModel::kDielectric, Color{1.f}),
                            model(MaterialModel::kDielectric, Color{1.f}, 0.f, 2.4f), mirror}) {
    const Color got = furnace_value(m);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], 1.f, 0.01f) << "model " << static_cast<int>(m.model);
  }
}

TEST(PathIntegrator, RoughAndCoatedMaterialsLoseLittleEnergy) {
  // Single-scattering microfacet models lose the light that would scatter between microfacets
  // (docs/rendering.md has the measured figures): never more than comes in, and little at low
  // roughness.
  Material metal = model(MaterialModel::kConductor, Color{1.f}, 0.3f);
  metal.conductor_eta = Color{1e-4f};
  metal.conductor_k = Color{1e4f};
  const Color rough_metal = furnace_value(metal);
  EXPECT_LE(rough_metal.y, 1.01f);
  EXPECT_GE(rough_metal.y, 0.95f);
  const Color rough_glass = furnace_value(model(MaterialModel::kDielectric, Color{1.f}, 0.3f));
  EXPECT_LE(rough_glass.y, 1.01f);
  EXPECT_GE(rough_glass.y, 0.9f);
  const Color plastic = furnace_value(model(MaterialModel::kPlastic, Color{1.f}, 0.1f));
  EXPECT_LE(plastic.y, 1.02f);
  EXPECT_GE(plastic.y, 0.9f);
}

// A diffuse floor lit by light `which` of a point, a directional and a spot light (no
// interreflection possible; one light, so that the light sample needs no choice between lights).
Scene direct_light_scene(int which) {
  Scene s;
  Material floor;
  floor.color = {0.6f, 0.5f, 0.4f};
  s.geometry.add(Quad{Vec3{-5.f, 0.f, -5.f}, Vec3{0.f, 0.f, 10.f}, Vec3{10.f, 0.f, 0.f}},
                 s.add_object("floor", s.add_material(floor)));
  Light point;
  point.position = {1.f, 3.f, 0.5f};
  point.intensity = {2.f, 2.f, 2.f};
  point.falloff = true;
  Light sun;
  sun.kind = Light::Kind::kDirectional;
  sun.direction = normalize(Vec3{-1.f, -2.f, 0.3f});
  sun.intensity = {0.3f, 0.4f, 0.5f};
  // A spot whose cone edge crosses the points looked at: inside, fading and outside.
  Light spot = point;
  spot.kind = Light::Kind::kSpot;
  spot.direction = normalize(Vec3{-0.3f, -1.f, 0.1f});
  spot.spot_angle = 40.f;
  spot.spot_blend = 0.4f;
  s.lights = {which == 0 ? point : which == 1 ? sun : spot};
  s.settings.max_depth = 1;
  return s;
}

TEST(PathIntegrator, DirectLightAtDepthOneIsWhittedsDirectLight) {
  // Point and directional lights are sampled exactly (no noise), so both integrators agree to
  // float rounding: albedo/pi x pi I cos / d^2 against kd colour x I cos / d^2.
  for (int which : {0, 1, 2}) {
    const Scene s = direct_light_scene(which);
    const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", s.geometry);
    const PathIntegrator path(s);
    const WhittedIntegrator whitted;
    RenderStats stats;
    const TraceContext ctx{s, *accel, stats};
    for (float x : {-2.f, -0.5f, 0.f, 1.f, 2.5f}) {
      for (float z : {-1.5f, 0.f, 2.f}) {
        Ray ray;
        ray.origin = {0.f, 2.f, 6.f};
        ray.direction = normalize(Vec3{x, 0.f, z} - ray.origin);
        SampleSource a(1), b(1);
        const Color want = whitted.radiance(ctx, ray, a);
        const Color got = path.radiance(ctx, ray, b);
        if (which != 2) {
          ASSERT_GT(want.y, 0.01f);  // lit, so that the comparison means something
        }
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-5f + 1e-5f * want[k]) << x << " " << z;
      }
    }
  }
}

// A floor and a glossy ball under an emissive quad, beside an emissive cone, in a dim environment: every strategy has
// light it finds well and light it finds badly.
Scene strategy_scene() {
  Scene s;
  s.settings.background = Color{0.2f};
  s.settings.max_depth = 4;
  const std::uint32_t floor = s.add_material(model(MaterialModel::kDiffuse, Color{0.7f}));
  const std::uint32_t ball = s.add_material(model(MaterialModel::kPlastic, Color{0.3f, 0.5f, 0.7f}, 0.3f));
  Material lamp = model(MaterialModel::kDiffuse, Color{0.f});
  lamp.emission = {4.f, 3.f, 2.f};
  s.geometry.add(Quad{Vec3{-5.f, 0.f, -5.f}, Vec3{0.f, 0.f, 10.f}, Vec3{10.f, 0.f, 0.f}}, s.add_object("floor", floor));
  s.geometry.add(Sphere{Vec3{0.f, 1.f, 0.f}, 1.f}, s.add_object("ball", ball));
  s.geometry.add(Quad{Vec3{-1.f, 4.f, -1.f}, Vec3{2.f, 0.f, 0.f}, Vec3{0.f, 0.f, 2.f}},
                 s.add_object("lamp", s.add_material(lamp)));
  // A second light, a glowing tapered tube beside the ball: a cone is sampled by area too.
  Material tube = model(MaterialModel::kDiffuse, Color{0.f});
  tube.emission = {0.5f, 1.f, 2.f};
  s.geometry.add(Cylinder{Vec3{2.2f, 0.f, -0.5f}, 0.3f, Vec3{2.f, 2.5f, -0.8f}, 0.1f},
                 s.add_object("tube", s.add_material(tube)));
  return s;
}

TEST(PathIntegrator, LightSamplingBsdfSamplingAndMisConverge) {
  const Scene s = strategy_scene();
  for (Vec3 target : {Vec3{0.f, 1.f, 0.f}, Vec3{2.f, 0.f, 1.f}}) {
    std::vector<Estimate> found;
    for (auto strategy :
         {PathIntegrator::Strategy::kMis, PathIntegrator::Strategy::kLightsOnly, PathIntegrator::Strategy::kBsdfOnly}) {
      const PathIntegrator path(s, strategy);
      found.push_back(estimate(s, path, Vec3{0.f, 2.f, 6.f}, target, 0.3f, 1 << 14));
    }
    for (std::size_t i = 1; i < found.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        const float sigma = std::sqrt(found[0].variance_of_mean[k] + found[i].variance_of_mean[k]);
        // 4.5 sigma: 6 comparisons per target pass by chance with probability above 0.9999.
        EXPECT_LT(std::fabs(found[i].mean[k] - found[0].mean[k]), 4.5f * sigma + 1e-6f)
            << "strategy " << i << " channel " << k << ": " << found[i].mean[k] << " vs " << found[0].mean[k];
      }
    }
    // MIS is never much noisier than the better of the two alone.
    EXPECT_LT(found[0].variance_of_mean.y, 1.5f * std::min(found[1].variance_of_mean.y, found[2].variance_of_mean.y));
  }
}

TEST(PathIntegrator, ImageIsTheSameForAnyThreadCount) {
  Scene s = make_cornell_scene();
  s.settings.integrator = "path";
  s.settings.width = 24;
  s.settings.height = 24;
  s.settings.spp = 4;
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", s.geometry);
  std::vector<Film> films;
  for (int threads : {1, 2}) {
    Film film(s.settings.width, s.settings.height);
    RenderOptions options;
    options.threads = threads;
    options.tile_size = 8;
    render(s, *accel, film, options);
    films.push_back(std::move(film));
  }
  ASSERT_EQ(films[0].pixels().size(), films[1].pixels().size());
  for (std::size_t i = 0; i < films[0].pixels().size(); ++i) {
    ASSERT_EQ(films[0].pixels()[i], films[1].pixels()[i]) << "pixel " << i;
  }
  // And the path integrator did light the box (not a black image).
  Color sum{0.f};
  for (const Color& c : films[0].pixels()) sum += c;
  EXPECT_GT(sum.y, 0.05f * static_cast<float>(films[0].pixels().size()));
}

TEST(PathIntegrator, ShowcaseHoldsEveryModelAndRendersUnderItsSky) {
  Scene s = make_builtin_scene("showcase");
  EXPECT_EQ(s.settings.integrator, "path");
  ASSERT_TRUE(s.environment);
  for (MaterialModel m :
       {MaterialModel::kDiffuse, MaterialModel::kPlastic, MaterialModel::kConductor, MaterialModel::kDielectric}) {
    EXPECT_TRUE(std::any_of(s.materials.begin(), s.materials.end(), [&](const Material& x) { return x.model == m; }))
        << static_cast<int>(m);
  }
  s.settings.width = 48;
  s.settings.height = 18;
  s.settings.spp = 4;
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", s.geometry);
  Film film(s.settings.width, s.settings.height);
  RenderOptions options;
  options.threads = 2;
  const RenderResult r = render(s, *accel, film, options);
  EXPECT_EQ(r.stats.nonfinite_samples, 0u);
  // The sky lights the ground: the bottom row is bright.
  Color bottom{0.f};
  for (int x = 0; x < s.settings.width; ++x) bottom += film.at(x, s.settings.height - 1);
  EXPECT_GT(bottom.y / static_cast<float>(s.settings.width), 0.2f);
}

TEST(PathIntegrator, UnknownIntegratorNamesTheValidOnes) {
  Scene s;
  s.settings.integrator = "photon";
  try {
    check_sampling_settings(s.settings);
    FAIL() << "accepted an unknown integrator";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("whitted, path"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raylab
