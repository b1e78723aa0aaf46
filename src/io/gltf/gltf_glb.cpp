#include "gltf_glb.h"

#include <cstdint>

#include "gltf_files.h"
#include "raylab/core/error.h"

namespace raylab::gltf_detail {
namespace {

// GLB numbers are little-endian whatever the host.
std::uint32_t read_le32(const unsigned char* p) {
  return std::uint32_t{p[0]} | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) | (std::uint32_t{p[3]} << 24);
}

}  // namespace

std::size_t checked_glb_length(const std::string& path, std::span<const unsigned char> bytes) {
  if (bytes.size() < 20)
    throw InputError(path, "too short for a glTF binary (" + std::to_string(bytes.size()) + " bytes)");
  const std::uint32_t version = read_le32(bytes.data() + 4);
  if (version == 1) throw InputError::at_byte(path, 4, "glTF binary version 1: " + gltf1_refusal());
  if (version != 2) {
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

std::string_view glb_json_chunk(std::span<const unsigned char> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()) + 20, read_le32(bytes.data() + 12)};
}

}  // namespace raylab::gltf_detail
