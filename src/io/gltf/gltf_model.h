#pragma once
// Internal to the glTF reader: tinygltf's model types, configured the same way in every file of
// the reader. The configuration changes tinygltf's class layout, so no file may include
// <tiny_gltf.h> but through this header.
//
// tinygltf is one header; gltf_tinygltf.cpp is the one translation unit that compiles its
// implementation (Debian's libtinygltf-dev also ships a prebuilt libtinygltf.so, not used: its
// image loader decodes with stb_image before raylab could check an image's size). Without
// stb_image inside tinygltf, every image goes through raylab's image callback (gltf_files.cpp)
// and raylab's size-checked decoder (texture_io), and only for the images a material actually
// uses. JSON is nlohmann-json, which raylab already depends on. tiny_gltf.h lives in
// /usr/include, so its own warnings stay out of -Werror builds.

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

namespace raylab::gltf_detail {

// glTF buffers are little-endian; they are read with memcpy straight into host numbers.
static_assert(std::endian::native == std::endian::little, "the glTF reader assumes a little-endian host");

/// Whether every number of a glTF number array (a factor, a matrix) is finite.
inline bool all_finite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace raylab::gltf_detail
