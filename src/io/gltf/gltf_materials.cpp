#include "gltf_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

namespace raylab::gltf_detail {
namespace {

namespace fs = std::filesystem;

// Metallic/roughness onto Phong/Whitted, roughly (a Phong lobe cannot be a GGX lobe):
//  - shininess: the Phong exponent whose lobe matches a Beckmann lobe of the same width,
//    n = 2 / alpha^2 - 2 with alpha = roughness^2 (Walter et al. 2007), kept in [1, 10000];
//  - ks = 1 - roughness: smooth surfaces show sharp, strong highlights, rough ones none;
//  - reflectivity = metallic x (1 - roughness): smooth metals are mirrors, rough metals and all
//    dielectrics are not (a Whitted mirror ray has no blur to offer them);
//  - kd = 1 - reflectivity: what a mirror reflects it does not also scatter.
void map_metallic_roughness(double metallic, double roughness, Material& out) {
  const double alpha = roughness * roughness;
  const double exponent = alpha > 0.0 ? 2.0 / (alpha * alpha) - 2.0 : 1e4;
  out.shininess = static_cast<float>(std::clamp(exponent, 1.0, 1e4));
  out.ks = static_cast<float>(1.0 - roughness);
  out.reflectivity = static_cast<float>(metallic * (1.0 - roughness));
  out.kd = 1.f - out.reflectivity;
}

// The number `key` of material extension `extension` (KHR_materials_ior's "ior", say):
// nullopt when the material does not use the extension or the extension does not give it, NaN
// when it gives something that is not a finite number.
std::optional<double> extension_number(const tinygltf::Material& in, const std::string& extension,
                                       const std::string& key) {
  const auto it = in.extensions.find(extension);
  if (it == in.extensions.end() || !it->second.IsObject() || !it->second.Has(key)) return std::nullopt;
  const tinygltf::Value& v = it->second.Get(key);
  if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) return std::nan("");
  return v.GetNumberAsDouble();
}

// glTF's own default (white, fully metallic, fully rough) would render as a black shape with a
// broad highlight in a Whitted tracer; raylab's matte default is what a user expects here.
Material default_material() {
  Material m;
  m.name = "default";
  return m;
}

}  // namespace

std::uint32_t GltfReader::object_for(int index, const std::string& user) {
  if (index != -1) check_index(index, m_model.materials.size(), user + ".material", "material");
  const std::size_t slot = static_cast<std::size_t>(index + 1);
  if (m_objects.empty()) {
    m_objects.resize(m_model.materials.size() + 1);
    m_uv_set.assign(m_model.materials.size() + 1, -1);
  }
  if (!m_objects[slot]) {
    Material material = index == -1 ? default_material() : convert_material(index);
    const std::string name = fs::path(m_path).stem().string() + "/" + material.name;
    m_objects[slot] = m_scene.add_object(name, m_scene.add_material(std::move(material)));
  }
  return *m_objects[slot];
}

