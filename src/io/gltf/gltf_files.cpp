#include "gltf_files.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "../json_document.h"
#include "gltf_glb.h"
#include "raylab/core/error.h"
#include "raylab/io/read_file.h"
#include "raylab/io/scene_paths.h"
#include "raylab/io/text_scanner.h"

namespace raylab::gltf_detail {
namespace {

namespace fs = std::filesystem;

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
  note_file_read(*resolved);
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

// tinygltf's messages end in newlines and may hold several; keep them on one line.
std::string one_line(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ';');
  return text;
}

// --- Files no glTF 2.0 reader can read, refused before tinygltf parses them
//
// tinygltf reads glTF 2.0 only, and given anything else fails far from the cause or not at all:
// a glTF 1.0 file's dictionaries ("meshes": {"name": {...}}) are skipped without a word, leaving
// a scene with no faces, and a Draco-compressed primitive's accessors, which have no bufferView,
// fail as "invalid bufferView". These checks read the few parts of the JSON that tell, and name
// the cause. They run after tinygltf, when it failed or its result shows a sign of trouble.

using json = nlohmann::json;

// The top-level properties that are arrays in glTF 2.0 and objects keyed by name in glTF 1.0.
constexpr std::string_view kTopLevelArrays[] = {"accessors", "animations", "buffers", "bufferViews", "cameras",
                                                "images",    "materials",  "meshes",  "nodes",       "samplers",
                                                "scenes",    "skins",      "textures"};
// Top-level properties only glTF 1.0 has (its shader-based materials).
constexpr std::string_view kGltf1Only[] = {"programs", "shaders", "techniques"};

constexpr const char* kDraco = "KHR_draco_mesh_compression";

// A part of the file that makes it unreadable.
struct Refusal {
  std::string pointer;  // JSON pointer of the part, for its line and column
  std::string message;  // "element: what is wrong"
};

// The parts of the JSON the checks read: the root's members (whose kind, object or array, tells
// glTF 1.0 from 2.0) and, in full but without extras, asset, extensionsRequired, meshes and
// accessors. The members of the others are dropped as they are read: buffers and images can hold
// megabytes of base64. Null when the text is not JSON; tinygltf then says what is wrong.
json outline(std::string_view text) {
  std::string member;  // the root member being read
  const json::parser_callback_t keep = [&member](int depth, json::parse_event_t event, json& parsed) {
    if (depth == 1 && event == json::parse_event_t::key && parsed.is_string()) member = parsed.get<std::string>();
    if (depth <= 1) return true;
    if (event == json::parse_event_t::key && parsed == "extras") return false;
    return member == "asset" || member == "extensionsRequired" || member == "meshes" || member == "accessors";
  };
  try {
    json root = json::parse(text.begin(), text.end(), keep, /*allow_exceptions=*/false);
    return root.is_discarded() ? json() : root;
  } catch (const json::exception&) {
    return json();
  }
}

// The major version of asset.version `v` ("2.0" -> 2; a number, which glTF 1.0 files sometimes
// wrote, by its integer part), or none when `v` is no version.
std::optional<std::uint64_t> major_version(const json& v) {
  if (v.is_number()) {
    const double d = v.get<double>();
    if (!(d >= 0.0 && d < 1e9)) return std::nullopt;
    return static_cast<std::uint64_t>(std::floor(d));
  }
  if (!v.is_string()) return std::nullopt;
  const std::string& s = v.get_ref<const std::string&>();
  std::uint64_t major = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), major);
  if (ec != std::errc() || (end != s.data() + s.size() && *end != '.')) return std::nullopt;
  return major;
}

