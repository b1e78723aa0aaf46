#include "gltf_reader.h"

#include <algorithm>
#include <cmath>

namespace raylab::gltf_detail {
namespace {

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

}  // namespace

AccessorData GltfReader::accessor(int index, const AccessorUse& use, const std::string& user) const {
  check_index(index, m_model.accessors.size(), user + " " + use.name, "accessor");
  const std::string element = "accessors[" + std::to_string(index) + "] (" + use.name + " of " + user + ")";
  const tinygltf::Accessor& a = m_model.accessors[static_cast<std::size_t>(index)];
  if (a.sparse.isSparse) fail(element, "sparse accessors are not supported");
  if (a.type != use.type) fail(element, "wrong type for " + std::string(use.name));
  if (std::find(use.component_types.begin(), use.component_types.end(), a.componentType) == use.component_types.end()) {
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
    fail(element, "byteStride " + std::to_string(view.byteStride) + " of bufferViews[" + std::to_string(a.bufferView) +
                      "] is smaller than one element (" + std::to_string(element_size) + " bytes)");
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

std::span<const unsigned char> GltfReader::view_bytes(int index) const {
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

std::vector<float> GltfReader::read_floats(const AccessorData& a, const std::string& element, const char* name) const {
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

}  // namespace raylab::gltf_detail
