// load_gltf: geometry of every index type, node transforms composed as computed by hand, the
// camera, materials and textures (data: URIs, files, GLB buffer views) and every kind of invalid
// input refused with an InputError that says where.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "gltf_test_util.h"
#include "io_test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/gltf_loader.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using Bytes = std::vector<unsigned char>;

using test::base64;
using test::GltfDoc;
using test::kFloat;
using test::kUnsignedByte;
using test::kUnsignedInt;
using test::kUnsignedShort;
using test::put32;

// A 2 x 1 PNG, left texel red, right texel blue.
Bytes red_blue_png() {
  const unsigned char rgb[] = {255, 0, 0, 0, 0, 255};
  return test::png_bytes(2, 1, rgb);
}

// Builds a glTF document and its one binary buffer.
class Gltf : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(m_dir); }

  std::string write(const fs::path& path, const Bytes& bytes) { return test::write_bytes(path, bytes); }
  std::string write(const fs::path& path, const std::string& text) { return test::write_text(path, text); }

  void load(GltfDoc& doc, const GltfLoadOptions& options = {}) {
    m_path = write(m_dir / "scene.gltf", doc.gltf_text());
    load_gltf(m_path, m_scene, options);
  }

  // Loads `path`, which must fail with an InputError naming it and containing `fragment`.
  void expect_error_in(const std::string& path, const std::string& fragment, const GltfLoadOptions& options = {}) {
    try {
      load_gltf(path, m_scene, options);
      ADD_FAILURE() << "no error for " << path;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }
  void expect_error(GltfDoc& doc, const std::string& fragment, const GltfLoadOptions& options = {}) {
    m_path = write(m_dir / "scene.gltf", doc.gltf_text());
    expect_error_in(m_path, fragment, options);
  }
  // Loads `path`, which must fail with a message that starts with `prefix` (the file and where
  // in it).
  void expect_error_at(const std::string& path, const std::string& prefix) {
    try {
      load_gltf(path, m_scene);
      ADD_FAILURE() << "no error for " << path;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what() << "\nexpected prefix: " << prefix;
    }
  }

  // The scene's material for triangle `t`.
  const Material& material_of_triangle(std::size_t t) const {
    return m_scene.materials[m_scene.objects[m_scene.geometry.triangle_objects[t]].material];
  }

  Scene m_scene;
  test::TempDir m_tmp{"gltf"};
  const fs::path m_root = m_tmp.path(), m_dir = m_root / "scene";
  std::string m_path;
};

void expect_near(Vec3 got, Vec3 want, float tolerance = 1e-6f) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

TEST_F(Gltf, IndexedTriangleWithEveryIndexType) {
  for (const int type : {kUnsignedByte, kUnsignedShort, kUnsignedInt}) {
    Scene scene;
    GltfDoc doc;
    const int mesh =
        doc.add_mesh({{"attributes", {{"POSITION", doc.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5}, 3)}}},
                      {"indices", doc.add_indices({2, 0, 1}, type)}});
    doc.j["scenes"] = json::array({{{"nodes", {doc.add_node({{"mesh", mesh}})}}}});
    const std::string path = write(m_dir / "t.gltf", doc.gltf_text());
    load_gltf(path, scene);
    ASSERT_EQ(scene.geometry.triangles.size(), 1u) << type;
    EXPECT_EQ(scene.geometry.triangles[0].p0, Vec3(0, 1, 0));
    EXPECT_EQ(scene.geometry.triangles[0].p1, Vec3(0, 0, 0));
    EXPECT_EQ(scene.geometry.triangles[0].p2, Vec3(1, 0, 0));
  }
}

