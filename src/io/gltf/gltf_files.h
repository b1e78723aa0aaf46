#pragma once
// Internal to the glTF reader: parsing the file with tinygltf through raylab's own file-system
// and image callbacks, which keep every buffer and image URI inside the glTF file's folder
// (unless allowed) and keep images encoded until a material uses them; and refusing, with their
// cause named, the files tinygltf misreads or fails on with a message about a symptom (glTF 1.0,
// other versions, required extensions, Draco-compressed meshes).

#include <map>
#include <string>
#include <vector>

#include "gltf_model.h"

namespace raylab::gltf_detail {

/// What the file-system and image callbacks share with the loader.
struct CallbackContext {
  std::string folder;  ///< absolute folder of the glTF file, without a trailing slash
  bool allow_outside = false;
  std::string refused;                                    ///< the first URI that leaves the folder, when not allowed
  std::map<int, std::vector<unsigned char>> image_bytes;  ///< encoded images given by URI, by index
};

/// Parses the .gltf or .glb file `path` (told apart by content) with tinygltf through raylab's
/// callbacks. Throws InputError for a malformed file or container, a URI that leaves the folder
/// when `ctx.allow_outside` is off, or a file raylab cannot read whatever its data: a glTF
/// version other than 2.x (glTF 1.0 named as such), an extension in extensionsRequired (raylab
/// supports none), or a Draco-compressed primitive without an uncompressed copy.
tinygltf::Model parse_gltf(const std::string& path, CallbackContext& ctx);

/// Why a glTF 1.0 file is refused and what to do about it, for messages that first say how the
/// file showed its version.
std::string gltf1_refusal();

}  // namespace raylab::gltf_detail
