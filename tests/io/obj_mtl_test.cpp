// load_obj with MTL materials: values mapped, one object per material, texture coordinates per
// corner (negative indices too), map_Kd images, and every path refusal placed at its statement.

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "io_test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/image_io.h"
#include "raylab/io/obj_loader.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

class ObjMtl : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(m_dir);
    Material grey;
    grey.name = "fallback";
    m_object = m_scene.add_object("mesh", m_scene.add_material(grey));
  }
  std::string write_file(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    return test::write_text(path, text);
  }
  std::string write(const std::string& name, const std::string& text) { return write_file(m_dir / name, text); }

  // A 2 x 1 PNG: left texel red, right texel blue.
  void write_png(const fs::path& path) {
    const unsigned char rgb[] = {255, 0, 0, 0, 0, 255};
    fs::create_directories(path.parent_path());
    ASSERT_NE(stbi_write_png(path.string().c_str(), 2, 1, 3, rgb, 6), 0);
  }

  MeshLoadReport load(const std::string& obj_text, const ObjLoadOptions& options = {}) {
    m_path = write("model.obj", obj_text);
    return load_obj(m_path, m_scene, m_object, options);
  }

  // Loads `obj_text`, which must fail with an InputError at `file:line:col` containing `fragment`.
  void expect_error(const std::string& obj_text, const std::string& file, int line, int col,
                    const std::string& fragment, const ObjLoadOptions& options = {}) {
    try {
      load(obj_text, options);
      ADD_FAILURE() << "no error for:\n" << obj_text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), file.empty() ? m_path : file) << e.what();
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_EQ(e.column(), col) << e.what();
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }

  // The material of the object triangle `t` belongs to.
  const Material& material_of_triangle(std::size_t t) const {
    return m_scene.materials[m_scene.objects[m_scene.geometry.triangle_objects[t]].material];
  }

  Scene m_scene;
  std::uint32_t m_object = 0;
  test::TempDir m_tmp{"objmtl"};
  const fs::path m_root = m_tmp.path(), m_dir = m_root / "model";
  std::string m_path;
};

TEST_F(ObjMtl, MaterialValuesAreMapped) {
  write("m.mtl",
        "newmtl glass\nKd 0.8 0.1 0.2\nKs 0.3 0.5 0.4\nNs 77\nd 0.25\nNi 1.5\nKe 0 0.5 0\nillum 2\n"
        "newmtl mirror\nKd 0.1 0.1 0.1\nKs 0.9 0.7 0.8\nillum 3\n");
  load(std::string("mtllib m.mtl\n") + kTriangle + "usemtl glass\nf 1 2 3\nusemtl mirror\nf 3 2 1\n");
  ASSERT_EQ(m_scene.geometry.triangles.size(), 2u);
  const Material& glass = material_of_triangle(0);
  EXPECT_EQ(glass.name, "glass");
  EXPECT_EQ(glass.color, Color(0.8f, 0.1f, 0.2f));
  EXPECT_FLOAT_EQ(glass.ks, 0.5f);
  EXPECT_FLOAT_EQ(glass.shininess, 77.f);
  EXPECT_FLOAT_EQ(glass.transmittance, 0.75f);
  EXPECT_FLOAT_EQ(glass.ior, 1.5f);
  EXPECT_EQ(glass.emission, Color(0.f, 0.5f, 0.f));
  EXPECT_FLOAT_EQ(glass.reflectivity, 0.f);
  EXPECT_EQ(glass.texture.kind, Texture::Kind::kNone);
  const Material& mirror = material_of_triangle(1);
  EXPECT_EQ(mirror.name, "mirror");
  EXPECT_FLOAT_EQ(mirror.reflectivity, 0.9f);  // illum 3: ray-traced reflection of weight Ks
  EXPECT_FLOAT_EQ(mirror.transmittance, 0.f);
  EXPECT_FLOAT_EQ(mirror.shininess, Material{}.shininess);  // no Ns: raylab's default, not 1
}