TEST_F(Gltf, NonIndexedAndStrips) {
  GltfDoc doc;
  const int positions = doc.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, 3);
  const int list = doc.add_mesh({{"attributes", {{"POSITION", doc.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3)}}}});
  const int strip = doc.add_mesh({{"attributes", {{"POSITION", positions}}}, {"mode", 5}});
  doc.add_node({{"mesh", list}});
  doc.add_node({{"mesh", strip}});
  load(doc);  // no scenes: every root node
  const auto& t = m_scene.geometry.triangles;
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].p2, Vec3(0, 1, 0));
  // Strip 0 1 2 3: triangles (0 1 2) and (2 1 3), the second turned back to the same winding.
  EXPECT_EQ(t[1].p0, Vec3(0, 0, 0));
  EXPECT_EQ(t[2].p0, Vec3(0, 1, 0));
  EXPECT_EQ(t[2].p1, Vec3(1, 0, 0));
  EXPECT_EQ(t[2].p2, Vec3(1, 1, 0));
}

TEST_F(Gltf, NodeTransformsCompose) {
  GltfDoc doc;
  const int mesh = doc.add_triangle_mesh();
  const double s = std::sqrt(0.5);
  // Parent: 90 degrees about +Z. Child: translated by +X, holding the mesh.
  const int child = 1;
  doc.add_node({{"rotation", {0, 0, s, s}}, {"children", {child}}});
  doc.add_node({{"translation", {1, 0, 0}}, {"mesh", mesh}});
  // A root with a matrix (column-major): scale 2, then translate by (0, 0, 3).
  doc.add_node({{"matrix", {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 3, 1}}, {"mesh", mesh}});
  doc.j["scenes"] = json::array({{{"nodes", {0, 2}}}});
  load(doc, {.placement = Transform::translate(0, 0, 10)});
  const auto& t = m_scene.geometry.triangles;
  ASSERT_EQ(t.size(), 2u);
  // R(p + (1, 0, 0)) with R(x, y, z) = (-y, x, z), then + (0, 0, 10).
  expect_near(t[0].p0, {0, 1, 10});
  expect_near(t[0].p1, {0, 2, 10});
  expect_near(t[0].p2, {-1, 1, 10});
  expect_near(t[1].p0, {0, 0, 13});
  expect_near(t[1].p1, {2, 0, 13});
  expect_near(t[1].p2, {0, 2, 13});
}

TEST_F(Gltf, MirroringKeepsNormalsOutside) {
  GltfDoc doc;
  const int mesh = doc.add_triangle_mesh({{"attributes",
                                           {{"POSITION", doc.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3)},
                                            {"NORMAL", doc.add_floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, 3)}}}});
  doc.add_node({{"scale", {1, 1, -1}}, {"mesh", mesh}});
  load(doc);
  ASSERT_EQ(m_scene.geometry.triangles.size(), 1u);
  // Two corners swap so the winding (and the geometric normal) follows the mirrored normal.
  EXPECT_EQ(m_scene.geometry.triangles[0].p1, Vec3(0, 1, 0));
  EXPECT_EQ(m_scene.geometry.triangles[0].p2, Vec3(1, 0, 0));
  ASSERT_EQ(m_scene.geometry.triangle_normals.size(), 1u);
  expect_near(m_scene.geometry.triangle_normals[0][0], {0, 0, -1});
}

