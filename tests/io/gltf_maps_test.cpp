// load_gltf's texture maps beyond the colour: metallicRoughnessTexture, emissiveTexture,
// normalTexture (with its scale) and KHR_materials_transmission's transmissionTexture, each in its
// MaterialMaps member with its encoding (sRGB for colours, linear for data), the one TEXCOORD set
// a material keeps, every malformed reference refused naming its element, and the loss that
// convert reports for maps a format cannot carry.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../test_util.h"
#include "gltf_test_util.h"
#include "io_test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/format_losses.h"
#include "raylab/io/gltf_loader.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using Bytes = std::vector<unsigned char>;

using test::base64;

/// A 1 x 1 8-bit RGB PNG holding the texel (r, g, b), as a data: URI.
std::string png_uri(unsigned char r, unsigned char g, unsigned char b) {
  const unsigned char rgb[] = {r, g, b};
  return "data:image/png;base64," + base64(test::png_bytes(1, 1, rgb));
}

/// An 8-bit value read as linear data: exactly s / 255, as the loader computes it.
float linear8(int s) { return static_cast<float>(s) / 255.f; }

/// An 8-bit value read as sRGB, from the IEC 61966-2-1 formula in double precision (independent
/// of the loader's float table, hence compared with a tolerance).
double srgb8(int s) {
  const double e = s / 255.0;
  return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

/// A glTF document of one triangle that carries two sets of texture coordinates, with
/// TEXCOORD_0 = (0,0) (1,0) (0,1) and TEXCOORD_1 = (0.25,0.25) (0.75,0.25) (0.25,0.75), all under
/// material 0; the caller adds the materials, textures and images.
class MapsDoc : public test::GltfDoc {
 public:
  MapsDoc() {
    const int position = add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3);
    const int uv0 = add_floats({0, 0, 1, 0, 0, 1}, 2);
    const int uv1 = add_floats({0.25f, 0.25f, 0.75f, 0.25f, 0.25f, 0.75f}, 2);
    add_node({{"mesh", add_mesh({{"attributes", {{"POSITION", position}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}}},
                                 {"material", 0}})}});
  }

  /// Adds a 1 x 1 image of texel (r, g, b) and a texture reading it; returns the texture index.
  int add_texture(unsigned char r, unsigned char g, unsigned char b) {
    j["images"].push_back({{"uri", png_uri(r, g, b)}});
    j["textures"].push_back({{"source", j["images"].size() - 1}});
    return static_cast<int>(j["textures"].size()) - 1;
  }
};

class GltfMaps : public ::testing::Test {
 protected:
  void load(MapsDoc& doc) {
    m_path = test::write_text(m_tmp.path() / "maps.gltf", doc.gltf_text());
    load_gltf(m_path, m_scene);
  }

  /// Loads `doc`, which must fail with an InputError naming the file and containing `fragment`.
  void expect_refused(MapsDoc& doc, const std::string& fragment) {
    m_path = test::write_text(m_tmp.path() / "maps.gltf", doc.gltf_text());
    Scene scene;
    try {
      load_gltf(m_path, scene);
      ADD_FAILURE() << "no error; expected: " << fragment;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), m_path);
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what() << "\nexpected: " << fragment;
    }
  }

  /// The material of the scene's one triangle.
  const Material& material() const {
    EXPECT_EQ(m_scene.geometry.triangles.size(), 1u);
    return m_scene.materials[m_scene.objects[m_scene.geometry.triangle_objects.at(0)].material];
  }

  Scene m_scene;
  test::TempDir m_tmp{"gltf-maps"};
  std::string m_path;
};

