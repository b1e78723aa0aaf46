#include "gltf_reader.h"

#include <array>
#include <utility>

namespace raylab::gltf_detail {
namespace {

// An attribute accessor's index, or -1 when the primitive has no such attribute.
int attribute(const tinygltf::Primitive& p, const std::string& name) {
  const auto it = p.attributes.find(name);
  return it == p.attributes.end() ? -1 : it->second;
}

}  // namespace

void GltfReader::add_mesh(int index, const Transform& world, const std::string& node_element) {
  check_index(index, m_model.meshes.size(), node_element + ".mesh", "mesh");
  const tinygltf::Mesh& mesh = m_model.meshes[static_cast<std::size_t>(index)];
  for (std::size_t i = 0; i < mesh.primitives.size(); ++i) {
    add_primitive(mesh.primitives[i], world,
                  "meshes[" + std::to_string(index) + "].primitives[" + std::to_string(i) + "]");
  }
}

void GltfReader::add_primitive(const tinygltf::Primitive& p, const Transform& world, const std::string& element) {
  if (p.mode >= TINYGLTF_MODE_POINTS && p.mode <= TINYGLTF_MODE_LINE_STRIP) {
    warn(element + ": points and lines skipped (they have no area to render)");
    return;
  }
  if (p.mode < TINYGLTF_MODE_TRIANGLES || p.mode > TINYGLTF_MODE_TRIANGLE_FAN) {
    fail(element, "mode " + std::to_string(p.mode) + " is not a glTF primitive mode");
  }
  const int position = attribute(p, "POSITION");
  if (position == -1) fail(element, "the primitive has no POSITION attribute");
  const AccessorData pa =
      accessor(position, {"POSITION", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}}, element);
  const std::vector<float> positions = read_floats(pa, element, "POSITION");
  const std::size_t n = pa.count;

  std::vector<float> normals;
  if (const int normal = attribute(p, "NORMAL"); normal != -1) {
    const AccessorData na = accessor(normal, {"NORMAL", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}}, element);
    if (na.count != n)
      fail(element, "NORMAL has " + std::to_string(na.count) + " elements, POSITION " + std::to_string(n));
    normals = read_floats(na, element, "NORMAL");
  }
  if (p.material < -1) check_index(p.material, m_model.materials.size(), element + ".material", "material");
  const std::uint32_t object = object_for(p.material, element);
  std::vector<float> uvs;
  if (const int set = m_uv_set[p.material + 1]; set >= 0) {
    const std::string name = "TEXCOORD_" + std::to_string(set);
    const int texcoord = attribute(p, name);
    if (texcoord == -1) fail(element, "a texture of its material reads " + name + ", which the primitive lacks");
    const AccessorData ta = accessor(
        texcoord,
        {"TEXCOORD",
         TINYGLTF_TYPE_VEC2,
         {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
         true},
        element);
    if (ta.count != n)
      fail(element, name + " has " + std::to_string(ta.count) + " elements, POSITION " + std::to_string(n));
    uvs = read_floats(ta, element, name.c_str());
  }
  add_triangles(triangle_corners(p, n, element), positions, normals, uvs, world, object);
}

std::vector<std::uint32_t> GltfReader::triangle_corners(const tinygltf::Primitive& p, std::size_t vertex_count,
                                                        const std::string& element) const {
  std::vector<std::uint32_t> indices;
  if (p.indices >= 0 || p.indices < -1) {
    const AccessorData a = accessor(p.indices,
                                    {"indices",
                                     TINYGLTF_TYPE_SCALAR,
                                     {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}},
                                    element);
    indices.resize(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
      const double v = a.component(i, 0);
      if (v >= static_cast<double>(vertex_count)) {
        fail(element, "index " + std::to_string(static_cast<std::uint64_t>(v)) + " out of range (vertex count " +
                          std::to_string(vertex_count) + ")");
      }
      indices[i] = static_cast<std::uint32_t>(v);
    }
  } else {
    indices.resize(vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i) indices[i] = static_cast<std::uint32_t>(i);
  }
  return unroll(indices, p.mode, element);
}

std::vector<std::uint32_t> GltfReader::unroll(const std::vector<std::uint32_t>& in, int mode,
                                              const std::string& element) const {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (in.size() % 3 != 0) fail(element, std::to_string(in.size()) + " corners is not a whole number of triangles");
    return in;
  }
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i + 2 < in.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      out.insert(out.end(), {in[0], in[i + 1], in[i + 2]});
    } else if (i % 2 == 0) {
      out.insert(out.end(), {in[i], in[i + 1], in[i + 2]});
    } else {
      out.insert(out.end(), {in[i + 1], in[i], in[i + 2]});
    }
  }
  return out;
}

void GltfReader::add_triangles(const std::vector<std::uint32_t>& corners, const std::vector<float>& positions,
                               const std::vector<float>& normals, const std::vector<float>& uvs, const Transform& world,
                               std::uint32_t object) {
  // A mirroring transform flips the winding; swapping two corners keeps faces facing out.
  // A singular one (a zero scale hides a node in glTF) leaves normals undefined: use none.
  const double det = world.determinant();
  const bool mirrored = det < 0.0;
  const bool use_normals = !normals.empty() && det != 0.0;
  auto point = [&](std::uint32_t i) {
    return world.point({positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]});
  };
  auto normal = [&](std::uint32_t i) {
    const Vec3 nw = world.normal({normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]});
    return length(nw) > 0.f ? normalize(nw) : Vec3{0.f, 0.f, 0.f};
  };
  // glTF's v runs down the image, raylab's up (texture_image.h).
  auto uv = [&](std::uint32_t i) { return Vec2{uvs[2 * i], 1.f - uvs[2 * i + 1]}; };
  for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
    std::array<std::uint32_t, 3> c = {corners[t], corners[t + 1], corners[t + 2]};
    if (mirrored) std::swap(c[1], c[2]);
    const Triangle tri{point(c[0]), point(c[1]), point(c[2])};
    const std::array<Vec3, 3> tn =
        use_normals ? std::array<Vec3, 3>{normal(c[0]), normal(c[1]), normal(c[2])} : std::array<Vec3, 3>{};
    const std::array<Vec2, 3> tuv =
        !uvs.empty() ? std::array<Vec2, 3>{uv(c[0]), uv(c[1]), uv(c[2])} : std::array<Vec2, 3>{};
    add_triangle(m_scene.geometry, tri, use_normals ? &tn : nullptr, uvs.empty() ? nullptr : &tuv, object, m_report);
  }
}

}  // namespace raylab::gltf_detail