TEST_F(Gltf, DefaultSceneIsChosen) {
  GltfDoc doc;
  const int mesh = doc.add_triangle_mesh();
  doc.add_node({{"mesh", mesh}, {"translation", {5, 0, 0}}});
  doc.add_node({{"mesh", mesh}, {"translation", {7, 0, 0}}});
  doc.j["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1}}}});
  doc.j["scene"] = 1;
  load(doc);
  ASSERT_EQ(m_scene.geometry.triangles.size(), 1u);
  EXPECT_EQ(m_scene.geometry.triangles[0].p0, Vec3(7, 0, 0));
}

TEST_F(Gltf, CameraFromTheNodeWorldTransform) {
  GltfDoc doc;
  doc.add_triangle_mesh();
  doc.j["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}});
  const double s = std::sqrt(0.5);
  // 90 degrees about +Y turns the camera's -Z view direction into -X.
  doc.add_node({{"translation", {0, 0, 10}}, {"children", {1}}});
  doc.add_node({{"rotation", {0, s, 0, s}}, {"camera", 0}});
  doc.add_node({{"mesh", 0}});
  doc.j["scenes"] = json::array({{{"nodes", {0, 2}}}});

  load(doc);  // use_camera is off by default
  EXPECT_EQ(m_scene.camera.from, CameraSpec{}.from);
  EXPECT_FALSE(m_scene.camera_from_file);

  load(doc, {.placement = Transform::translate(0, 5, 0), .use_camera = true});
  const CameraSpec& c = m_scene.camera;
  expect_near(c.from, {0, 5, 10});
  expect_near(c.at, {-1, 5, 10});
  expect_near(c.up, {0, 1, 0});
  EXPECT_NEAR(c.vfov_degrees, 0.5 * 180.0 / std::numbers::pi, 1e-4);
  EXPECT_NEAR(c.hither, 0.1f, 1e-6f);
  EXPECT_TRUE(m_scene.camera_from_file);
}

TEST_F(Gltf, MaterialsAndADataUriTexture) {
  GltfDoc doc;
  doc.j["images"].push_back({{"uri", "data:image/png;base64," + base64(red_blue_png())}});
  doc.j["images"].push_back({{"uri", "data:image/png;base64," + base64(Bytes{1, 2, 3, 4})}});  // unused
  doc.j["textures"].push_back({{"source", 0}});
  doc.j["materials"].push_back({{"name", "plastic"},
                                {"pbrMetallicRoughness",
                                 {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}},
                                  {"metallicFactor", 0.0},
                                  {"roughnessFactor", 0.5},
                                  {"baseColorTexture", {{"index", 0}}}}}});
  doc.j["materials"].push_back(
      {{"pbrMetallicRoughness", {{"metallicFactor", 1.0}, {"roughnessFactor", 0.0}}}, {"emissiveFactor", {1, 0, 0}}});
  const int uv = doc.add_floats({0, 0, 1, 0, 0, 1}, 2);
  const int textured = doc.add_triangle_mesh({{"material", 0}});
  doc.j["meshes"][textured]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv;
  const int metal = doc.add_triangle_mesh({{"material", 1}});
  const int plain = doc.add_triangle_mesh();
  doc.add_node({{"mesh", textured}});
  doc.add_node({{"mesh", metal}});
  doc.add_node({{"mesh", plain}});
  load(doc);
  ASSERT_EQ(m_scene.geometry.triangles.size(), 3u);

  const Material& plastic = material_of_triangle(0);
  EXPECT_EQ(plastic.name, "plastic");
  expect_near(plastic.color, {0.2f, 0.4f, 0.6f});
  EXPECT_FLOAT_EQ(plastic.ks, 0.5f);
  EXPECT_FLOAT_EQ(plastic.shininess, 30.f);  // 2 / alpha^2 - 2 with alpha = 0.5^2
  EXPECT_FLOAT_EQ(plastic.reflectivity, 0.f);
  EXPECT_FLOAT_EQ(plastic.kd, 1.f);
  ASSERT_EQ(plastic.texture.kind, Texture::Kind::kImage);
  ASSERT_TRUE(plastic.texture.image);
  EXPECT_EQ(plastic.texture.image->texel(0, 0), Color(1, 0, 0));
  EXPECT_EQ(plastic.texture.image->texel(1, 0), Color(0, 0, 1));
  // glTF's v points down the image; raylab stores 1 - v.
  const auto& uvs = m_scene.geometry.triangle_uvs;
  ASSERT_EQ(uvs.size(), 3u);
  EXPECT_EQ(uvs[0][0].x, 0.f);
  EXPECT_EQ(uvs[0][0].y, 1.f);
  EXPECT_EQ(uvs[0][1].x, 1.f);
  EXPECT_EQ(uvs[0][1].y, 1.f);
  EXPECT_EQ(uvs[0][2].y, 0.f);

  const Material& mirror = material_of_triangle(1);
  EXPECT_EQ(mirror.name, "materials[1]");
  EXPECT_EQ(mirror.color, Color(1, 1, 1));  // glTF's default base colour
  EXPECT_FLOAT_EQ(mirror.reflectivity, 1.f);
  EXPECT_FLOAT_EQ(mirror.kd, 0.f);
  EXPECT_FLOAT_EQ(mirror.shininess, 1e4f);
  EXPECT_EQ(mirror.emission, Color(1, 0, 0));

  const Material& none = material_of_triangle(2);
  EXPECT_EQ(none.color, Material{}.color);
}