// asset.version, when it is there: glTF 1.0 and every major version but 2 are refused.
std::optional<Refusal> version_refusal(const json& root) {
  const auto asset = root.find("asset");
  if (asset == root.end() || !asset->is_object()) return std::nullopt;
  const auto version = asset->find("version");
  if (version == asset->end()) return std::nullopt;
  const std::string shown =
      "asset.version is " + raylab::quoted(version->is_string() ? version->get<std::string>() : version->dump());
  const std::optional<std::uint64_t> major = major_version(*version);
  if (!major) return Refusal{"/asset/version", shown + ", which is not a glTF version (glTF 2.0 files say \"2.0\")"};
  if (*major == 1) return Refusal{"/asset/version", shown + ": " + gltf1_refusal()};
  if (*major != 2) return Refusal{"/asset/version", shown + ": raylab reads glTF 2.0 only"};
  if (!version->is_string()) {
    return Refusal{"/asset/version", shown + ", a number: glTF writes the version as a string (\"2.0\")"};
  }
  return std::nullopt;
}

// Objects keyed by name where glTF 2.0 has arrays, or glTF 1.0's shader properties. Without an
// asset.version they show a glTF 1.0 file; a file that says it is 2.0 is refused all the same,
// since tinygltf would skip those objects and read nothing from them.
std::optional<Refusal> dictionary_refusal(const json& root) {
  const auto asset = root.find("asset");
  const bool says_2 = asset != root.end() && asset->is_object() && asset->contains("version");
  for (const std::string_view name : kTopLevelArrays) {
    const std::string element(name);
    const auto it = root.find(element);
    if (it == root.end() || !it->is_object()) continue;
    if (says_2) return Refusal{"/" + element, element + ": an object keyed by name, where glTF 2.0 has an array"};
    return Refusal{"/" + element, "\"" + element + "\" is an object keyed by name: " + gltf1_refusal()};
  }
  if (says_2) return std::nullopt;
  for (const std::string_view name : kGltf1Only) {
    const std::string element(name);
    if (!root.contains(element)) continue;
    return Refusal{"/" + element, "\"" + element + "\" is a glTF 1.0 property: " + gltf1_refusal()};
  }
  return std::nullopt;
}

// What a required extension does, for the ones exporters commonly require.
std::string described(const std::string& extension) {
  struct Known {
    std::string_view name, what;
  };
  static constexpr Known kKnown[] = {{kDraco, "Draco mesh compression"},
                                     {"EXT_meshopt_compression", "meshopt compression"},
                                     {"KHR_meshopt_compression", "meshopt compression"},
                                     {"KHR_mesh_quantization", "quantized vertex data"},
                                     {"KHR_texture_basisu", "Basis Universal textures"},
                                     {"EXT_texture_webp", "WebP textures"},
                                     {"KHR_texture_transform", "texture transforms"}};
  std::string out = raylab::quoted(extension);  // cut short and cleaned of control bytes
  out = out.substr(1, out.size() - 2);          // without its quotes
  for (const Known& k : kKnown) {
    if (k.name == extension) out += " (" + std::string(k.what) + ")";
  }
  return out;
}

// extensionsRequired: the file cannot be shown right without them, and raylab supports none.
std::optional<Refusal> extension_refusal(const json& root) {
  const auto required = root.find("extensionsRequired");
  if (required == root.end() || !required->is_array()) return std::nullopt;
  std::vector<std::string> names;
  for (const json& e : *required) {
    if (e.is_string()) names.push_back(described(e.get<std::string>()));
  }
  if (names.empty()) return std::nullopt;
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  const bool one = names.size() == 1;
  return Refusal{"/extensionsRequired",
                 std::string("extensionsRequired: the file needs extension") + (one ? " " : "s ") + list +
                     ", which raylab does not support (export the model again without " + (one ? "it)" : "them)")};
}

// Whether every accessor primitive `p` names has a bufferView (or sparse values): the
// uncompressed copy a file that does not require Draco keeps beside the compressed data.
// Indices out of range are left to the reader, which names them.
bool has_uncompressed_copy(const json& p, const json& accessors) {
  const auto stored = [&accessors](const json& index) {
    if (!index.is_number_integer() || !accessors.is_array()) return true;
    const auto i = index.get<std::int64_t>();
    if (i < 0 || static_cast<std::uint64_t>(i) >= accessors.size()) return true;
    const json& a = accessors[static_cast<std::size_t>(i)];
    return !a.is_object() || a.contains("bufferView") || a.contains("sparse");
  };
  if (const auto it = p.find("indices"); it != p.end() && !stored(*it)) return false;
  if (const auto it = p.find("attributes"); it != p.end() && it->is_object()) {
    for (const auto& [name, index] : it->items()) {
      if (!stored(index)) return false;
    }
  }
  return true;
}

