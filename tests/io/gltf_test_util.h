#pragma once
// Test helper: the pieces that glTF fixtures are made of, shared by the glTF test files: base64
// for data: URIs, PNG bytes encoded in memory, and a document builder (GltfDoc).

#include <stb/stb_image_write.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace raylab::test {

using Bytes = std::vector<unsigned char>;
using json = nlohmann::json;

/// `in` in base64 (RFC 4648, with padding), for data: URIs.
inline std::string base64(const std::vector<unsigned char>& in) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t{in[i]} << 16) | (i + 1 < in.size() ? std::uint32_t{in[i + 1]} << 8 : 0) |
                            (i + 2 < in.size() ? std::uint32_t{in[i + 2]} : 0);
    out += kDigits[(n >> 18) & 63];
    out += kDigits[(n >> 12) & 63];
    out += i + 1 < in.size() ? kDigits[(n >> 6) & 63] : '=';
    out += i + 2 < in.size() ? kDigits[n & 63] : '=';
  }
  return out;
}

/// glTF accessor component types.
inline constexpr int kUnsignedByte = 5121;
inline constexpr int kUnsignedShort = 5123;
inline constexpr int kUnsignedInt = 5125;
inline constexpr int kFloat = 5126;

/// Appends `v` little-endian.
inline void put32(Bytes& b, std::uint32_t v) {
  for (int s = 0; s < 32; s += 8) b.push_back(static_cast<unsigned char>(v >> s));
}

/// An 8-bit RGB PNG of `width` x `height` texels, `rgb` row by row from the top, as bytes.
inline std::vector<unsigned char> png_bytes(int width, int height, const unsigned char* rgb) {
  std::vector<unsigned char> out;
  const auto sink = [](void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<unsigned char>*>(context);
    bytes->insert(bytes->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
  };
  stbi_write_png_to_func(sink, &out, width, height, 3, rgb, width * 3);
  return out;
}

/// A glTF 2.0 document under construction: its JSON (`j`, open for tests to edit) and one
/// binary buffer (`bin`) that views, accessors and meshes are appended to.
class GltfDoc {
 public:
  GltfDoc() {
    j["asset"] = {{"version", "2.0"}};
    for (const char* array : {"bufferViews", "accessors", "meshes", "nodes", "materials", "textures", "images"}) {
      j[array] = json::array();
    }
  }

  // Appends raw bytes (4-aligned) as a buffer view; returns its index.
  int add_view(const Bytes& data) {
    while (bin.size() % 4 != 0) bin.push_back(0);
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", data.size()}});
    bin.insert(bin.end(), data.begin(), data.end());
    return static_cast<int>(j["bufferViews"].size()) - 1;
  }
  int add_accessor(int view, int component_type, std::size_t count, const char* type) {
    j["accessors"].push_back(
        {{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}});
    return static_cast<int>(j["accessors"].size()) - 1;
  }
  // Float vectors of `components` each ("VEC3" for 3).
  int add_floats(const std::vector<float>& values, int components) {
    Bytes data(values.size() * 4);
    std::memcpy(data.data(), values.data(), data.size());
    static const char* kTypes[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    return add_accessor(add_view(data), kFloat, values.size() / static_cast<std::size_t>(components),
                        kTypes[components]);
  }
  int add_indices(const std::vector<std::uint32_t>& indices, int component_type) {
    Bytes data;
    const int size = component_type == kUnsignedByte ? 1 : component_type == kUnsignedShort ? 2 : 4;
    for (std::uint32_t i : indices) {
      for (int b = 0; b < size; ++b) data.push_back(static_cast<unsigned char>(i >> (8 * b)));
    }
    return add_accessor(add_view(data), component_type, indices.size(), "SCALAR");
  }
  int add_mesh(const json& primitive) {
    j["meshes"].push_back({{"primitives", json::array({primitive})}});
    return static_cast<int>(j["meshes"].size()) - 1;
  }
  int add_node(const json& node) {
    j["nodes"].push_back(node);
    return static_cast<int>(j["nodes"].size()) - 1;
  }
  // The unit triangle (0,0,0), (1,0,0), (0,1,0) as a mesh with u16 indices; returns the mesh.
  int add_triangle_mesh(const json& extra = json::object()) {
    json primitive = {{"attributes", {{"POSITION", add_floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, 3)}}},
                      {"indices", add_indices({0, 1, 2}, kUnsignedShort)}};
    primitive.update(extra);
    return add_mesh(primitive);
  }

  // .gltf text, the buffer as a base64 data: URI (unless a buffer was set already).
  std::string gltf_text() {
    json doc = j;
    if (!doc.contains("buffers") && !bin.empty()) {
      doc["buffers"] =
          json::array({{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
    }
    return doc.dump();
  }

  // .glb bytes: 12-byte header, JSON chunk padded with spaces, BIN chunk padded with zeros.
  Bytes glb() {
    json doc = j;
    doc["buffers"] = json::array({{{"byteLength", bin.size()}}});
    std::string text = doc.dump();
    while (text.size() % 4 != 0) text += ' ';
    Bytes payload = bin;
    while (payload.size() % 4 != 0) payload.push_back(0);
    Bytes out = {'g', 'l', 'T', 'F'};
    put32(out, 2);
    put32(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + payload.size()));
    put32(out, static_cast<std::uint32_t>(text.size()));
    put32(out, 0x4E4F534Au);
    out.insert(out.end(), text.begin(), text.end());
    put32(out, static_cast<std::uint32_t>(payload.size()));
    put32(out, 0x004E4942u);
    out.insert(out.end(), payload.begin(), payload.end());
    return out;
  }

  json j;
  Bytes bin;
};

}  // namespace raylab::test
