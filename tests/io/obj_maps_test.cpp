// load_obj's MTL maps beyond the colour: map_Ke (an sRGB emission map), norm (a linear normal
// map), map_Bump / map_bump / bump read as a normal map when the image holds normals and as a
// height map scaled by -bm otherwise, norm preferred over map_Bump, and a missing map file a
// warning at its statement that leaves the material loaded without the map.

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "io_test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/format_losses.h"
#include "raylab/io/obj_loader.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";

/// An 8-bit value read as linear data: exactly s / 255, as the loader computes it.
float linear8(int s) { return static_cast<float>(s) / 255.f; }

/// An 8-bit value read as sRGB, from the IEC 61966-2-1 formula in double precision (independent
/// of the loader's float table, hence compared with a tolerance).
double srgb8(int s) {
  const double e = s / 255.0;
  return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

class ObjMaps : public ::testing::Test {
 protected:
  void SetUp() override { m_object = m_scene.add_object("mesh", m_scene.add_material(Material{})); }

  /// Writes an 8-bit RGB PNG of `width` x `height` texels, `rgb` row by row from the top.
  void write_png(const std::string& name, int width, int height, const std::vector<unsigned char>& rgb) {
    ASSERT_EQ(rgb.size(), static_cast<std::size_t>(width * height * 3));
    ASSERT_NE(stbi_write_png(m_tmp.file(name).c_str(), width, height, 3, rgb.data(), width * 3), 0);
  }
  /// A 2 x 2 tangent-space normal map of untilted normals: every texel (128, 128, 255).
  void write_flat_normals(const std::string& name) {
    write_png(name, 2, 2, {128, 128, 255, 128, 128, 255, 128, 128, 255, 128, 128, 255});
  }
  /// A 4 x 1 grey ramp, a height map: 0, 85, 170, 255 from left to right.
  void write_grey_ramp(const std::string& name) {
    write_png(name, 4, 1, {0, 0, 0, 85, 85, 85, 170, 170, 170, 255, 255, 255});
  }

  /// Writes `mtl` as m.mtl and an OBJ whose one triangle uses material `material` of it, and
  /// loads the OBJ; returns the path of the .mtl file.
  std::string load(const std::string& mtl, const std::string& material = "a") {
    const std::string mtl_path = test::write_text(m_tmp.path() / "m.mtl", mtl);
    m_path = test::write_text(m_tmp.path() / "model.obj",
                              std::string("mtllib m.mtl\n") + kTriangle + "usemtl " + material + "\nf 1/1 2/2 3/3\n");
    load_obj(m_path, m_scene, m_object);
    return mtl_path;
  }

  /// The material of the last triangle loaded.
  const Material& material() const {
    EXPECT_FALSE(m_scene.geometry.triangle_objects.empty());
    return m_scene.materials[m_scene.objects[m_scene.geometry.triangle_objects.back()].material];
  }

  Scene m_scene;
  std::uint32_t m_object = 0;
  test::TempDir m_tmp{"obj-maps"};
  std::string m_path;
};

TEST_F(ObjMaps, MapKeIsAnSrgbEmissionMap) {
  write_png("glow.png", 1, 1, {128, 64, 255});
  load("newmtl a\nKe 1 0.5 0.25\nmap_Ke glow.png\n");
  EXPECT_TRUE(m_scene.warnings.empty());
  const Material& m = material();
  EXPECT_EQ(m.emission, Color(1.f, 0.5f, 0.25f));
  ASSERT_TRUE(m.maps.emission);
  const Color e = m.maps.emission->texel(0, 0);
  EXPECT_NEAR(e.x, srgb8(128), 1e-6);
  EXPECT_NEAR(e.y, srgb8(64), 1e-6);
  EXPECT_EQ(e.z, 1.f);
  EXPECT_GT(std::fabs(e.x - linear8(128)), 0.2f);  // far from the linear reading of 128
  // It is no colour texture, and no other map.
  EXPECT_EQ(m.texture.kind, Texture::Kind::kNone);
  EXPECT_FALSE(m.maps.normal || m.maps.bump || m.maps.metallic_roughness || m.maps.transmission);
  // The path integrator's emission is Ke times the map.
  const Color radiance = emitted_radiance(m, 0.5f, 0.5f);
  EXPECT_FLOAT_EQ(radiance.x, e.x);
  EXPECT_FLOAT_EQ(radiance.y, 0.5f * e.y);
  EXPECT_FLOAT_EQ(radiance.z, 0.25f);
}

TEST_F(ObjMaps, NormIsALinearNormalMap) {
  write_png("n.png", 1, 1, {100, 150, 230});
  load("newmtl a\nnorm n.png\n");
  const Material& m = material();
  ASSERT_TRUE(m.maps.normal);
  EXPECT_EQ(m.maps.normal->texel(0, 0), Color(linear8(100), linear8(150), linear8(230)));
  EXPECT_EQ(m.maps.normal_scale, 1.f);
  EXPECT_FALSE(m.maps.bump);
  EXPECT_FALSE(m.maps.emission);
}

TEST_F(ObjMaps, MapBumpHoldingNormalsIsANormalMap) {
  write_flat_normals("flat.png");
  load("newmtl a\nmap_Bump flat.png\n");
  const Material& m = material();
  ASSERT_TRUE(m.maps.normal);
  EXPECT_FALSE(m.maps.bump);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 2; ++x) EXPECT_EQ(m.maps.normal->texel(x, y), Color(linear8(128), linear8(128), 1.f));
  }
}

