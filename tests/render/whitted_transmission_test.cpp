// Transmitters by the SPD testing procedure's rules 8 and 9: every hit on a transmitting surface
// spawns a reflection ray, and a refraction ray unless total internal reflection occurs; the
// rays spawned depend on the geometry alone, never on the weights; and the weights conserve
// energy (reflection + refraction = reflectivity + transmittance).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "raylab/render/whitted.h"
#include "trace_one.h"

namespace raylab {
namespace {

constexpr float kDeg = std::numbers::pi_v<float> / 180.f;

using test::trace_one;
using test::Traced;

// Radiance 1 in every channel, to within the weight left at the depth limit and float rounding.
void expect_near(Color c) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], 1.f, 1e-4f) << "channel " << k;
}

std::uint64_t cast(const Traced& t, RayKind k) { return t.stats.rays[static_cast<int>(k)]; }
std::uint64_t hits(const Traced& t, RayKind k) { return t.stats.ray_hits[static_cast<int>(k)]; }

// A clear glass material: no diffuse or highlight, only the interface.
Material glass(bool fresnel, float reflectivity = 0.f, float transmittance = 1.f) {
  Material m;
  m.kd = 0.f;
  m.reflectivity = reflectivity;
  m.transmittance = transmittance;
  m.ior = 1.5f;
  m.fresnel = fresnel;
  return m;
}

// An unbounded glass slab between y = -1 and y = 0 (outward normals), in a white furnace: the
// background is 1 in every direction and there are no lights.
Scene slab_scene(const Material& m, int max_depth) {
  Scene s;
  s.settings.max_depth = max_depth;
  s.settings.background = {1.f, 1.f, 1.f};
  const std::uint32_t g = s.add_object("slab", s.add_material(m));
  s.geometry.add(Quad{{-1e3f, 0.f, -1e3f}, {0.f, 0.f, 2e3f}, {2e3f, 0.f, 0.f}}, g);   // normal +y
  s.geometry.add(Quad{{-1e3f, -1.f, -1e3f}, {2e3f, 0.f, 0.f}, {0.f, 0.f, 2e3f}}, g);  // normal -y
  return s;
}

// A ray entering the slab from above at 30 degrees (inside 19.5 degrees: never total internal
// reflection). Depth 1 hits the top face and spawns a reflection (up, escapes) and a refraction
// (inside). Each inside ray of depth d < D hits a face and spawns an inside reflection and an
// escaping refraction. So for max depth D >= 2: D - 1 reflection rays, D - 2 of them hits; D - 1
// refraction rays, 1 hit (the first, inside). The same with Fresnel on or off, where the
// reflection ray carries no weight: which rays are spawned never depends on the weights.
TEST(WhittedTransmission, SlabSpawnsTheRaysTheSpdRulesPredictAtEveryDepth) {
  const Vec3 d{std::sin(30.f * kDeg), -std::cos(30.f * kDeg), 0.f};
  for (const bool fresnel : {true, false}) {
    for (int depth = 1; depth <= 8; ++depth) {
      SCOPED_TRACE(testing::Message() << "fresnel " << fresnel << ", max depth " << depth);
      const Traced t = trace_one(slab_scene(glass(fresnel), depth), d * -2.f, d);
      EXPECT_EQ(cast(t, RayKind::kPrimary), 1u);
      EXPECT_EQ(hits(t, RayKind::kPrimary), 1u);
      const std::uint64_t spawned = depth >= 2 ? static_cast<std::uint64_t>(depth - 1) : 0u;
      EXPECT_EQ(cast(t, RayKind::kReflection), spawned);
      EXPECT_EQ(hits(t, RayKind::kReflection), depth >= 2 ? spawned - 1 : 0u);
      EXPECT_EQ(cast(t, RayKind::kRefraction), spawned);
      EXPECT_EQ(hits(t, RayKind::kRefraction), depth >= 2 ? 1u : 0u);
      EXPECT_EQ(t.stats.total_internal_reflections, 0u);
      EXPECT_EQ(cast(t, RayKind::kShadow), 0u);
    }
  }
}

// From inside the slab at 60 degrees (beyond the critical 41.8): each face reflects totally, so
// each hit spawns one reflection ray and no refraction ray (rule 9), and nothing gets out.
TEST(WhittedTransmission, TotalInternalReflectionSpawnsOnlyTheReflection) {
  const Vec3 up{std::sin(60.f * kDeg), std::cos(60.f * kDeg), 0.f};
  for (const bool fresnel : {true, false}) {
    SCOPED_TRACE(fresnel);
    const Traced t = trace_one(slab_scene(glass(fresnel), 5), {0.f, -0.5f, 0.f}, up);
    EXPECT_EQ(cast(t, RayKind::kReflection), 4u);  // depths 2 to 5, each bouncing off a face
    EXPECT_EQ(hits(t, RayKind::kReflection), 4u);
    EXPECT_EQ(cast(t, RayKind::kRefraction), 0u);
    EXPECT_EQ(t.stats.total_internal_reflections, 4u);  // at depths 1 to 4
    EXPECT_EQ(t.color.x, 0.f);                          // trapped: no light reaches the eye
  }
  // Just inside the critical angle the ray gets out.
  const float below = std::asin(1.f / 1.5f) - 0.5f * kDeg;
  const Traced out = trace_one(slab_scene(glass(true), 2), {0.f, -0.5f, 0.f}, {std::sin(below), std::cos(below), 0.f});
  EXPECT_EQ(cast(out, RayKind::kRefraction), 1u);
  EXPECT_EQ(out.stats.total_internal_reflections, 0u);
}

