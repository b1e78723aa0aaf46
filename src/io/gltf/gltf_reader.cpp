#include "gltf_reader.h"

#include "raylab/core/error.h"

namespace raylab::gltf_detail {

void GltfReader::read() {
  const std::vector<int> roots = root_nodes();
  traverse(roots);
  if (m_report.degenerate_dropped > 0) {
    warn(std::to_string(m_report.degenerate_dropped) + " zero-area triangles dropped");
  }
}

void GltfReader::fail(const std::string& element, const std::string& message) const {
  throw InputError(m_path, element + ": " + message);
}

void GltfReader::warn(const std::string& message) { m_scene.warnings.push_back(m_path + ": " + message); }

void GltfReader::check_index(int index, std::size_t size, const std::string& element, const char* array) const {
  if (index < 0 || static_cast<std::size_t>(index) >= size) {
    fail(element, std::string(array) + " index " + std::to_string(index) + " out of range (the file has " +
                      std::to_string(size) + ")");
  }
}

}  // namespace raylab::gltf_detail
