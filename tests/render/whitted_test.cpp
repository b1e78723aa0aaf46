// WhittedIntegrator on scenes whose answer is known in closed form: furnaces, mirrors, a glass
// slab, shadows and the Lambert/Phong terms of point and directional lights.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "raylab/accel/factory.h"
#include "raylab/render/optics.h"
#include "raylab/render/renderer.h"
#include "raylab/render/whitted.h"
#include "trace_one.h"

namespace raylab {
namespace {

constexpr float kDeg = std::numbers::pi_v<float> / 180.f;

using test::trace_one;
using test::Traced;

int kind(RayKind k) { return static_cast<int>(k); }

void expect_color_near(Color got, Color want, float tol) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

// Relative tolerance per channel (channels of `want` are non-zero).
void expect_color_rel(Color got, Color want, float rel) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], rel * std::fabs(want[k])) << "channel " << k;
}

Material emitter(Color e) {
  Material m;
  m.kd = 0.f;
  m.ks = 0.f;
  m.emission = e;
  return m;
}

// Renders `scene` at its own settings with one thread; returns the film and the stats.
std::pair<Film, RenderStats> render_scene(const Scene& scene) {
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  Film film(scene.settings.width, scene.settings.height);
  RenderOptions options;
  options.threads = 1;
  const RenderResult r = render(scene, *accel, film, options);
  return {std::move(film), r.stats};
}

// A small scene seen from inside a closed shape; the background is loud so a leak shows.
Scene furnace_scene() {
  Scene s;
  s.settings.width = 24;
  s.settings.height = 16;
  s.settings.spp = 4;
  s.settings.background = {9.f, 9.f, 9.f};
  s.camera.from = {0.1f, 0.2f, -0.3f};
  s.camera.at = {0.6f, -0.4f, -1.f};
  s.camera.vfov_degrees = 110.f;
  return s;
}

// With no lights and kd = ks = 0, a closed emitter shows exactly its emission in every direction.
TEST(WhittedFurnace, ClosedEmissiveSphereGivesEmissionEverywhere) {
  Scene s = furnace_scene();
  const Color e{0.25f, 0.5f, 1.75f};
  s.geometry.add(Sphere{{0.f, 0.f, 0.f}, 2.f}, s.add_object("shell", s.add_material(emitter(e))));
  const auto [film, stats] = render_scene(s);
  for (const Color& c : film.pixels()) expect_color_near(c, e, 1e-6f);
  const auto n = static_cast<std::uint64_t>(film.width() * film.height() * s.settings.spp);
  EXPECT_EQ(stats.rays[kind(RayKind::kPrimary)], n);
  EXPECT_EQ(stats.ray_hits[kind(RayKind::kPrimary)], n);  // no ray escapes the shell
  EXPECT_EQ(stats.total_rays(), n);                       // nothing reflective, no lights
}

// The same with a cube of six quads: shared edges must not let rays out.
TEST(WhittedFurnace, ClosedEmissiveBoxOfQuadsGivesEmissionEverywhere) {
  Scene s = furnace_scene();
  const Color e{0.3f, 0.2f, 0.1f};
  const std::uint32_t obj = s.add_object("box", s.add_material(emitter(e)));
  for (float side : {-1.f, 1.f}) {
    s.geometry.add(Quad{{side, -1.f, -1.f}, {0.f, 2.f, 0.f}, {0.f, 0.f, 2.f}}, obj);
    s.geometry.add(Quad{{-1.f, side, -1.f}, {2.f, 0.f, 0.f}, {0.f, 0.f, 2.f}}, obj);
    s.geometry.add(Quad{{-1.f, -1.f, side}, {2.f, 0.f, 0.f}, {0.f, 2.f, 0.f}}, obj);
  }
  const auto [film, stats] = render_scene(s);
  for (const Color& c : film.pixels()) expect_color_near(c, e, 1e-6f);
  EXPECT_EQ(stats.ray_hits[kind(RayKind::kPrimary)], stats.rays[kind(RayKind::kPrimary)]);
}

