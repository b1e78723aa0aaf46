#include "gltf_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <span>

#include "gltf_glb.h"
#include "raylab/core/error.h"
#include "raylab/io/read_file.h"
#include "raylab/io/scene_paths.h"

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

}  // namespace raylab::gltf_detail