TEST_F(ObjMaps, MapBumpHoldingHeightsIsABumpMapScaledByBm) {
  write_grey_ramp("ramp.png");
  load("newmtl a\nmap_Bump -bm 0.25 ramp.png\n");
  const Material& m = material();
  ASSERT_TRUE(m.maps.bump);
  EXPECT_FALSE(m.maps.normal);
  EXPECT_EQ(m.maps.bump_scale, 0.25f);
  // Heights are data: linear, 85 reads as 85 / 255 = 1/3.
  ASSERT_EQ(m.maps.bump->width(), 4);
  EXPECT_EQ(m.maps.bump->texel(0, 0), Color(0.f, 0.f, 0.f));
  EXPECT_EQ(m.maps.bump->texel(1, 0), Color(linear8(85), linear8(85), linear8(85)));
  EXPECT_EQ(m.maps.bump->texel(2, 0).x, linear8(170));
  EXPECT_EQ(m.maps.bump->texel(3, 0).x, 1.f);
}

TEST_F(ObjMaps, MapBumpWithoutBmScalesByOne) {
  // The lower-case spelling that some exporters write.
  write_grey_ramp("ramp.png");
  load("newmtl a\nmap_bump ramp.png\n");
  ASSERT_TRUE(material().maps.bump);
  EXPECT_EQ(material().maps.bump_scale, 1.f);
  EXPECT_EQ(material().maps.bump->texel(1, 0).x, linear8(85));
}

TEST_F(ObjMaps, BumpSpellingReadsAsMapBump) {
  write_grey_ramp("ramp.png");
  write_flat_normals("flat.png");
  load("newmtl heights\nbump -bm 0.5 ramp.png\nnewmtl normals\nbump flat.png\n", "heights");
  ASSERT_TRUE(material().maps.bump);
  EXPECT_FALSE(material().maps.normal);
  EXPECT_EQ(material().maps.bump_scale, 0.5f);
  EXPECT_EQ(material().maps.bump->texel(2, 0).x, linear8(170));
  load("newmtl heights\nbump -bm 0.5 ramp.png\nnewmtl normals\nbump flat.png\n", "normals");
  ASSERT_TRUE(material().maps.normal);
  EXPECT_FALSE(material().maps.bump);
  EXPECT_EQ(material().maps.normal->texel(1, 1), Color(linear8(128), linear8(128), 1.f));
}

