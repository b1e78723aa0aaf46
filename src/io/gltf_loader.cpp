#include "raylab/io/gltf_loader.h"

// tinygltf is one header; this is the one translation unit that compiles its implementation
// (Debian's libtinygltf-dev also ships a prebuilt libtinygltf.so, not used: its image loader
// decodes with stb_image before raylab could check an image's size). Without stb_image inside
// tinygltf, every image goes through the callback below and raylab's size-checked decoder
// (texture_io), and only for the images a material actually uses. JSON is nlohmann-json, which
// raylab already depends on. tiny_gltf.h lives in /usr/include, so its own warnings stay out of
// -Werror builds.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/io/read_file.h"
#include "raylab/io/scene_paths.h"
#include "raylab/io/texture_io.h"
#include "raylab/scene/mesh_builder.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

// glTF buffers are little-endian; they are read with memcpy straight into host numbers.
static_assert(std::endian::native == std::endian::little, "the glTF reader assumes a little-endian host");

// What the file-system and image callbacks share with the loader.
struct CallbackContext {
  std::string folder;  // absolute folder of the glTF file, without a trailing slash
  bool allow_outside = false;
  std::string refused;                                    // the first URI that leaves the folder, when not allowed
  std::map<int, std::vector<unsigned char>> image_bytes;  // encoded images given by URI, by index
};

// The folder prefix tinygltf puts in front of every URI (JoinPath adds one '/').
std::string folder_prefix(const CallbackContext& ctx) {
  return ctx.folder.ends_with('/') ? ctx.folder : ctx.folder + "/";
}

// The file a path from tinygltf stands for: tinygltf joins the folder and the %-decoded URI and
// asks for that; raylab resolves the URI part itself (an absolute URI stays absolute) and
// refuses it when it leaves the folder. Paths not under the folder are tinygltf's second guess,
// the working directory, which a glTF URI never means: they are not found.
std::optional<std::string> resolve_uri_path(CallbackContext& ctx, const std::string& joined) {
  const std::string prefix = folder_prefix(ctx);
  if (joined.rfind(prefix, 0) != 0) return std::nullopt;
  const std::string uri = joined.substr(prefix.size());
  const std::string resolved = resolve_scene_path(ctx.folder, uri, ctx.allow_outside);
  if (resolved.empty()) {
    if (ctx.refused.empty()) ctx.refused = uri;
    return std::nullopt;
  }
  return resolved;
}

// tinygltf's file-system callbacks: the containment check happens here, before any read.
bool uri_file_exists(const std::string& path, void* user) {
  const auto resolved = resolve_uri_path(*static_cast<CallbackContext*>(user), path);
  std::error_code ec;
  return resolved && fs::is_regular_file(*resolved, ec);
}

// No `~` or `$VAR` expansion: a URI is a path relative to the file, nothing else.
std::string uri_expand_path(const std::string& path, void*) { return path; }

bool uri_read_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const auto resolved = resolve_uri_path(*static_cast<CallbackContext*>(user), path);
  if (!resolved) {
    *err = "refused";
    return false;
  }
  std::ifstream in(*resolved, std::ios::binary);
  if (!in) {
    *err = "cannot open";
    return false;
  }
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

bool uri_write_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "raylab does not write glTF files";
  return false;
}

// tinygltf's image callback. Images given by URI (data: or a file) are kept encoded and decoded
// later, only if a material uses them. Images in buffer views are read later too, from the view
// once it is checked against its buffer: tinygltf hands this callback a pointer into the buffer
// without checking that the view lies inside it.
bool keep_image_bytes(tinygltf::Image* image, int index, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
  if (image->bufferView >= 0 || bytes == nullptr || size <= 0) return true;
  static_cast<CallbackContext*>(user)->image_bytes[index].assign(bytes, bytes + size);
  return true;
}

