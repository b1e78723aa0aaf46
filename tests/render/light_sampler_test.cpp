// The path integrator's light sampling against its own density, by a chi-square test as for the
// BSDFs: from a point, the directions LightSampler::sample draws toward emissive triangles,
// quads, disks, spheres, cylinders and cones (one at a time, and two lights chosen by power) must follow the
// density emitter_pdf gives the point each direction reaches.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "../../src/render/light/light_sampler.h"
#include "../../src/render/light/shape_sampling.h"
#include "raylab/accel/factory.h"
#include "raylab/accel/two_level.h"
#include "raylab/core/rng.h"
#include "raylab/geometry/shading.h"
#include "sphere_chi2.h"

namespace raylab {
namespace {

using detail::LightSampler;

// A scene whose only emitters are what `add` puts in it (material emission 1), seen from the
// origin.
template <class Add>
Scene emitters(Add add) {
  Scene s;
  Material lamp;
  lamp.emission = {1.f, 1.f, 1.f};
  const std::uint32_t object = s.add_object("lamp", s.add_material(lamp));
  add(s.geometry, object);
  return s;
}

// Quadrature parts per cell side: a light's outline crosses cells, where the density jumps.
constexpr int kSplit = 16;

// Pearson's test of `samples` light samples of `scene` from the origin against the density
// that `density_of`'s lights give the direction each reaches; p-value. (`density_of` is `scene`
// itself but where a test checks that the test can fail.)
double light_sampling_p_value(const Scene& scene, const Scene& density_of, int samples, std::uint64_t seed) {
  const LightSampler lights(scene), density(density_of);
  SceneAccelOptions brute;
  brute.top = "brute";
  const std::unique_ptr<Accelerator> accel =
      make_scene_accelerator(density_of.geometry, density_of.prototypes, density_of.instances, brute);
  const Vec3 from{0.f, 0.f, 0.f};
  const test::SphereGrid grid{16, 32};
  Pcg32 rng(seed);
  const auto observed = test::observed_counts(grid, samples, [&]() -> std::optional<Vec3> {
    const float u_choice = rng.next_float();
    const Sample2 u{rng.next_float(), rng.next_float()};
    const std::optional<detail::LightSample> ls = lights.sample(from, u_choice, u);
    if (!ls) return std::nullopt;
    return ls->wi;
  });
  const auto expected = test::expected_counts(
      grid, samples,
      [&](Vec3 dir) {
        Ray ray;
        ray.origin = from;
        ray.direction = dir;
        Hit hit;
        if (!accel->intersect(ray, hit)) return 0.f;
        const SurfaceInteraction si = surface_at(density_of, ray, hit);
        if (!si.front_face) return 0.f;  // emitters light their front side only
        return density.emitter_pdf(from, hit.prim_id, si.position, si.geometric_normal);
      },
      kSplit);
  const test::Chi2Result r = test::pearson(observed, expected);
  EXPECT_TRUE(r.failure.empty()) << r.failure;
  std::printf("  chi2 light sampling: statistic %9.1f dof %4d p %.4f\n", r.statistic, r.dof, r.p_value);
  return r.p_value;
}

// Sidak's level for the cases of this file, so that all pass by chance with probability 0.99.
constexpr int kCases = 9;
const double kLevel = 1.0 - std::pow(0.99, 1.0 / kCases);

TEST(LightSamplerChi2, TriangleQuadDiskAndSphereEmitters) {
  // Each faces the origin (a triangle's front by its winding); big and near, so that the
  // directions they cover span many cells.
  const Scene triangle = emitters([](Geometry& g, std::uint32_t o) {
    g.add(Triangle{{-1.f, -1.f, 0.5f}, {0.f, 1.f, 0.5f}, {1.f, -1.f, 0.5f}}, o);
  });
  const Scene quad = emitters([](Geometry& g, std::uint32_t o) {
    g.add(Quad{{-1.f, -0.5f, 0.6f}, {0.f, 2.f, 0.f}, {1.5f, 0.f, 0.2f}}, o);
  });
  const Scene disk = emitters([](Geometry& g, std::uint32_t o) {
    g.add(Disk{{0.3f, 0.f, 0.7f}, normalize(Vec3{0.2f, 0.f, -1.f}), 1.f}, o);
  });
  // A sphere's far side faces away: those samples give no light (the last cell).
  const Scene sphere = emitters([](Geometry& g, std::uint32_t o) { g.add(Sphere{{0.f, 0.4f, 1.5f}, 1.f}, o); });
  // A cone frustum beside the origin, its axis tilted: its outward side faces it. (A cylinder's
  // uniformity is tested in the area domain below: its long straight outlines, where the
  // density of directions grows without bound, defeat this quadrature.)
  const Scene cone = emitters([](Geometry& g, std::uint32_t o) {
    g.add(Cylinder{{-0.3f, -1.2f, 1.2f}, 1.f, {0.2f, 1.f, 0.9f}, 0.15f}, o);
  });
  int seed = 1;
  for (const Scene* s : {&triangle, &quad, &disk, &sphere, &cone}) {
    const double p = light_sampling_p_value(*s, *s, 200000, static_cast<std::uint64_t>(seed++));
    EXPECT_GT(p, kLevel) << "case " << seed - 1;
  }
}

TEST(LightSamplerChi2, TwoLightsChosenByPower) {
  // A bright small triangle and a dim large quad on either side: the choice by power and each
  // light's own density together must give the mixture's density.
  Scene s;
  Material bright, dim;
  bright.emission = {8.f, 8.f, 8.f};
  dim.emission = {0.5f, 0.5f, 0.5f};
  s.geometry.add(Triangle{{-0.5f, -0.5f, 0.8f}, {0.f, 0.5f, 0.8f}, {0.5f, -0.5f, 0.8f}},
                 s.add_object("bright", s.add_material(bright)));
  s.geometry.add(Quad{{-1.f, -1.f, -0.7f}, {2.f, 0.f, 0.f}, {0.f, 2.f, 0.f}}, s.add_object("dim", s.add_material(dim)));
  EXPECT_GT(light_sampling_p_value(s, s, 200000, 99), kLevel);
}

TEST(LightSamplerChi2, InstancedMeshTrianglesAreLights) {
  // An emissive two-triangle mesh placed twice: turned, stretched and mirrored (a negative scale
  // flips the winding, not the side that emits), and moved. Each world triangle is a light, and
  // the density of a direction is that of the instanced triangle a ray finds there.
  Scene s;
  Material lamp;
  lamp.emission = {1.f, 1.f, 1.f};
  const std::uint32_t object = s.add_object("lamp", s.add_material(lamp));
  Geometry mesh;
  mesh.add(Triangle{{-0.5f, -0.5f, 0.f}, {0.5f, -0.5f, 0.f}, {0.f, 0.5f, 0.f}}, 0);
  mesh.add(Triangle{{0.5f, -0.5f, 0.f}, {0.6f, 0.6f, 0.f}, {0.f, 0.5f, 0.f}}, 0);
  s.prototypes.push_back(std::move(mesh));
  // Both face the origin: the first turned half round; the mirrored one emits towards -z (its
  // normal's image), while its vertices, in the plane z = 0 of the mesh, keep their winding.
  s.add_instance(0,
                 Transform::translate(0.2, 0.1, 1.0) * Transform::rotate(20.0, {1.f, 0.f, 0.f}) *
                     Transform::rotate(180.0, {0.f, 1.f, 0.f}),
                 object);
  s.add_instance(0, Transform::translate(-1.6, 0.2, 1.2) * Transform::scale(1.5, 0.8, -1.0), object);
  EXPECT_GT(light_sampling_p_value(s, s, 200000, 17), kLevel);
}

TEST(LightSamplerChi2, RejectsADensityThatIsSlightlyWrong) {
  // The test can fail: a quad whose density is taken for 10% more area than it has.
  const Scene quad = emitters([](Geometry& g, std::uint32_t o) {
    g.add(Quad{{-1.f, -0.5f, 0.6f}, {0.f, 2.f, 0.f}, {1.5f, 0.f, 0.2f}}, o);
  });
  const Scene wider = emitters([](Geometry& g, std::uint32_t o) {
    g.add(Quad{{-1.f, -0.5f, 0.6f}, {0.f, 2.2f, 0.f}, {1.5f, 0.f, 0.2f}}, o);
  });
  EXPECT_LT(light_sampling_p_value(quad, wider, 200000, 5), 1e-6);
}

// Points on a cylinder's and a cone's lateral surface against uniform area density, in the
// surface's own coordinates: the height fraction s (whose share of the area between 0 and s is
// (2 r0 s + (r1 - r0) s^2) / (r0 + r1)) and the angle about the axis (uniform). Each point lies
// on the surface with the outward normal there, and the area is that of a fine tessellation.
TEST(LightSamplerChi2, CylinderAndConePointsAreUniformInArea) {
  const Cylinder shapes[] = {{{0.8f, -1.f, 0.6f}, 0.5f, {0.6f, 1.2f, 1.f}, 0.5f},
                             {{-0.3f, -1.2f, 1.2f}, 1.f, {0.2f, 1.f, 0.9f}, 0.15f}};
  constexpr int kHeights = 20, kAngles = 16, kSamples = 200000;
  for (const Cylinder& c : shapes) {
    const Vec3 axis = c.apex - c.base;
    const float h = length(axis);
    const Vec3 w = axis / h;
    Vec3 t, b;
    orthonormal_basis(w, t, b);
    const double r0 = c.base_radius, r1 = c.apex_radius;
    const auto share = [&](double s) { return (2. * r0 * s + (r1 - r0) * s * s) / (r0 + r1); };
    std::vector<double> observed(kHeights * kAngles, 0.), expected(kHeights * kAngles, 0.);
    for (int i = 0; i < kHeights; ++i) {
      const double cell = (share((i + 1.) / kHeights) - share(double(i) / kHeights)) / kAngles;
      for (int j = 0; j < kAngles; ++j) expected[static_cast<std::size_t>(i * kAngles + j)] = cell * kSamples;
    }
    Pcg32 rng(11);
    for (int n = 0; n < kSamples; ++n) {
      const detail::SurfacePoint p = detail::sample_cylinder(c, {rng.next_float(), rng.next_float()});
      const Vec3 rel = p.position - c.base;
      const float s = dot(rel, w) / h;
      const Vec3 radial = rel - w * (s * h);
      ASSERT_NEAR(length(radial), c.base_radius + (c.apex_radius - c.base_radius) * s, 1e-5f);
      ASSERT_NEAR(dot(p.normal, cylinder_normal(c, p.position)), 1.f, 1e-5f);
      const double angle = std::atan2(dot(radial, b), dot(radial, t)) + std::numbers::pi;
      const int i = std::clamp(static_cast<int>(s * kHeights), 0, kHeights - 1);
      const int j = std::clamp(static_cast<int>(angle / (2. * std::numbers::pi) * kAngles), 0, kAngles - 1);
      ++observed[static_cast<std::size_t>(i * kAngles + j)];
    }
    const test::Chi2Result r = test::pearson(observed, expected);
    EXPECT_TRUE(r.failure.empty()) << r.failure;
    std::printf("  chi2 cylinder area: statistic %9.1f dof %4d p %.4f\n", r.statistic, r.dof, r.p_value);
    EXPECT_GT(r.p_value, kLevel);
    // The area against 4096 x 64 flat quads (trapezoids) between rings of the surface.
    double area = 0.;
    constexpr int kRings = 64, kAround = 4096;
    for (int i = 0; i < kRings; ++i) {
      const double ra = r0 + (r1 - r0) * i / kRings, rb = r0 + (r1 - r0) * (i + 1.) / kRings;
      const double chord_a = 2. * ra * std::sin(std::numbers::pi / kAround);
      const double chord_b = 2. * rb * std::sin(std::numbers::pi / kAround);
      const double dh = double(h) / kRings;
      const double slant =
          std::sqrt(dh * dh + (rb - ra) * (rb - ra) * std::pow(std::cos(std::numbers::pi / kAround), 2));
      area += kAround * 0.5 * (chord_a + chord_b) * slant;
    }
    EXPECT_NEAR(detail::cylinder_area(c), area, 1e-5 * area);
  }
}

// An emission map: a light sample's radiance is the map at the point sampled, the same as a ray
// that hits that point sees (emitted_radiance at its surface coordinates), for triangles
// with texture coordinates, quads, disks, spheres and cones. A 2 x 2 map of distinct texels with
// bilinear blending makes any mix-up of the two coordinates show.
TEST(LightSamplerEmissionMap, SampledRadianceIsWhatARayToThePointSees) {
  const auto map = std::make_shared<const TextureImage>(
      2, 2, std::vector<Color>{{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}, {1.f, 1.f, 1.f}});
  Scene s;
  Material lamp;
  lamp.emission = {2.f, 2.f, 2.f};
  lamp.emission_strength = 1.5f;
  lamp.maps.emission = map;
  const std::uint32_t object = s.add_object("lamp", s.add_material(lamp));
  const std::array<Vec2, 3> uvs{Vec2{0.1f, 0.1f}, Vec2{0.9f, 0.3f}, Vec2{0.3f, 0.8f}};
  s.geometry.add(Triangle{{-1.f, -1.f, 2.f}, {0.f, 1.f, 2.f}, {1.f, -1.f, 2.f}}, nullptr, &uvs, object);
  s.geometry.add(Quad{{-3.f, -1.f, 1.f}, {0.f, 2.f, 0.f}, {1.f, 0.f, 0.3f}}, object);
  s.geometry.add(Disk{{2.5f, 0.f, 1.5f}, normalize(Vec3{-0.3f, 0.f, -1.f}), 0.8f}, object);
  s.geometry.add(Sphere{{0.f, 3.f, 2.f}, 0.7f}, object);
  s.geometry.add(Cylinder{{-1.5f, -3.5f, 3.f}, 0.8f, {1.5f, -3.5f, 3.f}, 0.3f}, object);
  const LightSampler lights(s);
  const std::unique_ptr<Accelerator> accel = make_accelerator("brute", s.geometry);
  const Vec3 from{0.f, 0.f, -1.f};
  Pcg32 rng(3);
  int checked = 0;
  float least = 1e9f, most = 0.f;
  for (int i = 0; i < 4000; ++i) {
    const float u_choice = rng.next_float();
    const Sample2 u{rng.next_float(), rng.next_float()};
    const std::optional<detail::LightSample> ls = lights.sample(from, u_choice, u);
    if (!ls) continue;
    Ray ray;
    ray.origin = from;
    ray.direction = ls->wi;
    Hit hit;
    ASSERT_TRUE(accel->intersect(ray, hit));
    ASSERT_NEAR(hit.t, ls->distance, 1e-3f * ls->distance);  // nothing stands between
    const SurfaceInteraction si = surface_at(s, ray, hit);
    const Color seen = emitted_radiance(s.material_of(hit.prim_id), si.u, si.v);
    ASSERT_NEAR(ls->li.x, seen.x, 2e-3f) << "sample " << i << " prim " << hit.prim_id;
    ASSERT_NEAR(ls->li.y, seen.y, 2e-3f) << "sample " << i << " prim " << hit.prim_id;
    ASSERT_NEAR(ls->li.z, seen.z, 2e-3f) << "sample " << i << " prim " << hit.prim_id;
    least = std::min(least, ls->li.x + ls->li.y + ls->li.z);
    most = std::max(most, ls->li.x + ls->li.y + ls->li.z);
    ++checked;
  }
  EXPECT_GT(checked, 2000);
  // The map varies the radiance: from 3 (one channel of 2 x 1.5) to 9 (white).
  EXPECT_LT(least, 4.f);
  EXPECT_GT(most, 7.f);
}

}  // namespace
}  // namespace raylab