TEST_F(ObjMtl, OneObjectPerMaterialAndTheRestInTheCallersObject) {
  write("m.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n");
  load(std::string("mtllib m.mtl\n") + kTriangle +
       "f 1 2 3\nusemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\nusemtl a\nf 1 2 3\nusemtl nothing\nf 1 2 3\n");
  const auto& objects = m_scene.geometry.triangle_objects;
  ASSERT_EQ(objects.size(), 5u);
  EXPECT_EQ(objects[0], m_object);
  EXPECT_NE(objects[1], m_object);
  EXPECT_NE(objects[2], objects[1]);
  EXPECT_EQ(objects[3], objects[1]);  // the same material again: the same object
  EXPECT_EQ(objects[4], m_object);    // a name no library defines
  EXPECT_EQ(m_scene.objects.size(), 3u);
  EXPECT_EQ(m_scene.objects[objects[1]].name, "mesh/a");
  EXPECT_EQ(material_of_triangle(2).color, Color(0.f, 1.f, 0.f));
  // The unknown name is reported, with its position.
  ASSERT_EQ(m_scene.warnings.size(), 1u);
  EXPECT_NE(m_scene.warnings[0].find(m_path + ":12:8:"), std::string::npos) << m_scene.warnings[0];
  EXPECT_NE(m_scene.warnings[0].find("'nothing'"), std::string::npos) << m_scene.warnings[0];
}

TEST_F(ObjMtl, DefaultOverloadUsesTheFilesMaterials) {
  write("m.mtl", "newmtl a\nKd 1 0 0\n");
  m_path = write("model.obj", std::string("mtllib m.mtl\n") + kTriangle + "usemtl a\nf 1 2 3\n");
  load_obj(m_path, m_scene, m_object);
  EXPECT_EQ(material_of_triangle(0).color, Color(1.f, 0.f, 0.f));
}

TEST_F(ObjMtl, MaterialsCanBeTurnedOff) {
  // No library is read at all: a missing one is no error either.
  load(std::string("mtllib missing.mtl\n") + kTriangle + "usemtl a\nf 1 2 3\n", {.use_materials = false});
  ASSERT_EQ(m_scene.geometry.triangle_objects.size(), 1u);
  EXPECT_EQ(m_scene.geometry.triangle_objects[0], m_object);
  EXPECT_EQ(m_scene.objects.size(), 1u);
}

TEST_F(ObjMtl, EveryLibraryOfOneMtllibLineIsRead) {
  write("a.mtl", "newmtl a\nKd 1 0 0\n");
  write("b c.mtl", "newmtl b\nKd 0 0 1\n");
  load(std::string("mtllib a.mtl b\\ c.mtl\n") + kTriangle + "usemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n");
  EXPECT_EQ(material_of_triangle(0).color, Color(1.f, 0.f, 0.f));
  EXPECT_EQ(material_of_triangle(1).color, Color(0.f, 0.f, 1.f));
}

TEST_F(ObjMtl, TextureCoordinatesPerCorner) {
  load(std::string(kTriangle) + "v 1 1 0\nvt 0 0\nvt 1 0\nvt 0.25 0.75\nvt 0.5 0.5\n" +
       "f 1/1 2/2 3/3\n"
       "f 2/-3 4/-1 3/-2\n"  // relative: -3 is vt 2, -1 is vt 4, -2 is vt 3
       "f 1 2 3\n");         // no texture coordinates
  const auto& uvs = m_scene.geometry.triangle_uvs;
  ASSERT_EQ(uvs.size(), 3u);
  auto expect_uv = [](Vec2 got, float u, float v) {
    EXPECT_EQ(got.x, u);
    EXPECT_EQ(got.y, v);
  };
  expect_uv(uvs[0][0], 0.f, 0.f);
  expect_uv(uvs[0][1], 1.f, 0.f);
  expect_uv(uvs[0][2], 0.25f, 0.75f);
  expect_uv(uvs[1][0], 1.f, 0.f);
  expect_uv(uvs[1][1], 0.5f, 0.5f);
  expect_uv(uvs[1][2], 0.25f, 0.75f);
  // Without texture coordinates a triangle gets its barycentric ones.
  expect_uv(uvs[2][0], 0.f, 0.f);
  expect_uv(uvs[2][1], 1.f, 0.f);
  expect_uv(uvs[2][2], 0.f, 1.f);
}