Material GltfReader::convert_material(int index) {
  const std::string element = "materials[" + std::to_string(index) + "]";
  const tinygltf::Material& in = m_model.materials[static_cast<std::size_t>(index)];
  const tinygltf::PbrMetallicRoughness& pbr = in.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() != 4 || !all_finite(pbr.baseColorFactor)) {
    fail(element, "baseColorFactor must be 4 finite numbers");
  }
  if (in.emissiveFactor.size() != 3 || !all_finite(in.emissiveFactor))
    fail(element, "emissiveFactor must be 3 finite numbers");
  if (!std::isfinite(pbr.metallicFactor) || !std::isfinite(pbr.roughnessFactor)) {
    fail(element, "metallicFactor and roughnessFactor must be finite");
  }
  Material out;
  out.name = in.name.empty() ? element : in.name;
  const auto& c = pbr.baseColorFactor;
  out.color = {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
  map_metallic_roughness(std::clamp(pbr.metallicFactor, 0.0, 1.0), std::clamp(pbr.roughnessFactor, 0.0, 1.0), out);
  const auto& e = in.emissiveFactor;
  out.emission = {static_cast<float>(e[0]), static_cast<float>(e[1]), static_cast<float>(e[2])};
  // The physically based model keeps the file's values (the path integrator reads them; Whitted
  // reads the Phong members above). The extensions' defaults are the specification's.
  out.model = MaterialModel::kMetallicRoughness;
  out.metallic = static_cast<float>(std::clamp(pbr.metallicFactor, 0.0, 1.0));
  out.roughness = static_cast<float>(std::clamp(pbr.roughnessFactor, 0.0, 1.0));
  const auto number = [&](const std::string& extension, const std::string& key, double fallback) {
    const std::optional<double> v = extension_number(in, extension, key);
    if (!v) return fallback;
    if (std::isnan(*v)) fail(element, "extensions." + extension + "." + key + " must be a finite number");
    return *v;
  };
  out.transmission =
      static_cast<float>(std::clamp(number("KHR_materials_transmission", "transmissionFactor", 0.0), 0.0, 1.0));
  out.emission_strength =
      static_cast<float>(std::max(0.0, number("KHR_materials_emissive_strength", "emissiveStrength", 1.0)));
  // ior 0 is the extension's way to say "a perfect reflector" (no transmission); raylab's
  // dielectrics need an index above 1.
  if (const double ior = number("KHR_materials_ior", "ior", 1.5); ior >= 1.0) out.ior = static_cast<float>(ior);
  // Blended alpha is see-through coverage: light passes straight on (ior 1), not refracted.
  if (in.alphaMode == "BLEND") {
    out.transmittance = static_cast<float>(1.0 - std::clamp(c[3], 0.0, 1.0));
    out.ior = 1.f;
  }
  constexpr TextureEncoding kSrgb = TextureEncoding::kSrgb, kLinear = TextureEncoding::kLinear;
  const auto map = [&](const auto& info, const std::string& name, TextureEncoding encoding) {
    return info.index == -1 ? nullptr
                            : material_texture(index, info.index, info.texCoord, element + "." + name, encoding);
  };
  if (auto image = map(pbr.baseColorTexture, "pbrMetallicRoughness.baseColorTexture", kSrgb))
    out.texture = Texture::from_image(std::move(image));
  out.maps.metallic_roughness =
      map(pbr.metallicRoughnessTexture, "pbrMetallicRoughness.metallicRoughnessTexture", kLinear);
  out.maps.emission = map(in.emissiveTexture, "emissiveTexture", kSrgb);
  out.maps.normal = map(in.normalTexture, "normalTexture", kLinear);
  out.maps.normal_scale = static_cast<float>(in.normalTexture.scale);
  // KHR_materials_transmission's texture is a plain JSON object inside the extension.
  if (const auto it = in.extensions.find("KHR_materials_transmission");
      it != in.extensions.end() && it->second.IsObject() && it->second.Has("transmissionTexture")) {
    const std::string where = element + ".extensions.KHR_materials_transmission.transmissionTexture";
    const tinygltf::Value& info = it->second.Get("transmissionTexture");
    const auto integer = [&](const char* key, int fallback) {
      if (!info.Has(key)) return fallback;
      const tinygltf::Value& v = info.Get(key);
      if (!v.IsInt()) fail(where, std::string(key) + " must be an integer");
      return v.Get<int>();
    };
    if (!info.IsObject() || !info.Has("index")) fail(where, "must be an object with an index");
    out.maps.transmission = material_texture(index, integer("index", -1), integer("texCoord", 0), where, kLinear);
  }
  return out;
}

std::shared_ptr<const TextureImage> GltfReader::material_texture(int material, int texture_index, int tex_coord,
                                                                 const std::string& element, TextureEncoding encoding) {
  if (tex_coord < 0) fail(element, "texCoord must be >= 0");
  int& set = m_uv_set[static_cast<std::size_t>(material + 1)];
  if (set == -1) {
    set = tex_coord;
  } else if (set != tex_coord) {
    warn(element + ": reads TEXCOORD_" + std::to_string(tex_coord) +
         ", but raylab keeps one set per material: it reads TEXCOORD_" + std::to_string(set));
  }
  return texture(texture_index, element, encoding);
}

}  // namespace raylab::gltf_detail
