// Normal and bump maps, and the maps that vary a material's parameters: surface tangents against
// the triangle's own edges, a tilted normal-map texel against the rotation it encodes, a bump
// ramp against its analytic slope, the frame's handedness under mirrored texture coordinates,
// the rule's use by surface_at (front and back faces, instances), and material_at's products.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "raylab/core/transform.h"
#include "raylab/geometry/shading.h"
#include "raylab/scene/material.h"
#include "raylab/scene/normal_maps.h"
#include "raylab/scene/scene.h"

namespace raylab {
namespace {

void expect_vec(Vec3 got, Vec3 want, float tolerance) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

// A one-texel image of colour `c` (read as linear data).
std::shared_ptr<const TextureImage> flat_image(Color c) {
  return std::make_shared<const TextureImage>(1, 1, std::vector<Color>{c});
}

// The texel that encodes unit normal `n` in a normal map: (n + 1) / 2.
Color encode_normal(Vec3 n) { return (n + Vec3{1.f, 1.f, 1.f}) * 0.5f; }

// A 64-texel-wide height ramp h = (x + 0.5) / 64 along u, the same in every row.
std::shared_ptr<const TextureImage> ramp_image() {
  constexpr int kWidth = 64, kHeight = 4;
  std::vector<Color> texels;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) texels.push_back(Color{(static_cast<float>(x) + 0.5f) / kWidth});
  }
  return std::make_shared<const TextureImage>(kWidth, kHeight, std::move(texels));
}

TEST(SurfaceTangents, TriangleTangentsRebuildItsEdgesFromItsTextureCoordinates) {
  Geometry g;
  const Triangle tri{{0.f, 0.f, 0.f}, {2.f, 0.f, 1.f}, {0.5f, 3.f, 0.f}};
  const std::array<Vec2, 3> uvs{Vec2{0.1f, 0.2f}, Vec2{0.7f, 0.3f}, Vec2{0.2f, 0.9f}};
  g.add(tri, nullptr, &uvs, 0);
  const std::optional<SurfaceTangents> t = surface_tangents(g, 0);
  ASSERT_TRUE(t.has_value());
  // Each edge is its change of (u, v) along the two tangents.
  for (int k : {1, 2}) {
    const Vec3 edge = (k == 1 ? tri.p1 : tri.p2) - tri.p0;
    const Vec2 duv{uvs[k].x - uvs[0].x, uvs[k].y - uvs[0].y};
    expect_vec(t->dpdu * duv.x + t->dpdv * duv.y, edge, 1e-5f);
  }
}

TEST(SurfaceTangents, WithoutTextureCoordinatesTheEdgesAreTheTangents) {
  Geometry g;
  const Triangle tri{{1.f, 0.f, 0.f}, {2.f, 0.f, 0.f}, {1.f, 1.f, 0.f}};
  g.add(tri, 0);
  const std::optional<SurfaceTangents> t = surface_tangents(g, 0);
  ASSERT_TRUE(t.has_value());
  expect_vec(t->dpdu, tri.p1 - tri.p0, 0.f);
  expect_vec(t->dpdv, tri.p2 - tri.p0, 0.f);
}

TEST(SurfaceTangents, DegenerateTextureCoordinatesAndRoundShapesGiveNone) {
  Geometry g;
  const std::array<Vec2, 3> same{Vec2{0.5f, 0.5f}, Vec2{0.5f, 0.5f}, Vec2{0.5f, 0.5f}};
  g.add(Triangle{{0.f, 0.f, 0.f}, {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}}, nullptr, &same, 0);
  g.add(Sphere{{0.f, 0.f, 0.f}, 1.f}, 0);
  EXPECT_FALSE(surface_tangents(g, 0).has_value());
  EXPECT_FALSE(surface_tangents(g, 1).has_value());
}

TEST(SurfaceTangents, QuadTangentsAreItsUnitEdges) {
  Geometry g;
  g.add(Quad{{0.f, 0.f, 0.f}, {3.f, 0.f, 0.f}, {0.f, 0.f, -2.f}}, 0);
  const std::optional<SurfaceTangents> t = surface_tangents(g, 0);
  ASSERT_TRUE(t.has_value());
  expect_vec(t->dpdu, {1.f, 0.f, 0.f}, 0.f);
  expect_vec(t->dpdv, {0.f, 0.f, -1.f}, 0.f);
}

// A surface in the xy plane, normal +z, u along +x and v along +y.
const SurfaceTangents kPlane{{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}};
const Vec3 kUp{0.f, 0.f, 1.f};

