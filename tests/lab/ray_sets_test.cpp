// The ray sets of `raylab compare`: primary rays through pixel centres, shadow rays that end at
// the light, cosine-weighted diffuse rays on the viewer's side, all independent of threads.

#include "raylab/lab/ray_sets.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <memory>

#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/camera.h"

namespace raylab {
namespace {

Scene small_scene() { return load_scene("spd:balls?size=2"); }

bool same_bytes(const std::vector<Ray>& a, const std::vector<Ray>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Ray)) == 0;
}

// The small scene's ray sets made with brute force as the reference, which also finds the
// primary hit behind a ray again.
struct BruteRaySets {
  explicit BruteRaySets(const RaySetOptions& options)
      : scene(small_scene()),
        brute(make_accelerator("brute", scene.geometry)),
        sets(make_ray_sets(scene, *brute, options)) {}

  // The primary hit behind ray `i` of `kind`, found again with brute force.
  SurfaceInteraction primary_surface(BenchRayKind kind, std::size_t i) const {
    Ray ray = sets[BenchRayKind::kPrimary].rays[sets[kind].pixel[i]];
    Hit hit;
    EXPECT_TRUE(brute->intersect(ray, hit));
    return surface_at(scene, ray, hit);
  }

  Scene scene;
  std::unique_ptr<Accelerator> brute;
  RaySets sets;
};

TEST(RaySets, PrimaryRaysPassThroughPixelCentres) {
  Scene scene = small_scene();
  const int w = 33, h = 21;
  const std::vector<Ray> rays = primary_rays(scene, w, h);
  ASSERT_EQ(rays.size(), std::size_t(w) * h);
  const Camera camera(scene.camera, w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Ray expected = camera.generate(x + 0.5f, y + 0.5f);
      const Ray& r = rays[std::size_t(y) * w + x];
      ASSERT_EQ(r.origin, expected.origin) << x << "," << y;
      ASSERT_EQ(r.direction, expected.direction) << x << "," << y;
    }
  }
  // With an odd size the middle pixel's centre is the image centre: the ray looks straight at
  // the camera's target.
  const Vec3 forward = normalize(scene.camera.at - scene.camera.from);
  const Ray& centre = rays[std::size_t(h / 2) * w + w / 2];
  EXPECT_NEAR(dot(normalize(centre.direction), forward), 1.0, 1e-6);
  // Rows go downward: the top row looks further "up" than the bottom row.
  EXPECT_GT(dot(rays.front().direction, scene.camera.up), dot(rays.back().direction, scene.camera.up));
  EXPECT_THROW(primary_rays(scene, 0, 5), UsageError);
}

TEST(RaySets, SameRaysWhateverTheThreadsAndTheReference) {
  const Scene scene = small_scene();
  const auto bvh = make_accelerator("bvh", scene.geometry);
  const auto brute = make_accelerator("brute", scene.geometry);
  RaySetOptions o{48, 40, 7};
  const RaySets a = make_ray_sets(scene, *bvh, o);
  RaySets b;
  tbb::task_arena one(1);
  one.execute([&] { b = make_ray_sets(scene, *brute, o); });
  for (int k = 0; k < kBenchRayKinds; ++k) {
    SCOPED_TRACE(k);
    EXPECT_TRUE(same_bytes(a.sets[k].rays, b.sets[k].rays));
    EXPECT_EQ(a.sets[k].pixel, b.sets[k].pixel);
  }
  EXPECT_GT(a[BenchRayKind::kShadow].rays.size(), 0u);
  EXPECT_GT(a[BenchRayKind::kDiffuse].rays.size(), 0u);
  // Another seed moves the bounces but not the primary rays.
  o.seed = 8;
  const RaySets c = make_ray_sets(scene, *bvh, o);
  EXPECT_TRUE(same_bytes(a[BenchRayKind::kPrimary].rays, c[BenchRayKind::kPrimary].rays));
  EXPECT_FALSE(same_bytes(a[BenchRayKind::kDiffuse].rays, c[BenchRayKind::kDiffuse].rays));
}

