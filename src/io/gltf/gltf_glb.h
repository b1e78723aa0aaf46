#pragma once
// Internal to the glTF reader: the GLB container (a binary glTF: header, JSON chunk, BIN chunk).

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace raylab::gltf_detail {

/// Checks the GLB container `bytes` of file `path` (header and chunk headers) and returns its
/// length. tinygltf checks most of it, but reads the BIN chunk's 8-byte header without checking
/// that it fits. Throws InputError at the offending byte; a version 1 container says it is glTF
/// 1.0.
std::size_t checked_glb_length(const std::string& path, std::span<const unsigned char> bytes);

/// The JSON chunk of a container that checked_glb_length accepted.
std::string_view glb_json_chunk(std::span<const unsigned char> bytes);

}  // namespace raylab::gltf_detail