TEST_F(ObjMaps, NormWinsOverMapBump) {
  write_png("n.png", 1, 1, {120, 140, 250});
  write_flat_normals("flat.png");
  write_grey_ramp("ramp.png");
  // Against a map_Bump of normals: norm's image, not the flat one.
  load("newmtl a\nnorm n.png\nmap_Bump flat.png\n");
  ASSERT_TRUE(material().maps.normal);
  EXPECT_EQ(material().maps.normal->width(), 1);
  EXPECT_EQ(material().maps.normal->texel(0, 0), Color(linear8(120), linear8(140), linear8(250)));
  EXPECT_FALSE(material().maps.bump);
  // Against a map_Bump of heights, written first: still norm alone (the two would both tilt
  // the normal, and a normal map already says everything about it).
  load("newmtl a\nmap_Bump -bm 3 ramp.png\nnorm n.png\n");
  ASSERT_TRUE(material().maps.normal);
  EXPECT_EQ(material().maps.normal->texel(0, 0).x, linear8(120));
  EXPECT_FALSE(material().maps.bump);
  EXPECT_TRUE(m_scene.warnings.empty());
}

TEST_F(ObjMaps, OneFileAsColourAndAsNormalsIsDecodedBothWays) {
  write_png("both.png", 1, 1, {128, 64, 200});
  load("newmtl a\nmap_Kd both.png\nnorm both.png\n");
  const Material& m = material();
  ASSERT_EQ(m.texture.kind, Texture::Kind::kImage);
  ASSERT_TRUE(m.texture.image);
  ASSERT_TRUE(m.maps.normal);
  EXPECT_NE(m.texture.image, m.maps.normal);
  EXPECT_NEAR(m.texture.image->texel(0, 0).x, srgb8(128), 1e-6);
  EXPECT_NEAR(m.texture.image->texel(0, 0).z, srgb8(200), 1e-6);
  EXPECT_EQ(m.maps.normal->texel(0, 0), Color(linear8(128), linear8(64), linear8(200)));
}

TEST_F(ObjMaps, MissingNormFileIsAWarningAndTheMaterialLoads) {
  const std::string mtl = load("newmtl a\nKd 0.5 0.25 1\nnorm  missing.png\n");
  ASSERT_EQ(m_scene.warnings.size(), 1u);
  const std::string& w = m_scene.warnings[0];
  // At the file name: line 3, column 7.
  EXPECT_EQ(w.rfind(mtl + ":3:7: texture 'missing.png' not found (looked for ", 0), 0u) << w;
  EXPECT_TRUE(w.ends_with("; material 'a' renders without it")) << w;
  const Material& m = material();
  EXPECT_EQ(m.name, "a");
  EXPECT_EQ(m.color, Color(0.5f, 0.25f, 1.f));
  EXPECT_FALSE(m.maps.normal);
  EXPECT_FALSE(m.maps.bump);
  EXPECT_EQ(m_scene.geometry.triangles.size(), 1u);
}

TEST_F(ObjMaps, MissingMapFilesAreWarnedAtTheirOwnStatements) {
  // Each spelling of the bump statement, and map_Ke, is found for the warning's position.
  const std::string mtl = load("newmtl a\nKe 1 1 1\nmap_Ke  glow.png\n  bump -bm 2 heights.png\n");
  ASSERT_EQ(m_scene.warnings.size(), 2u);
  EXPECT_EQ(m_scene.warnings[0].rfind(mtl + ":3:9: texture 'glow.png' not found", 0), 0u) << m_scene.warnings[0];
  EXPECT_EQ(m_scene.warnings[1].rfind(mtl + ":4:14: texture 'heights.png' not found", 0), 0u) << m_scene.warnings[1];
  EXPECT_FALSE(material().maps.emission);
  EXPECT_FALSE(material().maps.bump);
  EXPECT_FALSE(material().maps.normal);
  EXPECT_EQ(material().emission, Color(1.f, 1.f, 1.f));
}

TEST_F(ObjMaps, ConvertingBackToObjReportsTheMapsAsALoss) {
  write_flat_normals("flat.png");
  load("newmtl a\nmap_Bump flat.png\n");
  const std::vector<std::string> losses = format_losses(m_scene, ".obj", false);
  EXPECT_NE(std::find(losses.begin(), losses.end(), "texture maps beyond the colour of 1 material"), losses.end())
      << losses_message("out.obj", losses);
}

}  // namespace
}  // namespace raylab