std::uint32_t read_le32(const unsigned char* p) {
  return std::uint32_t{p[0]} | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) | (std::uint32_t{p[3]} << 24);
}

// Checks the GLB container (header and chunk headers) and returns its length. tinygltf checks
// most of it, but reads the BIN chunk's 8-byte header without checking that it fits.
std::size_t checked_glb_length(const std::string& path, std::span<const unsigned char> bytes) {
  if (bytes.size() < 20)
    throw InputError(path, "too short for a glTF binary (" + std::to_string(bytes.size()) + " bytes)");
  if (const std::uint32_t version = read_le32(bytes.data() + 4); version != 2) {
    throw InputError::at_byte(path, 4, "glTF binary version " + std::to_string(version) + " (raylab reads version 2)");
  }
  const std::uint64_t length = read_le32(bytes.data() + 8);
  if (length > bytes.size() || length < 20) {
    throw InputError::at_byte(path, 8,
                              "the header gives a length of " + std::to_string(length) + " bytes; the file has " +
                                  std::to_string(bytes.size()));
  }
  const std::uint64_t json_end = 20 + std::uint64_t{read_le32(bytes.data() + 12)};
  if (read_le32(bytes.data() + 16) != 0x4E4F534Au) throw InputError::at_byte(path, 16, "the first chunk is not JSON");
  if (json_end > length) throw InputError::at_byte(path, 12, "the JSON chunk runs past the end of the file");
  if (json_end < length) {
    if (json_end + 8 > length) throw InputError::at_byte(path, json_end, "truncated chunk header");
    const std::uint64_t bin_end = json_end + 8 + read_le32(bytes.data() + json_end);
    if (bin_end > length) throw InputError::at_byte(path, json_end, "the BIN chunk runs past the end of the file");
    if (read_le32(bytes.data() + json_end + 4) != 0x004E4942u) {
      throw InputError::at_byte(path, json_end + 4, "the second chunk is not BIN");
    }
  }
  return static_cast<std::size_t>(length);
}

// tinygltf's messages end in newlines and may hold several; keep them on one line.
std::string one_line(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ';');
  return text;
}

// Parses the file with tinygltf through raylab's callbacks.
tinygltf::Model parse_gltf(const std::string& path, CallbackContext& ctx) {
  const std::string text = read_file(path);
  if (text.size() > std::numeric_limits<unsigned int>::max()) throw InputError(path, "larger than 4 GiB");
  tinygltf::TinyGLTF parser;
  parser.SetFsCallbacks({&uri_file_exists, &uri_expand_path, &uri_read_file, &uri_write_file, &ctx});
  parser.SetImageLoader(&keep_image_bytes, &ctx);
  tinygltf::Model model;
  std::string err, warn;
  const auto bytes = std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size());
  bool ok = false;
  if (text.rfind("glTF", 0) == 0) {
    const std::size_t length = checked_glb_length(path, bytes);
    ok = parser.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(length), ctx.folder);
  } else {
    const std::string ext = fs::path(path).extension().string();
    if (ext == ".glb" || ext == ".GLB") throw InputError::at_byte(path, 0, "not a glTF binary (no 'glTF' magic)");
    ok = parser.LoadASCIIFromString(&model, &err, &warn, text.data(), static_cast<unsigned int>(text.size()),
                                    ctx.folder);
  }
  if (!ctx.refused.empty()) {
    throw InputError(path, "uri '" + ctx.refused +
                               "' leaves the folder of the glTF file (reading files from "
                               "elsewhere needs allow_outside_paths)");
  }
  if (!ok) throw InputError(path, "not a valid glTF file: " + one_line(err.empty() ? "unknown error" : err));
  return model;
}

// Number of components of an accessor type; 0 for an unknown one.
int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;
  }
}

// Size in bytes of an accessor component type; 0 for one raylab never reads.
std::size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