// A Draco-compressed primitive with no uncompressed copy (a file that uses Draco without listing
// it in extensionsRequired; one that lists it is refused before).
std::optional<Refusal> draco_refusal(const json& root) {
  const auto meshes = root.find("meshes");
  if (meshes == root.end() || !meshes->is_array()) return std::nullopt;
  const auto accessors = root.find("accessors");
  const json none = json::array();
  for (std::size_t m = 0; m < meshes->size(); ++m) {
    const json& mesh = (*meshes)[m];
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    const json& primitives = mesh["primitives"];
    for (std::size_t i = 0; i < primitives.size(); ++i) {
      const json& p = primitives[i];
      if (!p.is_object() || !p.contains("extensions") || !p["extensions"].is_object()) continue;
      if (!p["extensions"].contains(kDraco)) continue;
      if (has_uncompressed_copy(p, accessors == root.end() ? none : *accessors)) continue;
      const std::string where = "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(i);
      return Refusal{where + "/extensions/" + kDraco,
                     "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(i) + "]: compressed with " +
                         kDraco +
                         ", which raylab does not decode, and the file holds no uncompressed copy (export "
                         "the model again without Draco compression)"};
    }
  }
  return std::nullopt;
}

// Throws InputError for the first reason the JSON text `text` of file `path` cannot be read
// whatever its data; at its line and column when `text` is the file itself (not a GLB chunk).
void refuse_unreadable(const std::string& path, std::string_view text, bool text_is_file) {
  const json root = outline(text);
  if (!root.is_object()) return;
  std::optional<Refusal> refusal = version_refusal(root);
  if (!refusal) refusal = dictionary_refusal(root);
  if (!refusal) refusal = extension_refusal(root);
  if (!refusal) refusal = draco_refusal(root);
  if (!refusal) return;
  TextPosition at;
  if (text_is_file) {
    try {
      at = JsonDocument(text, path).where(refusal->pointer);
    } catch (const InputError&) {
      // A duplicate key or deep nesting, which tinygltf accepts: refuse without a position.
    } catch (const json::exception&) {
    }
  }
  throw InputError(path, at.line, at.col, refusal->message);
}

// Whether tinygltf's result shows a sign that the file may be one refuse_unreadable refuses: a
// version other than 2.x, a required extension, a Draco-compressed primitive, or no meshes or no
// nodes (what is left of glTF 1.0's objects). Reading the JSON a second time for every file would
// add about a third to the load time of a file with large embedded buffers (0.3 s of 1.3 s for
// 29 MB of base64), so it is read again only then.
bool may_be_unreadable(const tinygltf::Model& model) {
  if (major_version(json(model.asset.version)) != std::optional<std::uint64_t>(2)) return true;
  if (!model.extensionsRequired.empty() || model.meshes.empty() || model.nodes.empty()) return true;
  for (const tinygltf::Mesh& mesh : model.meshes) {
    for (const tinygltf::Primitive& p : mesh.primitives) {
      if (p.extensions.count(kDraco) != 0) return true;
    }
  }
  return false;
}

}  // namespace

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
  const bool glb = text.rfind("glTF", 0) == 0;
  if (glb) {
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
  // tinygltf's own message, when it fails, is about a symptom; the cause is named first.
  if (!ok || may_be_unreadable(model)) refuse_unreadable(path, glb ? glb_json_chunk(bytes) : text, !glb);
  if (!ok) throw InputError(path, "not a valid glTF file: " + one_line(err.empty() ? "unknown error" : err));
  return model;
}

std::string gltf1_refusal() {
  return "this is glTF 1.0, which raylab does not read (convert it to glTF 2.0 first, e.g. with gltf-pipeline)";
}

}  // namespace raylab::gltf_detail