TEST_F(ObjMtl, TextureCoordinateIndexOutOfRange) {
  const std::string vts = std::string(kTriangle) + "vt 0 0\nvt 1 0\n";
  expect_error(vts + "f 1/1 2/2 3/3\n", "", 6, 11, "texture coordinate index out of range (the file has 2");
  expect_error(vts + "f 1/1 2/-3 3/1\n", "", 6, 7, "texture coordinate index out of range");
  // -3 with 2 coordinates resolves to -1 in tinyobjloader, the same as "none": still an error.
  expect_error(vts + "f 1/-3 2/-3 3/-3\n", "", 6, 3, "texture coordinate index out of range");
  expect_error(vts + "f 1/-4 2/1 3/1\n", "", 6, 3, "texture coordinate index out of range");
  expect_error(std::string(kTriangle) + "f 1/1 2/1 3/1\n", "", 4, 3, "(the file has 0 texture coordinates)");
}

TEST_F(ObjMtl, NormalIndexResolvingToMinusOneIsAnError) {
  expect_error(std::string(kTriangle) + "vn 0 0 1\nf 1//1 2//-2 3//1\n", "", 5, 8, "normal index out of range");
}

TEST_F(ObjMtl, NonFiniteTextureCoordinate) {
  expect_error(std::string(kTriangle) + "vt 0 1e999\nf 1/1 2/1 3/1\n", "", 4, 6, "not a finite number");
}

TEST_F(ObjMtl, MapKdIsAnImageTextureMultiplyingKd) {
  write_png(m_dir / "tex" / "checker.png");
  write("m.mtl", "newmtl painted\nKd 0.5 1 1\nmap_Kd tex/checker.png\nnewmtl plain\nmap_Kd -s 1 1 1 tex/checker.png\n");
  load(std::string("mtllib m.mtl\n") + kTriangle + "vt 0.25 0.5\nvt 0.75 0.5\nvt 0.5 0.5\n" +
       "usemtl painted\nf 1/1 2/2 3/3\nusemtl plain\nf 1/1 2/2 3/3\n");
  const Material& painted = material_of_triangle(0);
  ASSERT_EQ(painted.texture.kind, Texture::Kind::kImage);
  ASSERT_TRUE(painted.texture.image);
  EXPECT_EQ(painted.texture.image->width(), 2);
  EXPECT_EQ(painted.texture.image->texel(0, 0), Color(1.f, 0.f, 0.f));
  EXPECT_EQ(diffuse_color(painted, 0.25f, 0.5f), Color(0.5f, 0.f, 0.f));
  EXPECT_EQ(diffuse_color(painted, 0.75f, 0.5f), Color(0.f, 0.f, 1.f));
  // Without Kd the texture shows as painted (white), and options before the name are skipped.
  const Material& plain = material_of_triangle(1);
  EXPECT_EQ(plain.color, Color(1.f, 1.f, 1.f));
  EXPECT_EQ(diffuse_color(plain, 0.25f, 0.5f), Color(1.f, 0.f, 0.f));
  // One file, decoded once.
  EXPECT_EQ(plain.texture.image, painted.texture.image);
}

// A missing library is a missing optional part of the model: a warning at its name, and the
// faces load with the default material.
TEST_F(ObjMtl, MissingLibraryIsAWarningAtItsNameAndTheFacesStillLoad) {
  const std::string obj = std::string("# header\nmtllib  there.mtl missing.mtl\n") + kTriangle + "f 1 2 3\n";
  load(obj);
  ASSERT_EQ(m_scene.warnings.size(), 2u);
  EXPECT_EQ(m_scene.warnings[0].rfind(m_path + ":2:9: material library 'there.mtl' not found (looked for ", 0), 0u)
      << m_scene.warnings[0];
  EXPECT_TRUE(m_scene.warnings[0].ends_with("); its faces use the default material")) << m_scene.warnings[0];
  EXPECT_EQ(m_scene.geometry.triangles.size(), 1u);
  EXPECT_EQ(m_scene.geometry.triangle_objects[0], m_object);
  m_scene.warnings.clear();
  write("there.mtl", "newmtl a\n");
  load(obj);
  ASSERT_EQ(m_scene.warnings.size(), 1u);
  EXPECT_NE(m_scene.warnings[0].find(":2:19: material library 'missing.mtl' not found"), std::string::npos)
      << m_scene.warnings[0];
}

