// Spot lights: a point light within a cone, its edge faded by a smooth step, in Whitted's
// shading and in scene files.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../../src/render/light/spot.h"
#include "raylab/core/error.h"
#include "raylab/io/scene_json.h"
#include "trace_one.h"

namespace raylab {
namespace {

constexpr float kDeg = std::numbers::pi_v<float> / 180.f;

// A white floor under `light`; what the floor at (x, 0, 0) shows, seen from straight above.
float floor_brightness(const Light& light, float x) {
  Scene s;
  Material white;
  white.color = {1.f, 1.f, 1.f};
  s.geometry.add(Quad{{-50.f, 0.f, -50.f}, {0.f, 0.f, 100.f}, {100.f, 0.f, 0.f}},
                 s.add_object("floor", s.add_material(white)));
  s.lights = {light};
  s.settings.max_depth = 1;
  return test::trace_one(s, Vec3{x, 5.f, 0.f}, Vec3{0.f, -1.f, 0.f}).color.y;
}

TEST(SpotLight, LightsItsConeFadesAtTheEdgeAndNothingOutside) {
  Light spot;
  spot.kind = Light::Kind::kSpot;
  spot.position = {0.f, 1.f, 0.f};
  spot.direction = {0.f, -1.f, 0.f};
  spot.spot_angle = 30.f;
  spot.spot_blend = 0.5f;  // full intensity to 15 degrees, none beyond 30
  Light point = spot;
  point.kind = Light::Kind::kPoint;
  const float inner = std::tan(10.f * kDeg), middle = std::tan(22.5f * kDeg), outer = std::tan(35.f * kDeg);
  EXPECT_FLOAT_EQ(floor_brightness(spot, inner), floor_brightness(point, inner));  // as a point light
  EXPECT_EQ(floor_brightness(spot, outer), 0.f);
  // Half way through the fade in angle: a smooth step between the cosines, strictly between.
  const float fading = floor_brightness(spot, middle) / floor_brightness(point, middle);
  const float t = (std::cos(22.5f * kDeg) - std::cos(30.f * kDeg)) / (std::cos(15.f * kDeg) - std::cos(30.f * kDeg));
  EXPECT_NEAR(fading, t * t * (3.f - 2.f * t), 1e-4f);
  EXPECT_GT(fading, 0.f);
  EXPECT_LT(fading, 1.f);
}

TEST(SpotLight, FactorIsOneOnTheAxisAndZeroBehind) {
  Light spot;
  spot.kind = Light::Kind::kSpot;
  spot.direction = {0.f, 0.f, 2.f};  // any length
  EXPECT_EQ(detail::spot_factor(spot, Vec3{0.f, 0.f, 1.f}), 1.f);
  EXPECT_EQ(detail::spot_factor(spot, Vec3{0.f, 0.f, -1.f}), 0.f);
  EXPECT_EQ(detail::spot_factor(spot, Vec3{1.f, 0.f, 0.f}), 0.f);
}

TEST(SpotLight, SceneFilesReadSpotsAndRefuseBadCones) {
  const std::string scene = R"({"version": 1, "materials": {"m": {}},
    "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -2, 0], "angle": 25, "blend": 0.3}],
    "objects": [{"type": "sphere", "material": "m", "center": [0, 0, 0], "radius": 1}]})";
  const Scene s = parse_scene_json(scene, "s.json", ".");
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].kind, Light::Kind::kSpot);
  EXPECT_EQ(s.lights[0].direction, Vec3(0.f, -1.f, 0.f));
  EXPECT_EQ(s.lights[0].spot_angle, 25.f);
  EXPECT_FLOAT_EQ(s.lights[0].spot_blend, 0.3f);
  std::string wide = scene;
  wide.replace(wide.find("\"angle\": 25"), 11, "\"angle\": 95");
  try {
    parse_scene_json(wide, "s.json", ".");
    FAIL() << "a cone wider than a half-space was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'angle'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raylab