// Inside a closed mirror of reflectivity r that also emits E, every ray tree is a chain of
// max_depth hits each adding E, weighted r^k: E * (1 + r + ... + r^(D-1)).
TEST(WhittedFurnace, ClosedMirrorSphereSumsTheGeometricSeries) {
  const Color e{0.2f, 0.3f, 0.4f};
  const float r = 0.6f;
  for (int depth : {1, 2, 3, 5, 9}) {
    SCOPED_TRACE(depth);
    Scene s = furnace_scene();
    s.settings.width = 8;
    s.settings.height = 6;
    s.settings.spp = 1;
    s.settings.max_depth = depth;
    Material m = emitter(e);
    m.reflectivity = r;
    s.geometry.add(Sphere{{0.f, 0.f, 0.f}, 1.5f}, s.add_object("mirror shell", s.add_material(m)));
    const auto [film, stats] = render_scene(s);
    const Color want = e * ((1.f - std::pow(r, static_cast<float>(depth))) / (1.f - r));
    for (const Color& c : film.pixels()) expect_color_rel(c, want, 1e-4f);
    // One reflection ray per level below the eye ray, and every one of them hits the shell.
    const auto pixels = static_cast<std::uint64_t>(film.width() * film.height());
    EXPECT_EQ(stats.rays[kind(RayKind::kReflection)], pixels * (depth - 1));
    EXPECT_EQ(stats.ray_hits[kind(RayKind::kReflection)], pixels * (depth - 1));
  }
}

// A mirror floor at y = 0 and an emissive wall at x = 2: the ray from (-1, 1, 0) going down at
// 45 degrees hits the floor at the origin and is reflected into the wall at (2, 2, 0).
Scene mirror_scene(float reflectivity, bool with_wall) {
  Scene s;
  s.settings.max_depth = 5;
  s.settings.background = {0.1f, 0.2f, 0.3f};
  Material mirror;
  mirror.kd = 0.f;
  mirror.reflectivity = reflectivity;
  mirror.color = {0.f, 1.f, 0.f};  // must not tint the reflection
  s.geometry.add(Quad{{-5.f, 0.f, -5.f}, {0.f, 0.f, 10.f}, {10.f, 0.f, 0.f}},
                 s.add_object("mirror", s.add_material(mirror)));
  if (with_wall) {
    s.geometry.add(Quad{{2.f, 1.f, -1.f}, {0.f, 2.f, 0.f}, {0.f, 0.f, 2.f}},
                   s.add_object("wall", s.add_material(emitter({0.9f, 0.5f, 0.25f}))));
  }
  return s;
}

TEST(WhittedMirror, PerfectMirrorShowsTheEmitterItFaces) {
  const Traced t = trace_one(mirror_scene(1.f, true), {-1.f, 1.f, 0.f}, {1.f, -1.f, 0.f});
  expect_color_near(t.color, {0.9f, 0.5f, 0.25f}, 1e-6f);
  EXPECT_EQ(t.stats.rays[kind(RayKind::kReflection)], 1u);
  EXPECT_EQ(t.stats.ray_hits[kind(RayKind::kReflection)], 1u);
}

TEST(WhittedMirror, PartialMirrorScalesByReflectivity) {
  const Traced t = trace_one(mirror_scene(0.35f, true), {-1.f, 1.f, 0.f}, {1.f, -1.f, 0.f});
  expect_color_near(t.color, Color{0.9f, 0.5f, 0.25f} * 0.35f, 1e-6f);
}

TEST(WhittedMirror, MirrorFacingNothingShowsTheBackground) {
  const Traced t = trace_one(mirror_scene(0.8f, false), {-1.f, 1.f, 0.f}, {1.f, -1.f, 0.f});
  expect_color_near(t.color, Color{0.1f, 0.2f, 0.3f} * 0.8f, 1e-6f);
  EXPECT_EQ(t.stats.ray_hits[kind(RayKind::kReflection)], 0u);
}

// max_depth 1 means eye rays only: the mirror then reflects nothing.
TEST(WhittedMirror, DepthOneCastsNoReflection) {
  Scene s = mirror_scene(1.f, true);
  s.settings.max_depth = 1;
  const Traced t = trace_one(s, {-1.f, 1.f, 0.f}, {1.f, -1.f, 0.f});
  expect_color_near(t.color, {0.f, 0.f, 0.f}, 0.f);
  EXPECT_EQ(t.stats.total_rays(), 1u);
}

// Direction at angle `theta` from the downward normal, in the xy plane, travelling down.
Vec3 downward(float theta) { return {std::sin(theta), -std::cos(theta), 0.f}; }