TEST(NormalMap, TexelTiltsTheNormalByTheRotationItEncodes) {
  const float angle = 0.5f;
  const Vec3 tilted{std::sin(angle), 0.f, std::cos(angle)};  // towards +u
  MaterialMaps maps;
  maps.normal = flat_image(encode_normal(tilted));
  expect_vec(mapped_normal(maps, kUp, kPlane, 0.3f, 0.6f), tilted, 1e-6f);
  // Towards +v: the map's green.
  const Vec3 towards_v{0.f, std::sin(angle), std::cos(angle)};
  maps.normal = flat_image(encode_normal(towards_v));
  expect_vec(mapped_normal(maps, kUp, kPlane, 0.3f, 0.6f), towards_v, 1e-6f);
}

TEST(NormalMap, FrameFollowsTheSurfaceNotTheWorld) {
  // The same texel on a wall facing +x, u along -z and v along +y: +u there is -z.
  const float angle = 0.4f;
  MaterialMaps maps;
  maps.normal = flat_image(encode_normal({std::sin(angle), 0.f, std::cos(angle)}));
  const SurfaceTangents wall{{0.f, 0.f, -2.f}, {0.f, 5.f, 0.f}};  // lengths do not matter
  expect_vec(mapped_normal(maps, {1.f, 0.f, 0.f}, wall, 0.f, 0.f), {std::cos(angle), 0.f, -std::sin(angle)}, 1e-6f);
}

TEST(NormalMap, MirroredTextureCoordinatesMirrorTheGreenAxis) {
  const float angle = 0.3f;
  MaterialMaps maps;
  maps.normal = flat_image(encode_normal({0.f, std::sin(angle), std::cos(angle)}));
  // v runs down the surface (a mirrored UV island): +y of the map points along -y.
  const SurfaceTangents mirrored{{1.f, 0.f, 0.f}, {0.f, -1.f, 0.f}};
  expect_vec(mapped_normal(maps, kUp, mirrored, 0.f, 0.f), {0.f, -std::sin(angle), std::cos(angle)}, 1e-6f);
}

TEST(NormalMap, ScaleMultipliesTheTiltAndZeroRemovesIt) {
  MaterialMaps maps;
  maps.normal = flat_image(encode_normal(normalize(Vec3{1.f, 0.f, 1.f})));
  maps.normal_scale = 0.f;
  expect_vec(mapped_normal(maps, kUp, kPlane, 0.f, 0.f), kUp, 1e-6f);
  maps.normal_scale = 2.f;
  // (2 sin 45, 0, cos 45) normalised.
  expect_vec(mapped_normal(maps, kUp, kPlane, 0.f, 0.f), normalize(Vec3{2.f, 0.f, 1.f}), 1e-6f);
}

TEST(BumpMap, HeightRampTiltsTheNormalByItsSlope) {
  MaterialMaps maps;
  maps.bump = ramp_image();
  maps.bump_scale = 0.5f;
  // Inside the ramp (away from where repeat addressing wraps it) dh/du = 0.5 per unit of u:
  // the displaced surface (u, v, 0.5 u) has the normal (-0.5, 0, 1).
  const Vec3 want = normalize(Vec3{-0.5f, 0.f, 1.f});
  for (const float u : {0.25f, 0.5f, 0.7f}) expect_vec(mapped_normal(maps, kUp, kPlane, u, 0.5f), want, 1e-4f);
}

TEST(BumpMap, ConstantHeightChangesNothing) {
  MaterialMaps maps;
  maps.bump = flat_image(Color{0.8f});
  maps.bump_scale = 10.f;
  expect_vec(mapped_normal(maps, kUp, kPlane, 0.4f, 0.1f), kUp, 1e-6f);
}

TEST(NormalMaps, AFlatNormalMapLooksLikeOneAndAGreyHeightMapDoesNot) {
  EXPECT_TRUE(looks_like_normal_map(*flat_image({0.5f, 0.5f, 1.f})));
  EXPECT_FALSE(looks_like_normal_map(*ramp_image()));
  EXPECT_FALSE(looks_like_normal_map(*flat_image({0.9f, 0.9f, 0.9f})));  // bright grey: a height
}

// A quad in the xy plane facing +z, with `maps`, seen by rays along -z or +z.
Scene mapped_quad(const MaterialMaps& maps) {
  Scene scene;
  Material m;
  m.maps = maps;
  const std::uint32_t object = scene.add_object("quad", scene.add_material(m));
  scene.geometry.add(Quad{{-1.f, -1.f, 0.f}, {2.f, 0.f, 0.f}, {0.f, 2.f, 0.f}}, object);
  return scene;
}