// An accessor's elements, checked to lie inside their buffer view and buffer. `data` is null for
// an accessor without a buffer view, whose elements are all zero.
struct AccessorData {
  const unsigned char* data = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int component_type = 0;
  int components = 0;
  bool normalized = false;

  // Component `c` of element `i` as a number (normalised integers scaled to [0, 1]).
  double component(std::size_t i, int c) const {
    if (data == nullptr) return 0.0;
    const unsigned char* p = data + i * stride + static_cast<std::size_t>(c) * component_size(component_type);
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? p[0] / 255.0 : p[0];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
      }
      default: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
      }
    }
  }
};

// What a use of an accessor requires of it.
struct AccessorUse {
  const char* name;  // for messages: "POSITION", "indices"
  int type;
  std::initializer_list<int> component_types;
  bool normalized_integers = false;  // integer components must be normalised (texture coordinates)
};

std::string component_type_name(int t) {
  switch (t) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "FLOAT";
    default:
      return std::to_string(t);
  }
}

// The unit quaternion (x, y, z, w) as a rotation matrix.
Transform rotation_of(const std::vector<double>& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double x = q[0] / n, y = q[1] / n, z = q[2] / n, w = q[3] / n;
  return Transform::from_rows({1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0,  //
                               2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0,  //
                               2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0});
}

bool all_finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

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

// Turns a parsed, unchecked glTF model into raylab geometry, materials and camera.
class GltfReader {
 public:
  GltfReader(std::string path, const tinygltf::Model& model, CallbackContext& ctx, Scene& scene,
             const GltfLoadOptions& options)
      : m_path(std::move(path)), m_model(model), m_ctx(ctx), m_scene(scene), m_options(options) {}

  void read() {
    check_required_extensions();
    const std::vector<int> roots = root_nodes();
    traverse(roots);
    if (m_report.degenerate_dropped > 0) {
      warn(std::to_string(m_report.degenerate_dropped) + " zero-area triangles dropped");
    }
  }

 private:
  [[noreturn]] void fail(const std::string& element, const std::string& message) const {
    throw InputError(m_path, element + ": " + message);
  }

  void warn(const std::string& message) { m_scene.warnings.push_back(m_path + ": " + message); }

  // Checks that `index` names one of `size` elements of array `array`.
  void check_index(int index, std::size_t size, const std::string& element, const char* array) const {
    if (index < 0 || static_cast<std::size_t>(index) >= size) {
      fail(element, std::string(array) + " index " + std::to_string(index) + " out of range (the file has " +
                        std::to_string(size) + ")");
    }
  }

  // Extensions the file cannot be read without change geometry or images in ways raylab does not
  // know (Draco, meshopt, quantisation, Basis textures, texture transforms): refuse rather than
  // show something else.
  void check_required_extensions() const {
    for (const std::string& name : m_model.extensionsRequired) {
      fail("extensionsRequired", "the file needs extension " + name + ", which raylab does not support");
    }
  }

