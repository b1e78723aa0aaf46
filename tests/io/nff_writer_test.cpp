// encode_nff: the SPD reference files and a hand-built scene survive load -> encode -> load bit
// for bit; what NFF cannot say is approximated as documented.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "../test_paths.h"
#include "../test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/nff_loader.h"
#include "raylab/io/nff_writer.h"
#include "raylab/render/camera.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

const std::string kSpdDir = raylab::test::source_dir() + "/../shared/spd-reference/";

Scene reparse(const std::string& text) {
  Scene scene;
  NffSceneBuilder builder(scene);
  parse_nff(text, "written.nff", builder);
  builder.finish();
  return scene;
}

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool same_bits(Vec3 a, Vec3 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

// Arrays of plain float records (no padding), compared byte for byte: -0 and 0 differ.
template <class T>
void expect_same_array(const std::vector<T>& got, const std::vector<T>& want, const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (std::memcmp(&got[i], &want[i], sizeof(T)) != 0) {
      ADD_FAILURE() << what << " differ first at index " << i << " of " << got.size();
      return;
    }
  }
}

void expect_same_material(const Material& got, const Material& want, bool names) {
  if (names) {
    EXPECT_EQ(got.name, want.name);
  }
  EXPECT_TRUE(same_bits(got.color, want.color));
  EXPECT_TRUE(same_bits(got.kd, want.kd));
  EXPECT_TRUE(same_bits(got.ks, want.ks));
  EXPECT_TRUE(same_bits(got.shininess, want.shininess));
  EXPECT_TRUE(same_bits(got.reflectivity, want.reflectivity));
  EXPECT_TRUE(same_bits(got.transmittance, want.transmittance));
  EXPECT_TRUE(same_bits(got.ior, want.ior));
  EXPECT_TRUE(same_bits(got.emission, want.emission));
  EXPECT_EQ(got.texture.kind, want.texture.kind);
  EXPECT_EQ(got.fresnel, want.fresnel);
}

// Everything a Scene holds, bit for bit (material and object names only when `names`).
void expect_same_scene(const Scene& got, const Scene& want, bool names) {
  const Geometry& a = got.geometry;
  const Geometry& b = want.geometry;
  expect_same_array(a.triangles, b.triangles, "triangles");
  expect_same_array(a.spheres, b.spheres, "spheres");
  expect_same_array(a.cylinders, b.cylinders, "cylinders");
  expect_same_array(a.disks, b.disks, "disks");
  expect_same_array(a.quads, b.quads, "quads");
  expect_same_array(a.triangle_normals, b.triangle_normals, "triangle normals");
  const auto objects = [](const Geometry& g) {
    return std::tie(g.triangle_objects, g.sphere_objects, g.cylinder_objects, g.disk_objects, g.quad_objects);
  };
  EXPECT_EQ(a.triangle_uvs.size(), b.triangle_uvs.size());
  EXPECT_EQ(objects(a), objects(b));

  test::expect_each(got.objects, want.objects, "object", [names](const SceneObject& x, const SceneObject& y) {
    EXPECT_EQ(x.material, y.material);
    if (names) {
      EXPECT_EQ(x.name, y.name);
    }
  });
  test::expect_each(got.materials, want.materials, "material",
                    [names](const Material& x, const Material& y) { expect_same_material(x, y, names); });
  test::expect_each(got.lights, want.lights, "light", [](const Light& x, const Light& y) {
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_TRUE(same_bits(x.position, y.position));
    EXPECT_TRUE(same_bits(x.intensity, y.intensity));
    EXPECT_EQ(x.falloff, y.falloff);
  });
  EXPECT_TRUE(same_bits(got.camera.from, want.camera.from));
  EXPECT_TRUE(same_bits(got.camera.at, want.camera.at));
  EXPECT_TRUE(same_bits(got.camera.up, want.camera.up));
  EXPECT_TRUE(same_bits(got.camera.vfov_degrees, want.camera.vfov_degrees));
  EXPECT_EQ(got.camera.fov_span, want.camera.fov_span);
  EXPECT_TRUE(same_bits(got.camera.hither, want.camera.hither));
  const RenderSettings& s = got.settings;
  const RenderSettings& t = want.settings;
  const auto exact_settings = [](const RenderSettings& r) {
    return std::tie(r.width, r.height, r.spp, r.sampler, r.max_depth, r.seed, r.sky_gradient);
  };
  EXPECT_EQ(exact_settings(s), exact_settings(t));
  EXPECT_TRUE(same_bits(s.background, t.background));
  EXPECT_TRUE(same_bits(s.ambient, t.ambient));
}

std::size_t count_lines_starting(const std::string& text, const std::string& start) {
  std::size_t n = (text.rfind(start, 0) == 0) ? 1 : 0;
  for (std::size_t p = text.find("\n" + start); p != std::string::npos; p = text.find("\n" + start, p + 1)) ++n;
  return n;
}