// In a white furnace every ray that leaves brings back 1. An interface's two rays carry
// reflectivity + T F and T (1 - F), which add up to reflectivity + T: when that is 1 the glass
// neither makes nor loses light, whatever the angle, and only the weight still inside the glass
// at the depth limit (F^63 at most) is missing. Fresnel off (the reflection ray's weight is the
// reflectivity alone) conserves it the same way.
TEST(WhittedTransmission, InterfacesConserveEnergyInAWhiteFurnace) {
  struct Case {
    Material m;
    const char* name;
  };
  for (const Case& c : {Case{glass(true), "Fresnel"}, Case{glass(true, 0.1f, 0.9f), "Fresnel + mirror share"},
                        Case{glass(false), "no Fresnel"}, Case{glass(false, 0.1f, 0.9f), "no Fresnel + mirror"}}) {
    // The slab at angles from normal to near grazing.
    const Scene slab = slab_scene(c.m, WhittedIntegrator::kMaxDepth);
    for (float deg : {0.f, 20.f, 45.f, 70.f, 85.f}) {
      SCOPED_TRACE(testing::Message() << c.name << ", slab at " << deg << " degrees");
      const Vec3 d{std::sin(deg * kDeg), -std::cos(deg * kDeg), 0.f};
      expect_near(trace_one(slab, d * -2.f, d).color);
    }
    // A glass sphere, hit from the centre line out to near its rim.
    Scene ball;
    ball.settings.max_depth = WhittedIntegrator::kMaxDepth;
    ball.settings.background = {1.f, 1.f, 1.f};
    ball.geometry.add(Sphere{{0.f, 0.f, 0.f}, 1.f}, ball.add_object("ball", ball.add_material(c.m)));
    for (float b : {0.f, 0.3f, 0.6f, 0.9f, 0.99f}) {
      SCOPED_TRACE(testing::Message() << c.name << ", sphere at impact parameter " << b);
      expect_near(trace_one(ball, {b, 0.f, -3.f}, {0.f, 0.f, 1.f}).color);
    }
  }
}

// Rule 10 read both ways. A ray along the axis of a glass sphere (radius 1) enters at z = -1 and
// refracts, unbent, onto the far wall at z = +1, which it sees from inside (max depth 2: nothing
// spawns there). A light beyond that wall (z = 5) lies on the wall's outer side, a light at
// z = 0.5 on its inner side; at the entry point both are behind the surface in either reading.
TEST(WhittedTransmission, TheFacingRuleChoosesTheNormalThatMustFaceTheLight) {
  const auto scene = [](Vec3 light_position) {
    Scene s;
    s.settings.max_depth = 2;
    Material m = glass(true);
    m.kd = 0.5f;
    s.geometry.add(Sphere{{0.f, 0.f, 0.f}, 1.f}, s.add_object("ball", s.add_material(m)));
    Light l;
    l.kind = Light::Kind::kPoint;
    l.position = light_position;
    l.falloff = false;
    s.lights.push_back(l);
    return s;
  };
  const Vec3 from{0.f, 0.f, -3.f}, axis{0.f, 0.f, 1.f};
  const Scene beyond = scene({0.f, 0.f, 5.f});
  const Scene inside = scene({0.f, 0.f, 0.5f});

  const Traced viewer_beyond = trace_one(beyond, from, axis, ShadowFacing::kViewer);
  const Traced outward_beyond = trace_one(beyond, from, axis, ShadowFacing::kOutward);
  EXPECT_EQ(cast(viewer_beyond, RayKind::kShadow), 0u);
  EXPECT_EQ(cast(outward_beyond, RayKind::kShadow), 1u);  // from the far wall, out through it
  EXPECT_EQ(hits(outward_beyond, RayKind::kShadow), 0u);
  // The outward reading's extra shadow ray lights nothing: the wall's visible side faces away.
  EXPECT_EQ(outward_beyond.color.x, viewer_beyond.color.x);

  const Traced viewer_inside = trace_one(inside, from, axis, ShadowFacing::kViewer);
  const Traced outward_inside = trace_one(inside, from, axis, ShadowFacing::kOutward);
  EXPECT_EQ(cast(viewer_inside, RayKind::kShadow), 1u);  // the far wall, lit from inside
  EXPECT_EQ(cast(outward_inside, RayKind::kShadow), 0u);
  EXPECT_GT(viewer_inside.color.x, 0.f);
  EXPECT_EQ(outward_inside.color.x, 0.f);
  // Everything else is the same in both readings.
  for (const RayKind k : {RayKind::kPrimary, RayKind::kReflection, RayKind::kRefraction}) {
    EXPECT_EQ(cast(viewer_inside, k), cast(outward_inside, k));
    EXPECT_EQ(hits(viewer_inside, k), hits(outward_inside, k));
  }
}

}  // namespace
}  // namespace raylab