TEST(WhittedRefraction, RefractObeysSnellsLaw) {
  const Vec3 n{0.f, 1.f, 0.f};
  for (float eta_t : {1.33f, 1.5f, 2.4f}) {
    for (float deg : {0.f, 10.f, 30.f, 45.f, 60.f, 85.f}) {
      SCOPED_TRACE(::testing::Message() << "eta_t " << eta_t << " angle " << deg);
      const Vec3 d = downward(deg * kDeg);
      Vec3 t;
      ASSERT_TRUE(refract(d, n, 1.f / eta_t, t));
      EXPECT_NEAR(length(t), 1.f, 1e-5f);
      EXPECT_LT(t.y, 0.f);                         // carries on into the medium
      EXPECT_NEAR(t.z, 0.f, 1e-7f);                // stays in the plane of incidence
      EXPECT_NEAR(t.x * eta_t, d.x * 1.f, 1e-5f);  // sin(theta_t) eta_t = sin(theta_i) eta_i
      // Leaving through a parallel face restores the original direction.
      Vec3 back;
      ASSERT_TRUE(refract(t, n, eta_t, back));
      expect_color_near(back, d, 1e-5f);
    }
  }
}

TEST(WhittedRefraction, TotalInternalReflectionBeyondTheCriticalAngle) {
  const Vec3 n{0.f, 1.f, 0.f};
  const float ior = 1.5f;
  const float critical = std::asin(1.f / ior) / kDeg;  // 41.81 degrees
  Vec3 t;
  for (float deg : {0.f, 20.f, 41.f}) {
    EXPECT_TRUE(refract(downward(deg * kDeg), n, ior, t)) << deg;
    EXPECT_LT(fresnel_dielectric(std::cos(deg * kDeg), ior, 1.f), 1.f) << deg;
  }
  for (float deg : {critical + 0.1f, 50.f, 70.f, 89.f}) {
    EXPECT_FALSE(refract(downward(deg * kDeg), n, ior, t)) << deg;
    EXPECT_EQ(fresnel_dielectric(std::cos(deg * kDeg), ior, 1.f), 1.f) << deg;
  }
}

TEST(WhittedRefraction, FresnelAtNormalIncidenceIsTheSchlickR0) {
  for (float n : {1.33f, 1.5f, 2.4f}) {
    const float r0 = ((n - 1.f) / (n + 1.f)) * ((n - 1.f) / (n + 1.f));
    EXPECT_NEAR(fresnel_dielectric(1.f, 1.f, n), r0, 1e-6f);
    EXPECT_NEAR(fresnel_dielectric(1.f, n, 1.f), r0, 1e-6f);  // same from inside
  }
  EXPECT_NEAR(fresnel_dielectric(0.f, 1.f, 1.5f), 1.f, 1e-6f);  // grazing
}

// A glass slab between y = -1 and y = 0 (outward normals), and a small emissive target below.
Scene slab_scene(bool fresnel, Vec3 target_center, float target_half) {
  Scene s;
  s.settings.max_depth = 5;
  Material glass;
  glass.kd = 0.f;
  glass.transmittance = 1.f;
  glass.ior = 1.5f;
  glass.fresnel = fresnel;
  const std::uint32_t g = s.add_object("slab", s.add_material(glass));
  s.geometry.add(Quad{{-10.f, 0.f, -10.f}, {0.f, 0.f, 20.f}, {20.f, 0.f, 0.f}}, g);   // normal +y
  s.geometry.add(Quad{{-10.f, -1.f, -10.f}, {20.f, 0.f, 0.f}, {0.f, 0.f, 20.f}}, g);  // normal -y
  const Vec3 c = target_center - Vec3{target_half, 0.f, target_half};
  s.geometry.add(Quad{c, {2.f * target_half, 0.f, 0.f}, {0.f, 0.f, 2.f * target_half}},
                 s.add_object("target", s.add_material(emitter({0.5f, 1.f, 2.f}))));
  return s;
}