TEST(NffWriter, SpdReferenceFilesRoundTripBitForBit) {
  if (!fs::exists(kSpdDir)) GTEST_SKIP() << kSpdDir << " is not present";
  for (const char* name : {"balls", "gears", "mount", "rings", "teapot", "tetra", "tree"}) {
    SCOPED_TRACE(name);
    Scene original;
    load_nff(kSpdDir + name + ".nff", original);
    const std::string text = encode_nff(original);
    // One `f` per object: every fill of an NFF file starts an object with its own material.
    EXPECT_EQ(count_lines_starting(text, "f "), original.objects.size());
    const Scene again = reparse(text);
    expect_same_scene(again, original, true);
    // And the writer is a function of the Scene alone.
    EXPECT_EQ(encode_nff(again), text);
  }
}

TEST(NffWriter, HandBuiltSceneRoundTrips) {
  Scene original;
  NffSceneBuilder b(original);
  NffView view;
  view.from = {1.5f, -2.25f, 3.f};
  view.at = {0.1f, 0.2f, 0.3f};
  view.up = {0.f, 0.f, 1.f};
  view.angle = 37.5;
  view.hither = 0.001;
  view.xres = 640;
  view.yres = 360;
  b.view(view);
  b.background({0.25f, 0.5f, 0.75f});
  b.light({10.f, 10.f, 10.f}, {0.7f, 0.6f, 0.5f});
  b.light({-10.f, 5.f, 1.f});  // uncoloured: finish() gives it its share
  NffFill glass{{0.9f, 0.95f, 1.f}, 0.1f, 0.9f, 200.f, 0.8f, 1.52f};
  b.fill(glass);
  b.sphere({0.f, 0.f, 1.f / 3.f}, 0.1f);
  b.sphere({-0.f, 1e-30f, std::numeric_limits<float>::denorm_min()}, 16777217.f);
  // A non-convex polygon (a U shape), ear clipped into 6 triangles.
  const std::vector<Vec3> u_shape{{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0},
                                  {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
  b.polygon(u_shape);
  NffFill matte{{0.3f, 0.2f, 0.1f}, 0.7f, 0.3f, 12.f, 0.f, 0.f};
  b.fill(matte);
  b.cone({0.f, 0.f, 0.f}, 1.f, {0.f, 0.f, 2.f}, 0.f);
  b.cone({1.f, 1.f, 1.f}, 0.5f, {2.f, 2.f, 2.f}, 0.5f);
  // A pentagonal patch with one zero normal.
  std::vector<Vec3> pentagon, normals;
  for (int k = 0; k < 5; ++k) {
    const float a = 2.f * std::numbers::pi_v<float> * static_cast<float>(k) / 5.f;
    pentagon.push_back({std::cos(a), std::sin(a), 0.5f});
    normals.push_back(k == 2 ? Vec3{} : normalize(Vec3{std::cos(a), std::sin(a), 1.f}));
  }
  b.patch(pentagon, normals);
  b.polygon(std::vector<Vec3>{{0, 0, 5}, {1, 0, 5}, {0, 1, 5}});
  const MeshLoadReport r = b.finish();
  ASSERT_EQ(r.triangles, 6u + 3u + 1u);

  const std::string text = encode_nff(original);
  EXPECT_NE(text.find("\npp 3\n"), std::string::npos);
  const Scene again = reparse(text);
  expect_same_scene(again, original, true);
}

TEST(NffWriter, FloatsReadBackBitForBit) {
  // Random bit patterns cover every exponent; the named values are the usual troublemakers.
  std::vector<float> values{0.1f,
                            1.f / 3.f,
                            -0.f,
                            std::numeric_limits<float>::max(),
                            -std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::min(),
                            std::numeric_limits<float>::denorm_min(),
                            16777217.f,
                            3.0000001f,
                            1e-45f,
                            7.038531e-26f};
  std::mt19937 rng(99u);
  while (values.size() < 30000) {
    const float f = std::bit_cast<float>(static_cast<std::uint32_t>(rng()));
    if (std::isfinite(f)) values.push_back(f);
  }
  Scene original;
  const std::uint32_t object = original.add_object("o", original.add_material({}));
  for (std::size_t i = 0; i + 4 <= values.size(); i += 4) {
    float radius = std::abs(values[i + 3]);
    if (radius == 0.f) radius = 1.f;
    original.geometry.add(Sphere{{values[i], values[i + 1], values[i + 2]}, radius}, object);
  }
  const Scene again = reparse(encode_nff(original));
  expect_same_array(again.geometry.spheres, original.geometry.spheres, "spheres");
}

TEST(NffWriter, EdgeToEdgeFieldOfViewBecomesThePixelCentreAngle) {
  Scene scene;
  scene.camera.from = {0.f, 1.f, 4.f};
  scene.camera.at = {0.f, 0.f, 0.f};
  scene.camera.vfov_degrees = 60.f;
  scene.camera.fov_span = CameraSpec::FovSpan::kImageEdges;
  scene.settings.width = 100;
  scene.settings.height = 50;
  const std::string text = encode_nff(scene);
  EXPECT_NE(text.find("# angle converted"), std::string::npos);
  const Scene again = reparse(text);
  EXPECT_EQ(again.camera.fov_span, CameraSpec::FovSpan::kPixelCentres);
  const double want = 2.0 * std::atan(std::tan(std::numbers::pi / 6.0) * 49.0 / 50.0) * 180.0 / std::numbers::pi;
  EXPECT_NEAR(again.camera.vfov_degrees, want, 1e-4);
  // The same eye rays, corner pixels included.
  const Camera before(scene.camera, 100, 50);
  const Camera after(again.camera, 100, 50);
  for (const auto& [x, y] : {std::pair{0.5f, 0.5f}, std::pair{99.5f, 49.5f}, std::pair{0.f, 50.f}}) {
    const Vec3 d0 = before.generate(x, y).direction;
    const Vec3 d1 = after.generate(x, y).direction;
    EXPECT_NEAR(d0.x, d1.x, 2e-6);
    EXPECT_NEAR(d0.y, d1.y, 2e-6);
    EXPECT_NEAR(d0.z, d1.z, 2e-6);
  }
  // One pixel row: the camera reads the angle edge to edge either way, so it is kept.
  scene.settings.height = 1;
  EXPECT_EQ(reparse(encode_nff(scene)).camera.vfov_degrees, 60.f);
}

TEST(NffWriter, OtherLightsBecomePointLightsWithAComment) {
  Scene scene;
  const std::uint32_t object = scene.add_object("o", scene.add_material({}));
  scene.geometry.add(Sphere{{0.f, 0.f, 0.f}, 1.f}, object);
  Light directional;
  directional.kind = Light::Kind::kDirectional;
  directional.direction = {0.f, -2.f, 0.f};
  directional.intensity = {0.5f, 0.5f, 0.5f};
  Light sphere;
  sphere.kind = Light::Kind::kSphere;
  sphere.position = {1.f, 2.f, 3.f};
  sphere.radius = 0.5f;
  sphere.falloff = true;
  Light quad;
  quad.kind = Light::Kind::kQuad;
  quad.position = {0.f, 5.f, 0.f};
  quad.edge_u = {2.f, 0.f, 0.f};
  quad.edge_v = {0.f, 0.f, 2.f};
  scene.lights = {directional, sphere, quad};
  const std::string text = encode_nff(scene);
  EXPECT_NE(text.find("# directional light approximated by a distant point light\n"), std::string::npos);
  EXPECT_NE(text.find("# spherical area light approximated"), std::string::npos);
  EXPECT_NE(text.find("# quad area light approximated"), std::string::npos);
  EXPECT_NE(text.find("falls off with distance"), std::string::npos);

  const Scene again = reparse(text);
  ASSERT_EQ(again.lights.size(), 3u);
  for (const Light& l : again.lights) EXPECT_EQ(l.kind, Light::Kind::kPoint);
  // Far up, opposite the direction the light travels, above the sphere's centre.
  EXPECT_EQ(again.lights[0].position.x, 0.f);
  EXPECT_GT(again.lights[0].position.y, 100.f);
  EXPECT_EQ(again.lights[0].position.z, 0.f);
  EXPECT_TRUE(same_bits(again.lights[0].intensity, directional.intensity));
  EXPECT_TRUE(same_bits(again.lights[1].position, sphere.position));
  EXPECT_TRUE(same_bits(again.lights[2].position, Vec3{1.f, 5.f, 1.f}));
}

TEST(NffWriter, DisksAndQuadsBecomePolygons) {
  Scene scene;
  const std::uint32_t object = scene.add_object("o", scene.add_material({}));
  const Disk disk{{1.f, 2.f, 3.f}, normalize(Vec3{1.f, 1.f, 0.f}), 2.f};
  scene.geometry.add(disk, object);
  scene.geometry.add(Quad{{0.f, 0.f, 0.f}, {2.f, 0.f, 0.f}, {0.f, 3.f, 0.f}}, object);
  const std::string text = encode_nff(scene);
  EXPECT_NE(text.find("\np 32\n"), std::string::npos);
  EXPECT_NE(text.find("\np 4\n"), std::string::npos);

  const Scene again = reparse(text);
  const Geometry& g = again.geometry;
  ASSERT_EQ(g.triangles.size(), 30u + 2u);
  EXPECT_TRUE(g.disks.empty());
  EXPECT_TRUE(g.quads.empty());
  float disk_area = 0.f, quad_area = 0.f;
  for (std::size_t i = 0; i < 30; ++i) {
    const Triangle& t = g.triangles[i];
    for (const Vec3& p : {t.p0, t.p1, t.p2}) {
      EXPECT_NEAR(length(p - disk.center), disk.radius, 1e-5f);    // on the rim
      EXPECT_NEAR(dot(p - disk.center, disk.normal), 0.f, 1e-5f);  // in the disk's plane
    }
    disk_area += 0.5f * length(triangle_normal(t));
  }
  for (std::size_t i = 30; i < 32; ++i) quad_area += 0.5f * length(triangle_normal(g.triangles[i]));
  const double polygon_area = 0.5 * 32 * 4.0 * std::sin(2.0 * std::numbers::pi / 32);
  EXPECT_NEAR(disk_area, polygon_area, 1e-4);
  EXPECT_FLOAT_EQ(quad_area, 6.f);
}

TEST(NffWriter, OneFillPerMaterialChangeWithTheLargerOfKsAndReflectivity) {
  Scene scene;
  Material shiny;
  shiny.color = {0.5f, 0.25f, 0.125f};
  shiny.ks = 0.2f;
  shiny.reflectivity = 0.5f;
  shiny.shininess = 64.f;
  shiny.ior = 1.33f;
  Material dull;
  dull.ks = 0.3f;
  dull.reflectivity = 0.1f;
  const std::uint32_t m_shiny = scene.add_material(shiny);
  const std::uint32_t m_dull = scene.add_material(dull);
  const std::uint32_t a = scene.add_object("a", m_shiny);
  const std::uint32_t b = scene.add_object("b", m_shiny);  // same material: no second `f`
  const std::uint32_t c = scene.add_object("c", m_dull);
  // Interleaved objects: the writer groups them, keeping order within each object.
  scene.geometry.add(Sphere{{0.f, 0.f, 0.f}, 1.f}, c);
  scene.geometry.add(Sphere{{1.f, 0.f, 0.f}, 1.f}, a);
  scene.geometry.add(Sphere{{2.f, 0.f, 0.f}, 1.f}, b);
  scene.geometry.add(Sphere{{3.f, 0.f, 0.f}, 1.f}, a);
  const std::string text = encode_nff(scene);
  EXPECT_EQ(count_lines_starting(text, "f "), 2u);
  EXPECT_NE(text.find("f 0.5 0.25 0.125 1 0.5 64 0 1.33\n"), std::string::npos) << text;
  EXPECT_NE(text.find("f 0.7 0.7 0.7 1 0.3 32 0 1\n"), std::string::npos) << text;

  const Scene again = reparse(text);
  ASSERT_EQ(again.geometry.spheres.size(), 4u);
  const float xs[] = {1.f, 3.f, 2.f, 0.f};  // objects a, a, b, c
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(again.geometry.spheres[i].center.x, xs[i]);
  ASSERT_EQ(again.materials.size(), 2u);
  EXPECT_EQ(again.materials[0].ks, 0.5f);
  EXPECT_EQ(again.materials[0].reflectivity, 0.5f);
  EXPECT_EQ(again.materials[1].ks, 0.3f);
}

TEST(NffWriter, TrianglesWithoutNormalsArePlainPolygons) {
  Scene scene;
  const std::uint32_t object = scene.add_object("o", scene.add_material({}));
  const Triangle t{{0.f, 0.f, 0.f}, {1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}};
  scene.geometry.add(t, object);
  scene.geometry.add(t, std::array<Vec3, 3>{Vec3{0.f, 0.f, 1.f}, Vec3{}, Vec3{0.f, 0.f, 1.f}}, object);
  const std::string text = encode_nff(scene);
  EXPECT_EQ(count_lines_starting(text, "p 3"), 1u);
  EXPECT_EQ(count_lines_starting(text, "pp 3"), 1u);
  const Scene again = reparse(text);
  expect_same_array(again.geometry.triangles, scene.geometry.triangles, "triangles");
  expect_same_array(again.geometry.triangle_normals, scene.geometry.triangle_normals, "normals");
}

TEST(NffWriter, EmptySceneGivesAValidFile) {
  const Scene empty;
  const std::string text = encode_nff(empty);
  EXPECT_EQ(text.rfind("# ", 0), 0u);
  EXPECT_NE(text.find("\nv\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\n"), std::string::npos) << text;
  const Scene again = reparse(text);
  EXPECT_EQ(again.geometry.size(), 0u);
  EXPECT_EQ(again.settings.width, empty.settings.width);
  EXPECT_EQ(again.settings.height, empty.settings.height);
}

}  // namespace
}  // namespace raylab
