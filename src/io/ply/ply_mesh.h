#pragma once
// Internal to the PLY reader: what either body encoding reads into. The vertex element's
// properties map to slots (x y z, normals, uvs), faces pick their index list, and a MeshSink
// holds the vertices and turns faces and strips into the geometry's triangles.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ply_header.h"
#include "raylab/scene/mesh_builder.h"

namespace raylab::ply_detail {

/// What a vertex property is used for.
enum Slot : std::uint8_t { kX, kY, kZ, kNx, kNy, kNz, kU, kV, kSlots, kSkip = kSlots };

/// Each slot's name in messages.
inline constexpr const char* kSlotNames[kSlots] = {"x", "y", "z", "nx", "ny", "nz", "u", "v"};

/// The slot of the vertex property named `name` (with the usual aliases of u and v), or kSkip.
Slot slot_named(std::string_view name);

/// The use of each property of the vertex element. Normals (uvs) are read only when all three
/// (both) components are present; a lone `nx` is skipped like any unknown property.
struct VertexLayout {
  std::vector<Slot> slots;
  bool normals = false;
  bool uvs = false;
};

/// The layout of vertex element `e`; fails when x, y or z is missing or a used property is a list.
VertexLayout vertex_layout(const Element& e, const std::string& file);

/// Index of the list that holds a face's (or strip's) vertex indices in element `e`; fails when
/// there is none or it is not a list of integers.
std::size_t index_property(const Element& e, const std::string& file);

/// The vertices read so far, and the triangles made of them.
class MeshSink {
 public:
  /// Appends to `geometry` as object `object`.
  MeshSink(Geometry& geometry, std::uint32_t object) : m_geometry(geometry), m_object(object) {}

  std::vector<Vec3> positions, normals;  ///< per vertex; normals empty when the file has none
  std::vector<Vec2> uvs;                 ///< per vertex; empty when the file has none
  MeshLoadReport report;                 ///< what was read and what was dropped

  /// Makes room for `count` vertices laid out as `layout`.
  void resize_vertices(std::uint64_t count, const VertexLayout& layout) {
    positions.resize(count);
    if (layout.normals) normals.resize(count);
    if (layout.uvs) uvs.resize(count);
    report.vertices += count;
  }
  /// Stores vertex `i` from the slot values `v`.
  void set_vertex(std::uint64_t i, const float* v) {
    positions[i] = {v[kX], v[kY], v[kZ]};
    if (!normals.empty()) normals[i] = {v[kNx], v[kNy], v[kNz]};
    if (!uvs.empty()) uvs[i] = {v[kU], v[kV]};
  }
  /// Grows the triangle arrays once for about `n` more triangles.
  void reserve(std::uint64_t n) {
    const std::size_t total = m_geometry.triangles.size() + n;
    m_geometry.triangles.reserve(total);
    m_geometry.triangle_objects.reserve(total);
    if (!normals.empty()) m_geometry.triangle_normals.reserve(total);
    if (!uvs.empty()) m_geometry.triangle_uvs.reserve(total);
  }
  /// Adds the triangle of vertices `a b c` (checked indices).
  void triangle(std::size_t a, std::size_t b, std::size_t c) {
    const Triangle t{positions[a], positions[b], positions[c]};
    std::array<Vec3, 3> n;
    std::array<Vec2, 3> uv;
    if (!normals.empty()) n = {normals[a], normals[b], normals[c]};
    if (!uvs.empty()) uv = {uvs[a], uvs[b], uvs[c]};
    add_triangle(m_geometry, t, normals.empty() ? nullptr : &n, uvs.empty() ? nullptr : &uv, m_object, report);
  }
  /// Adds the polygon of vertices `corners` (checked indices), triangulated.
  void polygon(std::span<const std::size_t> corners) {
    if (corners.size() == 3) return triangle(corners[0], corners[1], corners[2]);
    m_corner_positions.clear();
    m_corner_normals.clear();
    m_corner_uvs.clear();
    for (const std::size_t c : corners) {
      m_corner_positions.push_back(positions[c]);
      if (!normals.empty()) m_corner_normals.push_back(normals[c]);
      if (!uvs.empty()) m_corner_uvs.push_back(uvs[c]);
    }
    add_polygon(m_geometry, m_corner_positions, m_corner_normals, m_corner_uvs, m_object, report);
  }

 private:
  Geometry& m_geometry;
  std::uint32_t m_object;
  std::vector<Vec3> m_corner_positions, m_corner_normals;
  std::vector<Vec2> m_corner_uvs;
};

/// The vertex indices of one record of a face or strip element, as they are read. A face
/// collects its corners and becomes a polygon when the record ends. A strip makes a triangle of
/// each vertex after the first two and the two before it, every other one with its first two
/// corners swapped so that all keep the winding of the first; -1 restarts it.
class FaceRecord {
 public:
  /// Starts a record of a face element, or of a strip element when `strip`; `corners` is scratch
  /// space that the reader keeps from one record to the next.
  FaceRecord(MeshSink& mesh, bool strip, std::vector<std::size_t>& corners)
      : m_mesh(mesh), m_strip(strip), m_corners(corners) {
    m_corners.clear();
  }
  /// Adds vertex index `v`, checked by the reader against the vertex count, or -1 in a strip.
  void add(std::int64_t v) {
    if (!m_strip) {
      m_corners.push_back(static_cast<std::size_t>(v));
      return;
    }
    if (v == -1) {
      m_count = 0;
      return;
    }
    const auto c = static_cast<std::size_t>(v);
    if (m_count >= 2) {
      if (m_count % 2 == 0) {
        m_mesh.triangle(m_a, m_b, c);
      } else {
        m_mesh.triangle(m_b, m_a, c);
      }
    }
    m_a = m_b;
    m_b = c;
    ++m_count;
  }
  /// Ends the record: a face is added as a polygon.
  void finish() {
    if (!m_strip) m_mesh.polygon(m_corners);
  }

 private:
  MeshSink& m_mesh;
  bool m_strip;
  std::vector<std::size_t>& m_corners;
  std::size_t m_a = 0, m_b = 0;  // the strip's last two vertices
  std::uint64_t m_count = 0;     // vertices since the strip (re)started
};

/// The message for vertex index `index` past the `vertex_count` vertices.
std::string out_of_range(std::int64_t index, std::size_t vertex_count);

}  // namespace raylab::ply_detail