TEST_F(GltfMaps, EachMapLandsInItsMemberWithItsEncoding) {
  MapsDoc doc;
  // Every value but 0 and 255 reads differently as sRGB and as linear data, so each texel below
  // tells which decoding its map got.
  const int mr = doc.add_texture(0, 128, 64);
  const int emissive = doc.add_texture(128, 64, 255);
  const int normal = doc.add_texture(128, 128, 255);
  const int transmission = doc.add_texture(200, 10, 20);
  doc.j["extensionsUsed"] = {"KHR_materials_transmission"};
  doc.j["materials"].push_back(
      {{"pbrMetallicRoughness",
        {{"metallicFactor", 0.5}, {"roughnessFactor", 1.0}, {"metallicRoughnessTexture", {{"index", mr}}}}},
       {"emissiveFactor", {1, 1, 1}},
       {"emissiveTexture", {{"index", emissive}}},
       {"normalTexture", {{"index", normal}, {"scale", 0.5}}},
       {"extensions",
        {{"KHR_materials_transmission",
          {{"transmissionFactor", 1.0}, {"transmissionTexture", {{"index", transmission}}}}}}}});
  load(doc);
  const Material& m = material();
  const MaterialMaps& maps = m.maps;
  EXPECT_EQ(m.texture.kind, Texture::Kind::kNone);  // no base colour texture was given

  // Data maps: an 8-bit s reads as s / 255 exactly.
  ASSERT_TRUE(maps.metallic_roughness);
  EXPECT_EQ(maps.metallic_roughness->texel(0, 0), Color(0.f, linear8(128), linear8(64)));
  ASSERT_TRUE(maps.normal);
  EXPECT_EQ(maps.normal->texel(0, 0), Color(linear8(128), linear8(128), 1.f));
  EXPECT_FLOAT_EQ(maps.normal_scale, 0.5f);
  ASSERT_TRUE(maps.transmission);
  EXPECT_EQ(maps.transmission->texel(0, 0), Color(linear8(200), linear8(10), linear8(20)));

  // The emission map is a colour: sRGB-decoded.
  ASSERT_TRUE(maps.emission);
  const Color e = maps.emission->texel(0, 0);
  EXPECT_NEAR(e.x, srgb8(128), 1e-6);
  EXPECT_NEAR(e.y, srgb8(64), 1e-6);
  EXPECT_EQ(e.z, 1.f);
  EXPECT_GT(std::fabs(e.x - linear8(128)), 0.2f);  // far from the linear reading

  EXPECT_FALSE(maps.bump);  // glTF has no height maps

  // The maps vary the parameters as material_at and emitted_radiance document: roughness times
  // green, metallic times blue, transmission times red, emission times the map.
  const MaterialPoint p = material_at(m, 0.5f, 0.5f);
  EXPECT_FLOAT_EQ(p.roughness, 1.f * linear8(128));
  EXPECT_FLOAT_EQ(p.metallic, 0.5f * linear8(64));
  EXPECT_FLOAT_EQ(p.transmission, linear8(200));
  EXPECT_EQ(emitted_radiance(m, 0.5f, 0.5f), e);
}

TEST_F(GltfMaps, NormalScaleDefaultsToOne) {
  MapsDoc doc;
  doc.j["materials"].push_back({{"normalTexture", {{"index", doc.add_texture(128, 128, 255)}}}});
  load(doc);
  ASSERT_TRUE(material().maps.normal);
  EXPECT_EQ(material().maps.normal_scale, 1.f);
  // The other maps stay empty.
  EXPECT_FALSE(material().maps.metallic_roughness || material().maps.emission || material().maps.transmission);
}

TEST_F(GltfMaps, OneImageAsColourAndAsDataIsDecodedBothWays) {
  MapsDoc doc;
  const int tex = doc.add_texture(128, 64, 200);
  doc.j["materials"].push_back(
      {{"pbrMetallicRoughness",
        {{"baseColorTexture", {{"index", tex}}}, {"metallicRoughnessTexture", {{"index", tex}}}}},
       {"emissiveTexture", {{"index", tex}}},
       {"normalTexture", {{"index", tex}}}});
  load(doc);
  const Material& m = material();
  ASSERT_EQ(m.texture.kind, Texture::Kind::kImage);
  ASSERT_TRUE(m.texture.image);
  ASSERT_TRUE(m.maps.normal);
  const Color colour = m.texture.image->texel(0, 0);
  EXPECT_NEAR(colour.x, srgb8(128), 1e-6);
  EXPECT_NEAR(colour.y, srgb8(64), 1e-6);
  EXPECT_NEAR(colour.z, srgb8(200), 1e-6);
  EXPECT_EQ(m.maps.normal->texel(0, 0), Color(linear8(128), linear8(64), linear8(200)));
  EXPECT_NE(m.texture.image, m.maps.normal);
  // Each decoding is made once and shared by the references that ask for it.
  EXPECT_EQ(m.maps.emission, m.texture.image);
  EXPECT_EQ(m.maps.metallic_roughness, m.maps.normal);
}

