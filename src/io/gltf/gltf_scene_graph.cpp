#include "gltf_reader.h"

#include <cmath>
#include <numbers>
#include <utility>

namespace raylab::gltf_detail {
namespace {

// The unit quaternion (x, y, z, w) as a rotation matrix.
Transform rotation_of(const std::vector<double>& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double x = q[0] / n, y = q[1] / n, z = q[2] / n, w = q[3] / n;
  return Transform::from_rows({1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0,  //
                               2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0,  //
                               2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0});
}

}  // namespace

std::vector<int> GltfReader::root_nodes() const {
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

void GltfReader::traverse(const std::vector<int>& roots) {
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

Transform GltfReader::local_transform(const tinygltf::Node& node, const std::string& element) const {
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
    if (!(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 0.0)) fail(element, "rotation is a zero quaternion");
    t = t * rotation_of(q);
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3 || !all_finite(node.scale)) fail(element, "scale must be 3 finite numbers");
    t = t * Transform::scale(node.scale[0], node.scale[1], node.scale[2]);
  }
  return t;
}

void GltfReader::take_camera(int index, const Transform& world, const std::string& element) {
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

}  // namespace raylab::gltf_detail