TEST_F(Gltf, MetallicRoughnessAndItsExtensionsKeepTheirValues) {
  // The path integrator reads the file's own model; Whitted keeps the Phong mapping above.
  GltfDoc doc;
  doc.j["extensionsUsed"] = {"KHR_materials_ior", "KHR_materials_transmission", "KHR_materials_emissive_strength"};
  doc.j["materials"].push_back(
      {{"pbrMetallicRoughness",
        {{"baseColorFactor", {0.9, 0.8, 0.7, 1.0}}, {"metallicFactor", 0.25}, {"roughnessFactor", 0.4}}},
       {"emissiveFactor", {1, 0.5, 0}},
       {"extensions",
        {{"KHR_materials_ior", {{"ior", 1.33}}},
         {"KHR_materials_transmission", {{"transmissionFactor", 0.8}}},
         {"KHR_materials_emissive_strength", {{"emissiveStrength", 6.0}}}}}});
  doc.j["materials"].push_back({{"pbrMetallicRoughness", {{"roughnessFactor", 0.1}}}});
  doc.add_node({{"mesh", doc.add_triangle_mesh({{"material", 0}})}});
  doc.add_node({{"mesh", doc.add_triangle_mesh({{"material", 1}})}});
  load(doc);
  const Material& water = material_of_triangle(0);
  EXPECT_EQ(water.model, MaterialModel::kMetallicRoughness);
  EXPECT_FLOAT_EQ(water.metallic, 0.25f);
  EXPECT_FLOAT_EQ(water.roughness, 0.4f);
  EXPECT_FLOAT_EQ(water.ior, 1.33f);
  EXPECT_FLOAT_EQ(water.transmission, 0.8f);
  EXPECT_FLOAT_EQ(water.emission_strength, 6.f);
  EXPECT_EQ(water.emission, Color(1, 0.5f, 0));
  // Without the extensions: the specification's defaults (ior 1.5, no transmission, strength 1).
  const Material& plain = material_of_triangle(1);
  EXPECT_EQ(plain.model, MaterialModel::kMetallicRoughness);
  EXPECT_FLOAT_EQ(plain.metallic, 1.f);
  EXPECT_FLOAT_EQ(plain.ior, 1.5f);
  EXPECT_FLOAT_EQ(plain.transmission, 0.f);
  EXPECT_FLOAT_EQ(plain.emission_strength, 1.f);
  // A value that is not a number is refused, naming where.
  GltfDoc bad;
  bad.j["materials"].push_back({{"extensions", {{"KHR_materials_ior", {{"ior", "thick"}}}}}});
  bad.add_node({{"mesh", bad.add_triangle_mesh({{"material", 0}})}});
  expect_error(bad, "extensions.KHR_materials_ior.ior must be a finite number");
}

