#include "raylab/io/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "raylab/core/error.h"

namespace raylab {
namespace {

struct Location {
  int line = 0;
  int col = 0;
};

// Finds where the `token_index`-th token after the keyword of the `ordinal`-th statement with
// keyword `keyword` is. tinyobjloader keeps no positions, so a bad index found after parsing is
// located by counting statements in the file again (only on the error path).
Location locate(const std::string& path, const std::string& keyword, std::size_t ordinal, std::size_t token_index) {
  std::ifstream in(path);
  std::string text;
  std::size_t seen = 0;
  for (int line_no = 1; std::getline(in, text); ++line_no) {
    std::size_t p = text.find_first_not_of(" \t");
    if (p == std::string::npos || text.compare(p, keyword.size(), keyword) != 0) continue;
    const std::size_t after = p + keyword.size();
    if (after < text.size() && !std::isspace(static_cast<unsigned char>(text[after]))) continue;
    if (seen++ != ordinal) continue;
    // Walk to the requested token.
    std::size_t pos = after;
    for (std::size_t t = 0;; ++t) {
      pos = text.find_first_not_of(" \t\r", pos);
      if (pos == std::string::npos) return {line_no, static_cast<int>(p) + 1};
      if (t == token_index) return {line_no, static_cast<int>(pos) + 1};
      pos = text.find_first_of(" \t\r", pos);
      if (pos == std::string::npos) return {line_no, static_cast<int>(p) + 1};
    }
  }
  return {};
}

// tinyobjloader reports "... line N ..." in some messages; keep its text but lead with file:line.
[[noreturn]] void throw_reader_error(const std::string& path, const std::string& message) {
  int line = 0;
  const auto at = message.find("line ");
  if (at != std::string::npos) line = std::atoi(message.c_str() + at + 5);
  std::string text = message;
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  throw InputError(path, line, 0, text.empty() ? "cannot parse OBJ file" : text);
}

}  // namespace

MeshLoadReport load_obj(const std::string& path, Scene& scene, std::uint32_t object) {
  {
    std::ifstream probe(path);
    if (!probe) throw InputError(path, "cannot open file");
  }
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // its triangulation reads vertices through unchecked indices
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) throw_reader_error(path, reader.Error());
  const tinyobj::attrib_t& attrib = reader.GetAttrib();

  MeshLoadReport report;
  const std::size_t vertex_count = attrib.vertices.size() / 3;
  const std::size_t normal_count = attrib.normals.size() / 3;
  report.vertices = vertex_count;
  for (std::size_t i = 0; i < attrib.vertices.size(); ++i) {
    if (!std::isfinite(attrib.vertices[i])) {
      const Location at = locate(path, "v", i / 3, i % 3);
      throw InputError(path, at.line, at.col, "vertex coordinate is not a finite number");
    }
  }
  std::vector<Vec3> normals(normal_count);
  for (std::size_t i = 0; i < normal_count; ++i) {
    normals[i] = {attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]};
    if (!is_finite(normals[i])) {
      const Location at = locate(path, "vn", i, 0);
      throw InputError(path, at.line, at.col, "normal is not a finite number");
    }
  }
  auto vertex = [&](int i) {
    return Vec3{attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]};
  };

  std::size_t face_ordinal = 0;  // faces in file order, across shapes
  std::vector<int> corners, corner_normals;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t offset = 0;
    for (const unsigned char fv_raw : shape.mesh.num_face_vertices) {
      const std::size_t fv = fv_raw;
      corners.clear();
      corner_normals.clear();
      bool all_normals = true;
      for (std::size_t k = 0; k < fv; ++k) {
        const tinyobj::index_t idx = shape.mesh.indices[offset + k];
        // Relative (negative) indices were resolved by the reader against the vertices read so
        // far; an out-of-range one comes out negative or past the end.
        if (idx.vertex_index < 0 || static_cast<std::size_t>(idx.vertex_index) >= vertex_count) {
          const Location at = locate(path, "f", face_ordinal, k);
          throw InputError(path, at.line, at.col,
                           "vertex index out of range (the file has " + std::to_string(vertex_count) + " vertices)");
        }
        if (idx.normal_index >= 0 && static_cast<std::size_t>(idx.normal_index) >= normal_count) {
          const Location at = locate(path, "f", face_ordinal, k);
          throw InputError(path, at.line, at.col,
                           "normal index out of range (the file has " + std::to_string(normal_count) + " normals)");
        }
        if (idx.normal_index < -1) {
          const Location at = locate(path, "f", face_ordinal, k);
          throw InputError(path, at.line, at.col, "normal index out of range");
        }
        corners.push_back(idx.vertex_index);
        corner_normals.push_back(idx.normal_index);
        all_normals = all_normals && idx.normal_index >= 0;
      }
      offset += fv;
      ++face_ordinal;
      // Fan triangulation: exact for the convex polygons mesh files carry.
      for (std::size_t k = 1; k + 1 < fv; ++k) {
        const Triangle tri{vertex(corners[0]), vertex(corners[k]), vertex(corners[k + 1])};
        if (dot(triangle_normal(tri), triangle_normal(tri)) == 0.f) {
          ++report.degenerate_dropped;
          continue;
        }
        if (all_normals) {
          scene.geometry.add(tri, {normals[corner_normals[0]], normals[corner_normals[k]], normals[corner_normals[k + 1]]},
                             object);
        } else {
          scene.geometry.add(tri, object);
        }
        ++report.triangles;
      }
    }
  }
  return report;
}

}  // namespace raylab