TEST_F(ObjMtl, LibraryOutsideTheFolderIsRefused) {
  write_file(m_root / "outside.mtl", "newmtl a\nKd 0 1 0\n");
  const std::string obj = std::string("mtllib ../outside.mtl\n") + kTriangle + "usemtl a\nf 1 2 3\n";
  expect_error(obj, "", 1, 8, "'../outside.mtl' is outside the folder");
  // An absolute path out of the folder too.
  expect_error("mtllib " + (m_root / "outside.mtl").string() + "\n" + kTriangle, "", 1, 8, "is outside the folder");
  // Allowed on request.
  load(obj, {.allow_outside_paths = true});
  EXPECT_EQ(material_of_triangle(0).color, Color(0.f, 1.f, 0.f));
}

TEST_F(ObjMtl, SymbolicLinkOutOfTheFolderIsRefused) {
  write_file(m_root / "outside.mtl", "newmtl a\n");
  fs::create_symlink(m_root / "outside.mtl", m_dir / "inside.mtl");
  expect_error(std::string("mtllib inside.mtl\n") + kTriangle, "", 1, 8, "is outside the folder");
  // A `..` that comes back into the folder is fine.
  write("m.mtl", "newmtl a\nKd 0 0 1\n");
  load(std::string("mtllib ../model/m.mtl\n") + kTriangle + "usemtl a\nf 1 2 3\n");
  EXPECT_EQ(material_of_triangle(0).color, Color(0.f, 0.f, 1.f));
}

TEST_F(ObjMtl, TextureErrorsArePlacedInTheMtlFile) {
  write_png(m_root / "outside.png");
  const std::string mtl = write("m.mtl", "newmtl a\nKd 1 1 1\n\n  map_Kd ../outside.png\n");
  const std::string obj = std::string("mtllib m.mtl\n") + kTriangle + "usemtl a\nf 1 2 3\n";
  expect_error(obj, mtl, 4, 10, "texture '../outside.png' is outside the folder");
  // A missing texture is a warning at the map_Kd that names it; the material renders without it.
  write("m.mtl", "newmtl a\nmap_Kd nowhere.png\n");
  load(obj);
  ASSERT_EQ(m_scene.warnings.size(), 1u);
  EXPECT_EQ(m_scene.warnings[0].rfind(mtl + ":2:8: texture 'nowhere.png' not found (looked for ", 0), 0u)
      << m_scene.warnings[0];
  EXPECT_TRUE(m_scene.warnings[0].ends_with("; material 'a' renders without it")) << m_scene.warnings[0];
  EXPECT_EQ(material_of_triangle(m_scene.geometry.triangles.size() - 1).texture.kind, Texture::Kind::kNone);
  m_scene = Scene{};
  m_object = m_scene.add_object("model", m_scene.add_material(Material{}));
  write("bad.png", "not a picture");
  write("m.mtl", "newmtl a\nmap_Kd bad.png\n");
  expect_error(obj, mtl, 2, 8, "not a PNG or JPEG image");
  // Materials no face uses are not converted, so their textures are not read.
  write("m.mtl", "newmtl a\nKd 1 1 1\nnewmtl unused\nmap_Kd nowhere.png\n");
  load(obj);
  EXPECT_EQ(m_scene.geometry.triangles.size(), 1u);
}

TEST_F(ObjMtl, NonFiniteMaterialValue) {
  const std::string mtl = write("m.mtl", "newmtl a\nKd 1 1 1\nNs 1e999\n");
  expect_error(std::string("mtllib m.mtl\n") + kTriangle + "usemtl a\nf 1 2 3\n", mtl, 3, 1,
               "Ns of material 'a' is not a finite number");
}

}  // namespace
}  // namespace raylab