TEST_F(GltfMaps, SecondTexCoordSetIsWarnedAboutAndTheFirstIsRead) {
  MapsDoc doc;
  // In the loader's order the metallic-roughness texture comes before the normal texture, so
  // TEXCOORD_1 is the material's set and the normal texture's TEXCOORD_0 is the odd one out.
  doc.j["materials"].push_back(
      {{"pbrMetallicRoughness",
        {{"metallicRoughnessTexture", {{"index", doc.add_texture(0, 255, 255)}, {"texCoord", 1}}}}},
       {"normalTexture", {{"index", doc.add_texture(128, 128, 255)}, {"texCoord", 0}}}});
  load(doc);
  ASSERT_EQ(m_scene.warnings.size(), 1u);
  const std::string& w = m_scene.warnings[0];
  EXPECT_EQ(w.rfind(m_path + ": materials[0].normalTexture: reads TEXCOORD_0", 0), 0u) << w;
  test::expect_contains_all(w, {"keeps one set per material", "it reads TEXCOORD_1"});
  // Both maps still load, and the triangle carries TEXCOORD_1 (v flipped to raylab's 1 - v).
  EXPECT_TRUE(material().maps.metallic_roughness);
  EXPECT_TRUE(material().maps.normal);
  const auto& uvs = m_scene.geometry.triangle_uvs;
  ASSERT_EQ(uvs.size(), 1u);
  EXPECT_EQ(uvs[0][0].x, 0.25f);
  EXPECT_EQ(uvs[0][0].y, 0.75f);
  EXPECT_EQ(uvs[0][1].x, 0.75f);
  EXPECT_EQ(uvs[0][2].y, 0.25f);
}

TEST_F(GltfMaps, OneTexCoordSetForAllMapsIsNoWarning) {
  MapsDoc doc;
  doc.j["materials"].push_back(
      {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", doc.add_texture(255, 0, 0)}, {"texCoord", 1}}}}},
       {"emissiveTexture", {{"index", 0}, {"texCoord", 1}}},
       {"normalTexture", {{"index", doc.add_texture(128, 128, 255)}, {"texCoord", 1}}}});
  load(doc);
  EXPECT_TRUE(m_scene.warnings.empty()) << m_scene.warnings.front();
  ASSERT_EQ(m_scene.geometry.triangle_uvs.size(), 1u);
  EXPECT_EQ(m_scene.geometry.triangle_uvs[0][1].x, 0.75f);  // TEXCOORD_1
}

TEST_F(GltfMaps, NegativeTexCoordIsRefusedNamingTheReference) {
  {
    MapsDoc doc;
    doc.j["materials"].push_back({{"normalTexture", {{"index", doc.add_texture(128, 128, 255)}, {"texCoord", -1}}}});
    expect_refused(doc, "materials[0].normalTexture: texCoord must be >= 0");
  }
  {
    MapsDoc doc;
    doc.j["materials"].push_back(
        {{"emissiveFactor", {1, 1, 1}}, {"emissiveTexture", {{"index", doc.add_texture(1, 2, 3)}, {"texCoord", -2}}}});
    expect_refused(doc, "materials[0].emissiveTexture: texCoord must be >= 0");
  }
  {
    MapsDoc doc;
    doc.j["materials"].push_back(
        {{"extensions",
          {{"KHR_materials_transmission",
            {{"transmissionTexture", {{"index", doc.add_texture(9, 9, 9)}, {"texCoord", -1}}}}}}}});
    expect_refused(doc,
                   "materials[0].extensions.KHR_materials_transmission.transmissionTexture: texCoord must be >= 0");
  }
}

TEST_F(GltfMaps, MalformedTransmissionTextureIsRefusedNamingIt) {
  const std::string where = "materials[0].extensions.KHR_materials_transmission.transmissionTexture: ";
  // Not an object, or an object without an index (the number 3 is no textureInfo).
  const json bad[] = {3, "texture.png", {{"texCoord", 0}}, json::array({0})};
  for (const json& info : bad) {
    SCOPED_TRACE(info.dump());
    MapsDoc doc;
    doc.add_texture(1, 2, 3);
    doc.j["materials"].push_back({{"extensions", {{"KHR_materials_transmission", {{"transmissionTexture", info}}}}}});
    expect_refused(doc, where + "must be an object with an index");
  }
  // An index or texCoord that is not an integer.
  for (const json& info : {json{{"index", "zero"}}, json{{"index", 0.5}}, json{{"index", 0}, {"texCoord", "one"}}}) {
    SCOPED_TRACE(info.dump());
    MapsDoc doc;
    doc.add_texture(1, 2, 3);
    doc.j["materials"].push_back({{"extensions", {{"KHR_materials_transmission", {{"transmissionTexture", info}}}}}});
    expect_refused(doc, where + (info["index"].is_number_integer() ? "texCoord" : "index") + " must be an integer");
  }
}

