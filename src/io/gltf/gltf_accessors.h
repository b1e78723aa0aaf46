#pragma once
// Internal to the glTF reader: accessors, the typed views of buffer data that vertex attributes
// and indices are read through. An accessor is checked once against its buffer view and buffer
// (GltfReader::accessor); its values are then read without further checks.

#include <cstdint>
#include <cstring>
#include <initializer_list>

#include "gltf_model.h"

namespace raylab::gltf_detail {

/// Number of components of an accessor type; 0 for an unknown one.
inline int component_count(int type) {
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

/// Size in bytes of an accessor component type; 0 for one raylab never reads.
inline std::size_t component_size(int component_type) {
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

/// An accessor's elements, checked to lie inside their buffer view and buffer. `data` is null for
/// an accessor without a buffer view, whose elements are all zero.
struct AccessorData {
  const unsigned char* data = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int component_type = 0;
  int components = 0;
  bool normalized = false;

  /// Component `c` of element `i` as a number (normalised integers scaled to [0, 1]).
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

/// What a use of an accessor requires of it.
struct AccessorUse {
  const char* name;                            ///< for messages: "POSITION", "indices"
  int type;                                    ///< TINYGLTF_TYPE_*
  std::initializer_list<int> component_types;  ///< the TINYGLTF_COMPONENT_TYPE_* allowed
  bool normalized_integers = false;            ///< integer components must be normalised (texture coordinates)
};

}  // namespace raylab::gltf_detail