// At 30 degrees the ray bends to sin(theta_t) = 1/3 inside, is displaced by tan(theta_t), leaves
// parallel to where it came from and lands on a 2 cm target where Snell's law says it must.
TEST(WhittedRefraction, RayThroughSlabExitsParallelAndDisplaced) {
  const float theta = 30.f * kDeg;
  const Vec3 d = downward(theta);
  const float sin_t = std::sin(theta) / 1.5f;
  const float exit_x = sin_t / std::sqrt(1.f - sin_t * sin_t);  // slab thickness 1
  const float land_x = exit_x + 2.f * std::tan(theta);          // target 2 below the slab
  const Vec3 origin = d * -2.f;                                 // enters at the origin

  const Traced hit = trace_one(slab_scene(false, {land_x, -3.f, 0.f}, 0.01f), origin, d);
  expect_color_near(hit.color, {0.5f, 1.f, 2.f}, 1e-6f);
  // In, out onto the target, and two more that leave the slab at depths 4 and 5 and miss the
  // target; every face hit also spawns a reflection ray, which Fresnel-off gives no weight
  // (whitted_transmission_test.cpp counts the whole tree).
  EXPECT_EQ(hit.stats.rays[kind(RayKind::kRefraction)], 4u);
  EXPECT_EQ(hit.stats.ray_hits[kind(RayKind::kRefraction)], 2u);
  EXPECT_EQ(hit.stats.rays[kind(RayKind::kReflection)], 4u);

  // Where the unbent ray would land, nothing arrives.
  const Traced straight = trace_one(slab_scene(false, {3.f * std::tan(theta), -3.f, 0.f}, 0.01f), origin, d);
  expect_color_near(straight.color, {0.f, 0.f, 0.f}, 0.f);
}

// With Fresnel at normal incidence each face passes 1 - R0 (R0 = 0.04 for n = 1.5). At depth 3
// the internally reflected ray ends on the dark slab face, so exactly (1 - R0)^2 gets through.
TEST(WhittedRefraction, FresnelWeightsTheTransmissionAtNormalIncidence) {
  Scene s = slab_scene(true, {0.f, -3.f, 0.f}, 1.f);
  s.settings.max_depth = 3;
  const Traced t = trace_one(s, {0.f, 2.f, 0.f}, {0.f, -1.f, 0.f});
  const float pass = 1.f - 0.04f;
  expect_color_rel(t.color, Color{0.5f, 1.f, 2.f} * (pass * pass), 1e-5f);
  EXPECT_EQ(t.stats.rays[kind(RayKind::kReflection)], 2u);  // off the top, and inside off the bottom
}

// A matte plane at y = 0 and the point P = (1, 0, 0) seen from (1, 1, 2).
constexpr Vec3 kP{1.f, 0.f, 0.f};
constexpr Vec3 kEye{1.f, 1.f, 2.f};
constexpr Color kAlbedo{0.5f, 0.6f, 0.7f};
constexpr float kKd = 0.8f;

Scene plane_scene() {
  Scene s;
  Material matte;
  matte.color = kAlbedo;
  matte.kd = kKd;
  s.geometry.add(Quad{{-10.f, 0.f, -10.f}, {0.f, 0.f, 20.f}, {20.f, 0.f, 0.f}},
                 s.add_object("plane", s.add_material(matte)));
  return s;
}

Light point_light(Vec3 position, Color intensity, bool falloff = false) {
  Light l;
  l.kind = Light::Kind::kPoint;
  l.position = position;
  l.intensity = intensity;
  l.falloff = falloff;
  return l;
}

class WhittedShadow : public ::testing::Test {
 protected:
  // Light at (0, 4, 0); a blocker sphere at the midpoint of P and the light, shifted by `offset`.
  Scene scene(Vec3 offset) {
    Scene s = plane_scene();
    s.lights.push_back(point_light(m_light, m_intensity));
    s.geometry.add(Sphere{(kP + m_light) * 0.5f + offset, 0.3f}, s.add_object("blocker", s.add_material({})));
    return s;
  }
  const Vec3 m_light{0.f, 4.f, 0.f};
  const Color m_intensity{2.f, 1.5f, 1.f};
};

TEST_F(WhittedShadow, BlockedPointGetsOnlyAmbient) {
  const Traced dark = trace_one(scene({}), kEye, kP - kEye);
  expect_color_near(dark.color, {0.f, 0.f, 0.f}, 0.f);
  EXPECT_EQ(dark.stats.rays[kind(RayKind::kShadow)], 1u);
  EXPECT_EQ(dark.stats.ray_hits[kind(RayKind::kShadow)], 1u);

  Scene with_ambient = scene({});
  with_ambient.settings.ambient = {0.1f, 0.2f, 0.3f};
  const Traced amb = trace_one(with_ambient, kEye, kP - kEye);
  expect_color_near(amb.color, Color{0.1f, 0.2f, 0.3f} * kAlbedo * kKd, 1e-7f);
}