TEST(RaySets, ShadowRaysEndJustShortOfAPointLight) {
  const BruteRaySets traced({40, 30, 0});
  const RaySet& shadow = traced.sets[BenchRayKind::kShadow];
  ASSERT_GT(shadow.rays.size(), 100u);
  const Vec3 light = traced.scene.lights.front().position;
  for (std::size_t i = 0; i < shadow.rays.size(); ++i) {
    const Ray& r = shadow.rays[i];
    const Vec3 end = r.at(r.tmax);
    const float to_light = length(light - r.origin);
    // tmax is 0.1% short of the light; the ray starts at the primary hit, just off the surface.
    EXPECT_NEAR(length(light - end), to_light * 1e-3f, 1e-3f * to_light + 1e-4f) << i;
    EXPECT_NEAR(dot(normalize(light - r.origin), r.direction), 1.f, 1e-5f) << i;
    const SurfaceInteraction si = traced.primary_surface(BenchRayKind::kShadow, i);
    EXPECT_LT(length(r.origin - si.position), 1e-3f) << i;
    EXPECT_GT(dot(si.geometric_normal, r.direction), 0.f) << i;
  }
}

TEST(RaySets, ShadowRaysReachAreaLightsAndFollowDirectionalOnes) {
  Scene scene = small_scene();
  const auto bvh = make_accelerator("bvh", scene.geometry);
  Light quad;
  quad.kind = Light::Kind::kQuad;
  quad.position = {-1.f, -1.f, 6.f};
  quad.edge_u = {2.f, 0.f, 0.f};
  quad.edge_v = {0.f, 2.f, 0.f};
  scene.lights = {quad};
  RaySets sets = make_ray_sets(scene, *bvh, {32, 24, 0});
  ASSERT_FALSE(sets[BenchRayKind::kShadow].rays.empty());
  for (const Ray& r : sets[BenchRayKind::kShadow].rays) {
    const Vec3 end = r.at(r.tmax / (1.f - 1e-3f));  // the light point itself
    EXPECT_NEAR(end.z, 6.f, 1e-3f);
    EXPECT_GE(end.x, -1.001f);
    EXPECT_LE(end.x, 1.001f);
    EXPECT_GE(end.y, -1.001f);
    EXPECT_LE(end.y, 1.001f);
  }
  Light sphere;
  sphere.kind = Light::Kind::kSphere;
  sphere.position = {0.f, 0.f, 6.f};
  sphere.radius = 0.5f;
  scene.lights = {sphere};
  sets = make_ray_sets(scene, *bvh, {32, 24, 0});
  ASSERT_FALSE(sets[BenchRayKind::kShadow].rays.empty());
  for (const Ray& r : sets[BenchRayKind::kShadow].rays) {
    const Vec3 end = r.at(r.tmax / (1.f - 1e-3f));
    EXPECT_NEAR(length(end - sphere.position), 0.5f, 1e-3f);
    // On the half of the light that faces the shading point.
    EXPECT_GE(dot(end - sphere.position, r.origin - sphere.position), -1e-3f);
  }
  Light sun;
  sun.kind = Light::Kind::kDirectional;
  sun.direction = {0.f, 0.f, -1.f};
  scene.lights = {sun};
  sets = make_ray_sets(scene, *bvh, {32, 24, 0});
  ASSERT_FALSE(sets[BenchRayKind::kShadow].rays.empty());
  for (const Ray& r : sets[BenchRayKind::kShadow].rays) {
    EXPECT_EQ(r.direction, (Vec3{0.f, 0.f, 1.f}));
    EXPECT_TRUE(std::isinf(r.tmax));
  }
  scene.lights.clear();
  EXPECT_TRUE(make_ray_sets(scene, *bvh, {8, 8, 0})[BenchRayKind::kShadow].rays.empty());
}

TEST(RaySets, DiffuseRaysAreCosineWeightedOnTheViewersSide) {
  const BruteRaySets traced({96, 72, 3});
  const RaySet& diffuse = traced.sets[BenchRayKind::kDiffuse];
  ASSERT_GT(diffuse.rays.size(), 3000u);
  double sum_cos = 0.0;
  for (std::size_t i = 0; i < diffuse.rays.size(); ++i) {
    const Ray& r = diffuse.rays[i];
    EXPECT_NEAR(length(r.direction), 1.f, 1e-5f);
    const SurfaceInteraction si = traced.primary_surface(BenchRayKind::kDiffuse, i);
    const float c = dot(si.geometric_normal, r.direction);
    EXPECT_GT(c, 0.f) << i;
    sum_cos += c;
  }
  // The mean cosine of a cosine-weighted hemisphere is 2/3 (uniform would give 1/2); with this
  // many samples the standard error is about 0.004.
  EXPECT_NEAR(sum_cos / static_cast<double>(diffuse.rays.size()), 2.0 / 3.0, 0.02);
}

}  // namespace
}  // namespace raylab