TEST_F(GltfMaps, TextureIndexOutOfRangeIsRefusedNamingTheReference) {
  // The document holds one texture (index 0); each reference names texture 7.
  const auto refused = [&](const std::function<void(json&)>& set, const std::string& element) {
    SCOPED_TRACE(element);
    MapsDoc doc;
    doc.add_texture(1, 2, 3);
    json material = json::object();
    set(material);
    doc.j["materials"].push_back(material);
    expect_refused(doc, element + ".index: texture index 7 out of range (the file has 1)");
  };
  const json seven = {{"index", 7}};
  refused(
      [&](json& m) {
        m["pbrMetallicRoughness"] = {{"metallicRoughnessTexture", seven}};
      },
      "materials[0].pbrMetallicRoughness.metallicRoughnessTexture");
  refused([&](json& m) { m["emissiveTexture"] = seven; }, "materials[0].emissiveTexture");
  refused([&](json& m) { m["normalTexture"] = seven; }, "materials[0].normalTexture");
  refused(
      [&](json& m) {
        m["extensions"] = {{"KHR_materials_transmission", {{"transmissionTexture", seven}}}};
      },
      "materials[0].extensions.KHR_materials_transmission.transmissionTexture");
}

/// Whether `losses` holds `item`, for a message that shows them all.
::testing::AssertionResult has_loss(const std::vector<std::string>& losses, const std::string& item) {
  if (std::find(losses.begin(), losses.end(), item) != losses.end()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "no '" << item << "' in: " << losses_message("out", losses);
}

TEST_F(GltfMaps, ConvertingToObjOrNffReportsTheMapsAsALoss) {
  MapsDoc doc;
  doc.j["materials"].push_back({{"normalTexture", {{"index", doc.add_texture(128, 128, 255)}}}});
  load(doc);
  for (const char* extension : {".obj", ".nff"}) {
    SCOPED_TRACE(extension);
    EXPECT_TRUE(has_loss(format_losses(m_scene, extension, false), "texture maps beyond the colour of 1 material"));
  }
  // A second glTF (the same triangle, emission-mapped) adds a second material with maps.
  MapsDoc emissive;
  emissive.j["materials"].push_back({{"emissiveTexture", {{"index", emissive.add_texture(9, 9, 9)}}}});
  load(emissive);
  ASSERT_EQ(m_scene.materials.size(), 2u);
  EXPECT_TRUE(has_loss(format_losses(m_scene, ".obj", false), "texture maps beyond the colour of 2 materials"));
}

TEST_F(GltfMaps, ConvertingToJsonKeepsEightBitMapsAndReportsOthers) {
  MapsDoc doc;
  doc.j["materials"].push_back({{"normalTexture", {{"index", doc.add_texture(128, 128, 255)}}},
                                {"emissiveFactor", {1, 1, 1}},
                                {"emissiveTexture", {{"index", doc.add_texture(128, 64, 32)}}}});
  load(doc);
  // A scene file writes the maps as PNGs beside it: the loaded 8-bit maps come back exactly.
  for (const std::string& loss : format_losses(m_scene, ".json", false)) {
    EXPECT_EQ(loss.find("texture maps"), std::string::npos) << loss;
  }
  // A map that no 8-bit PNG gives back (0.3 is no s / 255) is lost, and reported.
  Material& m = m_scene.materials.at(m_scene.objects.at(m_scene.geometry.triangle_objects.at(0)).material);
  m.maps.normal = std::make_shared<const TextureImage>(1, 1, std::vector<Color>{{0.3f, 0.5f, 1.f}});
  EXPECT_TRUE(has_loss(format_losses(m_scene, ".json", false), "texture maps beyond the colour of 1 material"));
}

TEST_F(GltfMaps, ABaseColourTextureAloneIsNoMapsLoss) {
  MapsDoc doc;
  doc.j["materials"].push_back(
      {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", doc.add_texture(1, 2, 3)}}}}}});
  load(doc);
  // OBJ loses the image texture (no file name is left to write) but there are no maps to lose.
  const std::vector<std::string> losses = format_losses(m_scene, ".obj", false);
  EXPECT_TRUE(has_loss(losses, "1 image texture"));
  for (const std::string& loss : losses) EXPECT_EQ(loss.find("texture maps"), std::string::npos) << loss;
}

}  // namespace
}  // namespace raylab