  // The default scene's nodes, or scene 0's, or, with no scenes, every node without a parent.
  std::vector<int> root_nodes() const {
    if (m_model.defaultScene >= 0 || !m_model.scenes.empty()) {
      const int scene = std::max(m_model.defaultScene, 0);
      check_index(scene, m_model.scenes.size(), "scene", "scene");
      return m_model.scenes[static_cast<std::size_t>(scene)].nodes;
    }
    std::vector<bool> is_child(m_model.nodes.size(), false);
    for (std::size_t i = 0; i < m_model.nodes.size(); ++i) {
      for (const int child : m_model.nodes[i].children) {
        check_index(child, m_model.nodes.size(), "nodes[" + std::to_string(i) + "].children", "node");
        is_child[static_cast<std::size_t>(child)] = true;
      }
    }
    std::vector<int> roots;
    for (std::size_t i = 0; i < is_child.size(); ++i) {
      if (!is_child[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
  }

  // Depth first, parents before children, without recursion (a hostile file can nest nodes
  // deeper than any stack). glTF nodes form trees: a node reached twice is an error, which also
  // catches cycles and the exponential blow-up of shared subtrees.
  void traverse(const std::vector<int>& roots) {
    std::vector<bool> visited(m_model.nodes.size(), false);
    std::vector<std::pair<int, Transform>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, m_options.placement);
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      const std::string element = "nodes[" + std::to_string(index) + "]";
      check_index(index, m_model.nodes.size(), element, "node");
      if (visited[static_cast<std::size_t>(index)]) {
        fail(element, "reached twice in the node hierarchy (a cycle, or a node with two parents)");
      }
      visited[static_cast<std::size_t>(index)] = true;
      const tinygltf::Node& node = m_model.nodes[static_cast<std::size_t>(index)];
      const Transform world = parent * local_transform(node, element);
      if (node.mesh >= 0 || node.mesh < -1) add_mesh(node.mesh, world, element);
      if (node.camera >= 0 || node.camera < -1) take_camera(node.camera, world, element);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
        stack.emplace_back(*child, world);
      }
    }
  }