TEST_F(WhittedShadow, BlockerOffTheLineLeavesTheLambertValue) {
  // 0.6 sideways of the segment, which is farther than the radius 0.3.
  const Traced lit = trace_one(scene({0.f, 0.f, 0.6f}), kEye, kP - kEye);
  const float cos_theta = 4.f / std::sqrt(17.f);  // P -> light is (-1, 4, 0)
  expect_color_rel(lit.color, kAlbedo * m_intensity * (kKd * cos_theta), 1e-5f);
  EXPECT_EQ(lit.stats.rays[kind(RayKind::kShadow)], 1u);
  EXPECT_EQ(lit.stats.ray_hits[kind(RayKind::kShadow)], 0u);
}

// Seen from below, the plane faces away from the light: no shadow ray is cast at all.
TEST_F(WhittedShadow, SurfaceFacingAwayCastsNoShadowRay) {
  const Traced back = trace_one(scene({0.f, 0.f, 0.6f}), {1.f, -1.f, 2.f}, kP - Vec3{1.f, -1.f, 2.f});
  EXPECT_EQ(back.stats.ray_hits[kind(RayKind::kPrimary)], 1u);
  EXPECT_EQ(back.stats.rays[kind(RayKind::kShadow)], 0u);
  expect_color_near(back.color, {0.f, 0.f, 0.f}, 0.f);
}

TEST(WhittedLights, DirectionalLightGivesLambert) {
  Scene s = plane_scene();
  Light sun;
  sun.kind = Light::Kind::kDirectional;
  sun.direction = {1.f, -2.f, 0.5f};  // not unit: the integrator normalises it
  sun.intensity = {0.9f, 0.8f, 0.7f};
  s.lights.push_back(sun);
  const Traced t = trace_one(s, kEye, kP - kEye);
  const float cos_theta = 2.f / length(sun.direction);
  expect_color_rel(t.color, kAlbedo * sun.intensity * (kKd * cos_theta), 1e-5f);
  EXPECT_EQ(t.stats.rays[kind(RayKind::kShadow)], 1u);

  // Light travelling upwards reaches only the underside.
  s.lights[0].direction = {1.f, 2.f, 0.5f};
  expect_color_near(trace_one(s, kEye, kP - kEye).color, {0.f, 0.f, 0.f}, 0.f);
}

TEST(WhittedLights, PointLightFalloffIsInverseSquare) {
  const Vec3 light{0.f, 3.f, 0.f};  // P -> light is (-1, 3, 0): d^2 = 10, cos = 3 / sqrt(10)
  const Color intensity{5.f, 4.f, 3.f};
  const float cos_theta = 3.f / std::sqrt(10.f);
  Scene s = plane_scene();
  s.lights.push_back(point_light(light, intensity, true));
  const Traced near = trace_one(s, kEye, kP - kEye);
  expect_color_rel(near.color, kAlbedo * intensity * (kKd * cos_theta / 10.f), 1e-5f);
  s.lights[0].falloff = false;  // NFF lights: no falloff at all
  expect_color_rel(trace_one(s, kEye, kP - kEye).color, kAlbedo * intensity * (kKd * cos_theta), 1e-5f);
}

// Viewed exactly along the mirror direction of the light, the Phong lobe is at its peak (ks).
TEST(WhittedLights, PhongHighlightPeaksInTheMirrorDirection) {
  Scene s = plane_scene();
  s.materials[0].ks = 0.5f;
  s.materials[0].shininess = 10.f;
  const Color intensity{1.f, 2.f, 3.f};
  s.lights.push_back(point_light({-1.f, 1.f, 0.f}, intensity));
  const Traced t = trace_one(s, {1.f, 1.f, 0.f}, {-1.f, -1.f, 0.f});  // hits the origin
  const float cos_theta = std::sqrt(0.5f);
  expect_color_rel(t.color, (kAlbedo * (kKd * cos_theta) + Color(0.5f)) * intensity, 1e-5f);
}

}  // namespace
}  // namespace raylab