TEST_F(Gltf, ImageFileNextToTheGltf) {
  write(m_dir / "tex.png", red_blue_png());
  GltfDoc doc;
  doc.j["images"].push_back({{"uri", "tex.png"}});
  doc.j["textures"].push_back({{"source", 0}});
  doc.j["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}}});
  const int mesh = doc.add_triangle_mesh({{"material", 0}});
  doc.j["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_1"] = doc.add_floats({0, 0, 1, 0, 0, 1}, 2);
  doc.add_node({{"mesh", mesh}});
  load(doc);
  ASSERT_TRUE(material_of_triangle(0).texture.image);
  EXPECT_EQ(material_of_triangle(0).texture.image->width(), 2);
  ASSERT_EQ(m_scene.geometry.triangle_uvs.size(), 1u);
  EXPECT_EQ(m_scene.geometry.triangle_uvs[0][1].x, 1.f);  // TEXCOORD_1, as the texture asks
}

TEST_F(Gltf, BinaryGlbWithAnImageInABufferView) {
  GltfDoc doc;
  const int view = doc.add_view(red_blue_png());
  doc.j["images"].push_back({{"bufferView", view}, {"mimeType", "image/png"}});
  doc.j["textures"].push_back({{"source", 0}});
  doc.j["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  const int mesh = doc.add_triangle_mesh({{"material", 0}});
  doc.j["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_0"] = doc.add_floats({0, 0, 1, 0, 0, 1}, 2);
  doc.add_node({{"mesh", mesh}, {"translation", {0, 0, -2}}});
  const std::string path = write(m_dir / "scene.glb", doc.glb());
  load_gltf(path, m_scene);
  ASSERT_EQ(m_scene.geometry.triangles.size(), 1u);
  EXPECT_EQ(m_scene.geometry.triangles[0].p1, Vec3(1, 0, -2));
  ASSERT_TRUE(material_of_triangle(0).texture.image);
  EXPECT_EQ(material_of_triangle(0).texture.image->texel(1, 0), Color(0, 0, 1));
}

TEST_F(Gltf, IndexOutOfRange) {
  GltfDoc doc;
  doc.add_mesh({{"attributes", {{"POSITION", doc.add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3)}}},
                {"indices", doc.add_indices({0, 1, 812}, kUnsignedShort)}});
  doc.add_node({{"mesh", 0}});
  expect_error(doc, "meshes[0].primitives[0]: index 812 out of range (vertex count 3)");
}

TEST_F(Gltf, BadAccessors) {
  {
    GltfDoc doc;
    doc.add_mesh({{"attributes", {{"POSITION", 7}}}});
    doc.add_node({{"mesh", 0}});
    expect_error(doc, "meshes[0].primitives[0] POSITION: accessor index 7 out of range (the file has 0)");
  }
  {
    GltfDoc doc;  // 4 elements of 12 bytes in a 36-byte view
    const int view = doc.add_view(Bytes(36, 0));
    doc.add_mesh({{"attributes", {{"POSITION", doc.add_accessor(view, kFloat, 4, "VEC3")}}}});
    doc.add_node({{"mesh", 0}});
    expect_error(doc, "accessors[0] (POSITION of meshes[0].primitives[0]): 4 elements from byte 0 do not fit");
  }
  {
    GltfDoc doc;
    doc.add_mesh(
        {{"attributes", {{"POSITION", doc.add_accessor(doc.add_view(Bytes(36, 0)), kUnsignedShort, 3, "VEC3")}}}});
    doc.add_node({{"mesh", 0}});
    expect_error(doc, "component type UNSIGNED_SHORT is not valid for POSITION");
  }
  {
    GltfDoc doc;  // a view past the end of its buffer
    doc.add_triangle_mesh();
    doc.j["bufferViews"][0]["byteLength"] = 400;
    doc.add_node({{"mesh", 0}});
    expect_error(doc, "bufferViews[0]: bytes 0 to 400 lie outside buffers[0]");
  }
  {
    GltfDoc doc;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    doc.add_mesh({{"attributes", {{"POSITION", doc.add_floats({0, 0, 0, 1, nan, 0, 0, 1, 0}, 3)}}}});
    doc.add_node({{"mesh", 0}});
    expect_error(doc, "meshes[0].primitives[0]: POSITION 1 is not finite");
  }
}

TEST_F(Gltf, NodeCycle) {
  GltfDoc doc;
  doc.add_triangle_mesh();
  doc.add_node({{"children", {1}}});
  doc.add_node({{"children", {0}}, {"mesh", 0}});
  doc.j["scenes"] = json::array({{{"nodes", {0}}}});
  expect_error(doc, "nodes[0]: reached twice in the node hierarchy");
}

TEST_F(Gltf, UriOutsideTheFolderIsRefused) {
  GltfDoc doc;
  doc.add_triangle_mesh();
  doc.add_node({{"mesh", 0}});
  write(m_root / "outside.bin", doc.bin);
  for (const std::string& uri :
       std::vector<std::string>{"../outside.bin", "%2E%2E/outside.bin", (m_root / "outside.bin").string()}) {
    doc.j["buffers"] = json::array({{{"byteLength", doc.bin.size()}, {"uri", uri}}});
    expect_error(doc, "leaves the folder of the glTF file");
  }
  // Allowed on request; the same file inside the folder needs nothing.
  load(doc, {.allow_outside_paths = true});
  EXPECT_EQ(m_scene.geometry.triangles.size(), 1u);
  write(m_dir / "inside.bin", doc.bin);
  doc.j["buffers"] = json::array({{{"byteLength", doc.bin.size()}, {"uri", "inside.bin"}}});
  load(doc);
  EXPECT_EQ(m_scene.geometry.triangles.size(), 2u);
  // Images too, even one that no material uses (tinygltf would read it).
  write(m_root / "outside.png", red_blue_png());
  doc.j["images"].push_back({{"uri", "../outside.png"}});
  expect_error(doc, "uri '../outside.png' leaves the folder");
}

TEST_F(Gltf, MissingBufferFile) {
  GltfDoc doc;
  doc.add_triangle_mesh();
  doc.j["buffers"] = json::array({{{"byteLength", doc.bin.size()}, {"uri", "missing.bin"}}});
  expect_error(doc, "missing.bin");
}

TEST_F(Gltf, ImageThatIsNotAnImage) {
  GltfDoc doc;
  doc.j["images"].push_back({{"uri", "data:image/png;base64," + base64(Bytes{'n', 'o', 'p', 'e'})}});
  doc.j["textures"].push_back({{"source", 0}});
  doc.j["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  const int mesh = doc.add_triangle_mesh({{"material", 0}});
  doc.j["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_0"] = doc.add_floats({0, 0, 1, 0, 0, 1}, 2);
  doc.add_node({{"mesh", mesh}});
  expect_error(doc, "images[0]: not a PNG or JPEG image");
  // A texture without the texture coordinates it reads.
  doc.j["images"][0]["uri"] = "data:image/png;base64," + base64(red_blue_png());
  doc.j["meshes"][mesh]["primitives"][0]["attributes"].erase("TEXCOORD_0");
  expect_error(doc, "reads TEXCOORD_0, which the primitive lacks");
}

TEST_F(Gltf, RequiredExtensionIsRefused) {
  GltfDoc doc;
  doc.add_triangle_mesh();
  doc.j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  expect_error(doc, "needs extension KHR_draco_mesh_compression");
}

// glTF 1.0 as collada2gltf wrote it: dictionaries keyed by name where glTF 2.0 has arrays.
// tinygltf skips them without a word, which left "the mesh has no faces".
const char* const kGltf1Body =
    "  \"scene\": \"defaultScene\",\n"
    "  \"scenes\": {\"defaultScene\": {\"nodes\": [\"node_1\"]}},\n"
    "  \"nodes\": {\"node_1\": {\"meshes\": [\"mesh_1\"]}},\n"
    "  \"meshes\": {\"mesh_1\": {\"primitives\": [{\"attributes\": {\"POSITION\": \"accessor_1\"}, \"mode\": 4}]}},\n"
    "  \"techniques\": {\"technique_1\": {\"program\": \"program_1\"}}\n"
    "}\n";

TEST_F(Gltf, Gltf1IsRefusedByItsVersion) {
  const std::string head = "{\n  \"asset\": {\n    \"generator\": \"collada2gltf@f356b99\",\n    \"version\": ";
  const std::string path = write(m_dir / "duck.gltf", head + "\"1.0\"\n  },\n" + kGltf1Body);
  expect_error_at(path, path +
                            ":4:5: asset.version is '1.0': this is glTF 1.0, which raylab does not read (convert "
                            "it to glTF 2.0 first, e.g. with gltf-pipeline)");
  // Early exporters wrote the version as a number.
  const std::string number = write(m_dir / "number.gltf", head + "1\n  },\n" + kGltf1Body);
  expect_error_at(number, number + ":4:5: asset.version is '1': this is glTF 1.0");
}

TEST_F(Gltf, Gltf1WithoutAVersionIsKnownByItsDictionaries) {
  // glTF 1.0 files may have no asset at all; tinygltf then said only that "asset" was missing.
  const std::string path = write(m_dir / "old.gltf", std::string("{\n") + kGltf1Body);
  expect_error_at(path,
                  path + ":5:3: \"meshes\" is an object keyed by name: this is glTF 1.0, which raylab does not read");
  // Only glTF 1.0 has shader techniques.
  const std::string shaders =
      write(m_dir / "shaders.gltf", "{\"asset\": {}, \"techniques\": {}, \"meshes\": [], \"nodes\": []}");
  expect_error_at(shaders, shaders + ":1:15: \"techniques\" is a glTF 1.0 property: this is glTF 1.0");
}

TEST_F(Gltf, BinaryGltf1IsRefused) {
  // A KHR_binary_glTF file: version 1, then the length, the content length and its format (0: JSON).
  Bytes glb = {'g', 'l', 'T', 'F'};
  put32(glb, 1);
  put32(glb, 24);
  put32(glb, 4);
  put32(glb, 0);
  glb.insert(glb.end(), {'{', '}', ' ', ' '});
  const std::string path = write(m_dir / "old.glb", glb);
  expect_error_at(path, path + ": byte 4: glTF binary version 1: this is glTF 1.0, which raylab does not read");
}

TEST_F(Gltf, VersionsOtherThan2AreRefusedByName) {
  GltfDoc doc;
  doc.add_node({{"mesh", doc.add_triangle_mesh()}});
  doc.j["asset"]["version"] = "3.0";
  expect_error(doc, "asset.version is '3.0': raylab reads glTF 2.0 only");
  doc.j["asset"]["version"] = "two";
  expect_error(doc, "asset.version is 'two', which is not a glTF version (glTF 2.0 files say \"2.0\")");
  doc.j["asset"]["version"] = 2;
  expect_error(doc, "asset.version is '2', a number: glTF writes the version as a string (\"2.0\")");
  // Any 2.x is glTF 2.0: minor versions only add what a 2.0 reader may ignore.
  doc.j["asset"]["version"] = "2.1";
  load(doc);
  EXPECT_EQ(m_scene.geometry.triangles.size(), 1u);
}

TEST_F(Gltf, ObjectsWhereGltf2HasArraysAreRefused) {
  GltfDoc doc;
  const int mesh = doc.add_triangle_mesh();
  doc.j["nodes"] = {{"root", {{"mesh", mesh}}}};
  expect_error(doc, "nodes: an object keyed by name, where glTF 2.0 has an array");
}

TEST_F(Gltf, DracoCompressionIsNamed) {
  // What a Draco exporter writes: the compressed bytes in a buffer view of their own, accessors
  // that describe the decoded data and have no bufferView, and Draco in extensionsRequired.
  // tinygltf refused such files as "accessor[1] invalid bufferView".
  GltfDoc doc;
  const int mesh = doc.add_triangle_mesh();
  doc.add_node({{"mesh", mesh}});
  const json uncompressed = doc.j["accessors"];
  for (json& a : doc.j["accessors"]) a.erase("bufferView");
  const int compressed = doc.add_view(Bytes(16, 0xAB));
  doc.j["meshes"][mesh]["primitives"][0]["extensions"] = {
      {"KHR_draco_mesh_compression", {{"bufferView", compressed}, {"attributes", {{"POSITION", 0}}}}}};
  doc.j["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  doc.j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  expect_error(doc,
               "extensionsRequired: the file needs extension KHR_draco_mesh_compression (Draco mesh compression), "
               "which raylab does not support (export the model again without it)");
  expect_error_at(m_path, m_path + ":1:");  // at its line and column in a .gltf
  const std::string glb = write(m_dir / "draco.glb", doc.glb());
  expect_error_at(glb, glb + ": extensionsRequired: the file needs extension KHR_draco_mesh_compression");
  // Draco used but not listed as required, and no uncompressed copy: the primitive is named.
  doc.j.erase("extensionsRequired");
  expect_error(doc,
               "meshes[0].primitives[0]: compressed with KHR_draco_mesh_compression, which raylab does not decode, "
               "and the file holds no uncompressed copy");
  // With the uncompressed copy that a file not requiring Draco must hold, that copy is read.
  doc.j["accessors"] = uncompressed;
  load(doc);
  EXPECT_EQ(m_scene.geometry.triangles.size(), 1u);
}

TEST_F(Gltf, EveryRequiredExtensionIsNamedAndUsedOnesAreIgnored) {
  GltfDoc doc;
  doc.add_node({{"mesh", doc.add_triangle_mesh()}});
  doc.j["extensionsUsed"] = {"KHR_materials_variants", "EXT_meshopt_compression"};
  doc.j["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_materials_variants"};
  expect_error(doc,
               "needs extensions EXT_meshopt_compression (meshopt compression), KHR_materials_variants, which "
               "raylab does not support (export the model again without them)");
  // An extension that is used but not required may be ignored: the file is read without it.
  doc.j.erase("extensionsRequired");
  load(doc);
  EXPECT_EQ(m_scene.geometry.triangles.size(), 1u);
}

TEST_F(Gltf, GarbageGlbAndJson) {
  expect_error_in(
      write(m_dir / "noise.glb", Bytes{0x13, 0x37, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17}),
      "not a glTF binary");
  Bytes header = {'g', 'l', 'T', 'F'};
  put32(header, 2);
  put32(header, 1000);  // longer than the file
  put32(header, 4);
  put32(header, 0x4E4F534Au);
  header.insert(header.end(), {'{', '}', ' ', ' '});
  expect_error_in(write(m_dir / "long.glb", header), "byte 8: the header gives a length of 1000 bytes");
  header[8] = 24;
  header[9] = header[10] = header[11] = 0;
  header[12] = 200;  // JSON chunk longer than the file
  expect_error_in(write(m_dir / "chunk.glb", header), "the JSON chunk runs past the end");
  header[12] = 4;
  expect_error_in(write(m_dir / "empty.glb", header), "not a valid glTF file");  // {} has no asset
  GltfDoc doc;
  doc.add_triangle_mesh();
  Bytes glb = doc.glb();
  glb.erase(glb.end() - 8, glb.end());  // BIN chunk cut short
  glb[8] = static_cast<unsigned char>(glb.size());
  glb[9] = static_cast<unsigned char>(glb.size() >> 8);
  expect_error_in(write(m_dir / "cut.glb", glb), "the BIN chunk runs past the end");
  expect_error_in(write(m_dir / "bad.gltf", std::string("{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [")),
                  "not a valid glTF file");
  expect_error_in((m_dir / "missing.gltf").string(), "cannot open");
}

}  // namespace
}  // namespace raylab