  // A node's own transform: its matrix, or translation x rotation x scale.
  Transform local_transform(const tinygltf::Node& node, const std::string& element) const {
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16) fail(element, "matrix must have 16 numbers");
      if (!all_finite(node.matrix)) fail(element, "matrix has a non-finite number");
      const auto& m = node.matrix;  // column-major: row r, column c is m[4c + r]
      if (std::fabs(m[3]) > 1e-6 || std::fabs(m[7]) > 1e-6 || std::fabs(m[11]) > 1e-6 || std::fabs(m[15] - 1) > 1e-6) {
        fail(element, "matrix is not affine (its last row must be 0 0 0 1)");
      }
      return Transform::from_column_major(m.data());
    }
    Transform t;
    if (!node.translation.empty()) {
      if (node.translation.size() != 3 || !all_finite(node.translation))
        fail(element, "translation must be 3 finite numbers");
      t = Transform::translate(node.translation[0], node.translation[1], node.translation[2]);
    }
    if (!node.rotation.empty()) {
      if (node.rotation.size() != 4 || !all_finite(node.rotation)) fail(element, "rotation must be 4 finite numbers");
      const auto& q = node.rotation;
      if (!(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 0.0))
        fail(element, "rotation is a zero quaternion");
      t = t * rotation_of(q);
    }
    if (!node.scale.empty()) {
      if (node.scale.size() != 3 || !all_finite(node.scale)) fail(element, "scale must be 3 finite numbers");
      t = t * Transform::scale(node.scale[0], node.scale[1], node.scale[2]);
    }
    return t;
  }

  // The first perspective camera met becomes the scene's camera, when asked for.
  void take_camera(int index, const Transform& world, const std::string& element) {
    check_index(index, m_model.cameras.size(), element + ".camera", "camera");
    if (!m_options.use_camera || m_camera_taken) return;
    const std::string camera_element = "cameras[" + std::to_string(index) + "]";
    const tinygltf::Camera& camera = m_model.cameras[static_cast<std::size_t>(index)];
    if (camera.type != "perspective") {
      warn(camera_element + ": " + camera.type + " camera skipped (raylab has pinhole cameras only)");
      return;
    }
    const double yfov = camera.perspective.yfov;
    if (!(yfov > 0.0 && yfov < std::numbers::pi)) fail(camera_element, "yfov must be between 0 and pi radians");
    const double znear = camera.perspective.znear;
    if (!(znear >= 0.0 && std::isfinite(znear))) fail(camera_element, "znear must be a finite number >= 0");
    // glTF cameras look down their local -Z axis with +Y up.
    const Vec3 forward = world.vector({0.f, 0.f, -1.f});
    const Vec3 up = world.vector({0.f, 1.f, 0.f});
    const Vec3 from = world.point({0.f, 0.f, 0.f});
    if (!is_finite(from) || !(length(forward) > 0.f) || !(length(up) > 0.f) || !(length(cross(forward, up)) > 0.f)) {
      fail(element, "the camera's transform is degenerate");
    }
    CameraSpec& spec = m_scene.camera;
    spec.from = from;
    spec.at = from + normalize(forward);
    spec.up = normalize(up);
    spec.vfov_degrees = static_cast<float>(yfov * 180.0 / std::numbers::pi);
    spec.fov_span = CameraSpec::FovSpan::kImageEdges;
    spec.hither = static_cast<float>(znear) * length(forward);
    m_scene.camera_from_file = true;
    m_camera_taken = true;
  }

  // Accessor `index` for `use`, checked against its buffer view and buffer.
  AccessorData accessor(int index, const AccessorUse& use, const std::string& user) const {
    check_index(index, m_model.accessors.size(), user + " " + use.name, "accessor");
    const std::string element = "accessors[" + std::to_string(index) + "] (" + use.name + " of " + user + ")";
    const tinygltf::Accessor& a = m_model.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) fail(element, "sparse accessors are not supported");
    if (a.type != use.type) fail(element, "wrong type for " + std::string(use.name));
    if (std::find(use.component_types.begin(), use.component_types.end(), a.componentType) ==
        use.component_types.end()) {
      fail(element, "component type " + component_type_name(a.componentType) + " is not valid for " + use.name);
    }
    if (use.normalized_integers && a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !a.normalized) {
      fail(element, "integer " + std::string(use.name) + " must be normalized");
    }
    AccessorData out;
    out.count = a.count;
    out.component_type = a.componentType;
    out.components = component_count(a.type);
    out.normalized = a.normalized;
    const std::size_t element_size = component_size(a.componentType) * static_cast<std::size_t>(out.components);
    if (a.bufferView == -1) return out;  // all zeros, as the glTF specification says
    check_index(a.bufferView, m_model.bufferViews.size(), element + ".bufferView", "bufferView");
    const tinygltf::BufferView& view = m_model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::span<const unsigned char> bytes = view_bytes(a.bufferView);
    out.stride = view.byteStride != 0 ? view.byteStride : element_size;
    if (out.stride < element_size) {
      fail(element, "byteStride " + std::to_string(view.byteStride) + " of bufferViews[" +
                        std::to_string(a.bufferView) + "] is smaller than one element (" +
                        std::to_string(element_size) + " bytes)");
    }
    if (out.count > 0) {
      // The last element must end inside the view; computed without overflow.
      const bool fits = a.byteOffset <= bytes.size() && element_size <= bytes.size() - a.byteOffset &&
                        (out.count - 1) <= (bytes.size() - a.byteOffset - element_size) / out.stride;
      if (!fits) {
        fail(element, std::to_string(out.count) + " elements from byte " + std::to_string(a.byteOffset) +
                          " do not fit in bufferViews[" + std::to_string(a.bufferView) + "] (" +
                          std::to_string(bytes.size()) + " bytes)");
      }
    }
    out.data = bytes.data() + a.byteOffset;
    return out;
  }

  // The bytes of buffer view `index`, checked to lie inside its buffer.
  std::span<const unsigned char> view_bytes(int index) const {
    const std::string element = "bufferViews[" + std::to_string(index) + "]";
    const tinygltf::BufferView& view = m_model.bufferViews[static_cast<std::size_t>(index)];
    check_index(view.buffer, m_model.buffers.size(), element + ".buffer", "buffer");
    const std::vector<unsigned char>& data = m_model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
      fail(element, "bytes " + std::to_string(view.byteOffset) + " to " +
                        std::to_string(view.byteOffset + view.byteLength) + " lie outside buffers[" +
                        std::to_string(view.buffer) + "] (" + std::to_string(data.size()) + " bytes)");
    }
    return {data.data() + view.byteOffset, view.byteLength};
  }

  // `n`-component float vectors of an accessor, every value checked finite.
  std::vector<float> read_floats(const AccessorData& a, const std::string& element, const char* name) const {
    std::vector<float> out(a.count * static_cast<std::size_t>(a.components));
    for (std::size_t i = 0; i < a.count; ++i) {
      for (int c = 0; c < a.components; ++c) {
        const auto v = static_cast<float>(a.component(i, c));
        if (!std::isfinite(v)) fail(element, std::string(name) + " " + std::to_string(i) + " is not finite");
        out[i * static_cast<std::size_t>(a.components) + static_cast<std::size_t>(c)] = v;
      }
    }
    return out;
  }

  // The corner indices of a primitive's triangles, in triangle-list order.
  std::vector<std::uint32_t> triangle_corners(const tinygltf::Primitive& p, std::size_t vertex_count,
                                              const std::string& element) const {
    std::vector<std::uint32_t> indices;
    if (p.indices >= 0 || p.indices < -1) {
      const AccessorData a = accessor(p.indices,
                                      {"indices",
                                       TINYGLTF_TYPE_SCALAR,
                                       {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}},
                                      element);
      indices.resize(a.count);
      for (std::size_t i = 0; i < a.count; ++i) {
        const double v = a.component(i, 0);
        if (v >= static_cast<double>(vertex_count)) {
          fail(element, "index " + std::to_string(static_cast<std::uint64_t>(v)) + " out of range (vertex count " +
                            std::to_string(vertex_count) + ")");
        }
        indices[i] = static_cast<std::uint32_t>(v);
      }
    } else {
      indices.resize(vertex_count);
      for (std::size_t i = 0; i < vertex_count; ++i) indices[i] = static_cast<std::uint32_t>(i);
    }
    return unroll(indices, p.mode, element);
  }

  // Strips and fans as triangle lists (strips alternate their winding back).
  std::vector<std::uint32_t> unroll(const std::vector<std::uint32_t>& in, int mode, const std::string& element) const {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (in.size() % 3 != 0) fail(element, std::to_string(in.size()) + " corners is not a whole number of triangles");
      return in;
    }
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i + 2 < in.size(); ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        out.insert(out.end(), {in[0], in[i + 1], in[i + 2]});
      } else if (i % 2 == 0) {
        out.insert(out.end(), {in[i], in[i + 1], in[i + 2]});
      } else {
        out.insert(out.end(), {in[i + 1], in[i], in[i + 2]});
      }
    }
    return out;
  }

  void add_mesh(int index, const Transform& world, const std::string& node_element) {
    check_index(index, m_model.meshes.size(), node_element + ".mesh", "mesh");
    const tinygltf::Mesh& mesh = m_model.meshes[static_cast<std::size_t>(index)];
    for (std::size_t i = 0; i < mesh.primitives.size(); ++i) {
      add_primitive(mesh.primitives[i], world,
                    "meshes[" + std::to_string(index) + "].primitives[" + std::to_string(i) + "]");
    }
  }

  // An attribute accessor's index, or -1 when the primitive has no such attribute.
  static int attribute(const tinygltf::Primitive& p, const std::string& name) {
    const auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
  }

  void add_primitive(const tinygltf::Primitive& p, const Transform& world, const std::string& element) {
    if (p.mode >= TINYGLTF_MODE_POINTS && p.mode <= TINYGLTF_MODE_LINE_STRIP) {
      warn(element + ": points and lines skipped (they have no area to render)");
      return;
    }
    if (p.mode < TINYGLTF_MODE_TRIANGLES || p.mode > TINYGLTF_MODE_TRIANGLE_FAN) {
      fail(element, "mode " + std::to_string(p.mode) + " is not a glTF primitive mode");
    }
    const int position = attribute(p, "POSITION");
    if (position == -1) fail(element, "the primitive has no POSITION attribute");
    const AccessorData pa =
        accessor(position, {"POSITION", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}}, element);
    const std::vector<float> positions = read_floats(pa, element, "POSITION");
    const std::size_t n = pa.count;

    std::vector<float> normals;
    if (const int normal = attribute(p, "NORMAL"); normal != -1) {
      const AccessorData na =
          accessor(normal, {"NORMAL", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}}, element);
      if (na.count != n)
        fail(element, "NORMAL has " + std::to_string(na.count) + " elements, POSITION " + std::to_string(n));
      normals = read_floats(na, element, "NORMAL");
    }
    if (p.material < -1) check_index(p.material, m_model.materials.size(), element + ".material", "material");
    const std::uint32_t object = object_for(p.material, element);
    std::vector<float> uvs;
    if (const int set = m_uv_set[p.material + 1]; set >= 0) {
      const std::string name = "TEXCOORD_" + std::to_string(set);
      const int texcoord = attribute(p, name);
      if (texcoord == -1)
        fail(element, "its material's base colour texture reads " + name + ", which the primitive lacks");
      const AccessorData ta = accessor(texcoord,
                                       {"TEXCOORD",
                                        TINYGLTF_TYPE_VEC2,
                                        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                        true},
                                       element);
      if (ta.count != n)
        fail(element, name + " has " + std::to_string(ta.count) + " elements, POSITION " + std::to_string(n));
      uvs = read_floats(ta, element, name.c_str());
    }
    add_triangles(triangle_corners(p, n, element), positions, normals, uvs, world, object);
  }

  void add_triangles(const std::vector<std::uint32_t>& corners, const std::vector<float>& positions,
                     const std::vector<float>& normals, const std::vector<float>& uvs, const Transform& world,
                     std::uint32_t object) {
    // A mirroring transform flips the winding; swapping two corners keeps faces facing out.
    // A singular one (a zero scale hides a node in glTF) leaves normals undefined: use none.
    const double det = world.determinant();
    const bool mirrored = det < 0.0;
    const bool use_normals = !normals.empty() && det != 0.0;
    auto point = [&](std::uint32_t i) {
      return world.point({positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]});
    };
    auto normal = [&](std::uint32_t i) {
      const Vec3 nw = world.normal({normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]});
      return length(nw) > 0.f ? normalize(nw) : Vec3{0.f, 0.f, 0.f};
    };
    // glTF's v runs down the image, raylab's up (texture_image.h).
    auto uv = [&](std::uint32_t i) { return Vec2{uvs[2 * i], 1.f - uvs[2 * i + 1]}; };
    for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
      std::array<std::uint32_t, 3> c = {corners[t], corners[t + 1], corners[t + 2]};
      if (mirrored) std::swap(c[1], c[2]);
      const Triangle tri{point(c[0]), point(c[1]), point(c[2])};
      const std::array<Vec3, 3> tn =
          use_normals ? std::array<Vec3, 3>{normal(c[0]), normal(c[1]), normal(c[2])} : std::array<Vec3, 3>{};
      const std::array<Vec2, 3> tuv =
          !uvs.empty() ? std::array<Vec2, 3>{uv(c[0]), uv(c[1]), uv(c[2])} : std::array<Vec2, 3>{};
      add_triangle(m_scene.geometry, tri, use_normals ? &tn : nullptr, uvs.empty() ? nullptr : &tuv, object, m_report);
    }
  }

  // The object of glTF material `index` (-1: none), created with its material on first use.
  // Also records which TEXCOORD set the material's base colour texture reads (-1: none).
  std::uint32_t object_for(int index, const std::string& user) {
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

  // glTF's own default (white, fully metallic, fully rough) would render as a black shape with a
  // broad highlight in a Whitted tracer; raylab's matte default is what a user expects here.
  static Material default_material() {
    Material m;
    m.name = "default";
    return m;
  }

  Material convert_material(int index) {
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
    // Blended alpha is see-through coverage: light passes straight on (ior 1), not refracted.
    if (in.alphaMode == "BLEND") {
      out.transmittance = static_cast<float>(1.0 - std::clamp(c[3], 0.0, 1.0));
      out.ior = 1.f;
    }
    if (pbr.baseColorTexture.index != -1) {
      const std::string texture_element = element + ".pbrMetallicRoughness.baseColorTexture";
      out.texture = Texture::from_image(texture(pbr.baseColorTexture.index, texture_element));
      if (pbr.baseColorTexture.texCoord < 0) fail(texture_element, "texCoord must be >= 0");
      m_uv_set[static_cast<std::size_t>(index + 1)] = pbr.baseColorTexture.texCoord;
    }
    return out;
  }

  std::shared_ptr<const TextureImage> texture(int index, const std::string& user) {
    check_index(index, m_model.textures.size(), user + ".index", "texture");
    const std::string element = "textures[" + std::to_string(index) + "]";
    const tinygltf::Texture& t = m_model.textures[static_cast<std::size_t>(index)];
    if (t.source == -1)
      fail(element, "no PNG or JPEG source (texture extensions such as KHR_texture_basisu are not supported)");
    check_index(t.source, m_model.images.size(), element + ".source", "image");
    if (t.sampler != -1) {
      check_index(t.sampler, m_model.samplers.size(), element + ".sampler", "sampler");
      const tinygltf::Sampler& s = m_model.samplers[static_cast<std::size_t>(t.sampler)];
      if (s.wrapS != TINYGLTF_TEXTURE_WRAP_REPEAT || s.wrapT != TINYGLTF_TEXTURE_WRAP_REPEAT) {
        warn(element + ": clamped or mirrored wrapping is read as repeat");
      }
    }
    const auto source = static_cast<std::size_t>(t.source);
    if (m_images.size() < m_model.images.size()) m_images.resize(m_model.images.size());
    if (!m_images[source]) m_images[source] = decode_image(t.source);
    return m_images[source];
  }

  std::shared_ptr<const TextureImage> decode_image(int index) {
    const std::string element = "images[" + std::to_string(index) + "]";
    const tinygltf::Image& image = m_model.images[static_cast<std::size_t>(index)];
    if (image.bufferView != -1) {
      check_index(image.bufferView, m_model.bufferViews.size(), element + ".bufferView", "bufferView");
      return decode_texture(view_bytes(image.bufferView), m_path, element);
    }
    const auto it = m_ctx.image_bytes.find(index);
    if (it == m_ctx.image_bytes.end()) fail(element, "cannot read image '" + image.uri + "' (not found)");
    return decode_texture(it->second, m_path, element);
  }

  std::string m_path;
  const tinygltf::Model& m_model;
  CallbackContext& m_ctx;
  Scene& m_scene;
  GltfLoadOptions m_options;
  MeshLoadReport m_report;
  bool m_camera_taken = false;
  std::vector<std::optional<std::uint32_t>> m_objects;        // by material index + 1
  std::vector<int> m_uv_set;                                  // by material index + 1
  std::vector<std::shared_ptr<const TextureImage>> m_images;  // by image index
};

}  // namespace

void load_gltf(const std::string& path, Scene& scene, const GltfLoadOptions& options) {
  if (!options.placement.valid()) throw UsageError("load_gltf: the placement transform is not invertible");
  CallbackContext ctx;
  std::error_code ec;
  ctx.folder = fs::absolute(folder_of(path), ec).lexically_normal().string();
  if (ctx.folder.size() > 1 && ctx.folder.ends_with('/')) ctx.folder.pop_back();
  ctx.allow_outside = options.allow_outside_paths;
  const tinygltf::Model model = parse_gltf(path, ctx);
  GltfReader(path, model, ctx, scene, options).read();
}

}  // namespace raylab