SurfaceInteraction hit_quad(const Scene& scene, float direction_z) {
  Ray ray;
  ray.origin = {0.2f, 0.1f, -direction_z};
  ray.direction = {0.f, 0.f, direction_z};
  Hit hit;
  hit.t = 1.f;
  hit.prim_id = 0;
  hit.u = 0.6f;
  hit.v = 0.55f;
  return surface_at(scene, ray, hit);
}

TEST(NormalMaps, SurfaceAtTiltsTheShadingNormalOnBothFaces) {
  const float angle = 0.35f;
  MaterialMaps maps;
  maps.normal = flat_image(encode_normal({std::sin(angle), 0.f, std::cos(angle)}));
  const Scene scene = mapped_quad(maps);
  const SurfaceInteraction front = hit_quad(scene, -1.f);
  ASSERT_TRUE(front.front_face);
  expect_vec(front.shading_normal, {std::sin(angle), 0.f, std::cos(angle)}, 1e-6f);
  expect_vec(front.geometric_normal, kUp, 0.f);
  // From behind, the map's normal is the outward side's: the shading normal is its opposite.
  const SurfaceInteraction back = hit_quad(scene, 1.f);
  ASSERT_FALSE(back.front_face);
  expect_vec(back.shading_normal, -Vec3{std::sin(angle), 0.f, std::cos(angle)}, 1e-6f);
}

TEST(NormalMaps, AMapCannotTurnTheShadingNormalAwayFromTheViewer) {
  MaterialMaps maps;
  maps.normal = flat_image(encode_normal({1.f, 0.f, 0.f}));  // lies in the surface
  maps.normal_scale = 5.f;
  const SurfaceInteraction si = hit_quad(mapped_quad(maps), -1.f);
  EXPECT_GT(dot(si.shading_normal, si.geometric_normal), 0.f);
  EXPECT_NEAR(length(si.shading_normal), 1.f, 1e-6f);
}

TEST(NormalMaps, InstancesCarryTheTangentFrameIntoTheWorld) {
  const float angle = 0.35f;
  MaterialMaps maps;
  maps.normal = flat_image(encode_normal({std::sin(angle), 0.f, std::cos(angle)}));
  Scene scene;
  Material m;
  m.maps = maps;
  const std::uint32_t object = scene.add_object("quad", scene.add_material(m));
  Geometry prototype;
  prototype.add(Quad{{-1.f, -1.f, 0.f}, {2.f, 0.f, 0.f}, {0.f, 2.f, 0.f}}, 0);  // object 0 of the instance
  scene.prototypes.push_back(std::move(prototype));
  // Turned a quarter turn about y: the quad faces +x and its u axis points along -z.
  scene.add_instance(0, Transform::rotate(90.0, {0.f, 1.f, 0.f}), object);
  Ray ray;
  ray.origin = {3.f, 0.1f, 0.2f};
  ray.direction = {-1.f, 0.f, 0.f};
  Hit hit;
  hit.t = 3.f;
  hit.prim_id = scene.geometry.size();  // the instance's first primitive
  hit.u = 0.4f;
  hit.v = 0.55f;
  const SurfaceInteraction si = surface_at(scene, ray, hit);
  expect_vec(si.geometric_normal, {1.f, 0.f, 0.f}, 1e-6f);
  expect_vec(si.shading_normal, {std::cos(angle), 0.f, -std::sin(angle)}, 1e-5f);
}

TEST(MaterialAt, MapsMultiplyTheFactors) {
  Material m;
  m.model = MaterialModel::kMetallicRoughness;
  m.roughness = 0.8f;
  m.metallic = 0.5f;
  m.transmission = 0.6f;
  m.emission = {2.f, 1.f, 0.5f};
  m.emission_strength = 3.f;
  m.maps.metallic_roughness = flat_image({0.9f, 0.25f, 0.5f});  // red (occlusion) is not read
  m.maps.transmission = flat_image({0.5f, 0.f, 0.f});
  m.maps.emission = flat_image({0.5f, 1.f, 0.f});
  const MaterialPoint p = material_at(m, 0.1f, 0.2f);
  EXPECT_FLOAT_EQ(p.roughness, 0.8f * 0.25f);
  EXPECT_FLOAT_EQ(p.metallic, 0.5f * 0.5f);
  EXPECT_FLOAT_EQ(p.transmission, 0.3f);
  expect_vec(emitted_radiance(m, 0.1f, 0.2f), {3.f, 3.f, 0.f}, 1e-6f);
  // Without maps the factors pass through.
  const Material plain;
  EXPECT_EQ(material_at(plain, 0.f, 0.f).roughness, plain.roughness);
  expect_vec(emitted_radiance(plain, 0.f, 0.f), plain.emission, 0.f);
}

}  // namespace
}  // namespace raylab
