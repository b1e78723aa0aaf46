#include "raylab/io/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <charconv>
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

// Number of whitespace-separated tokens in `text` from `pos` on.
std::size_t count_tokens(const std::string& text, std::size_t pos) {
  std::size_t n = 0;
  while ((pos = text.find_first_not_of(" \t\r", pos)) != std::string::npos) {
    ++n;
    pos = text.find_first_of(" \t\r", pos);
  }
  return n;
}

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
    // tinyobjloader drops faces of fewer than 3 corners without a trace, so they do not count.
    if (keyword == "f" && count_tokens(text, after) < 3) continue;
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

// Column of the first corner of face statement `text` with an index of 0 (which tinyobjloader
// rejects without saying where), or 0 if there is none.
int zero_index_column(const std::string& text) {
  std::size_t p = text.find_first_not_of(" \t");
  if (p == std::string::npos || text.compare(p, 1, "f") != 0) return 0;
  for (p += 1; (p = text.find_first_not_of(" \t\r", p)) != std::string::npos;) {
    const std::size_t end = std::min(text.find_first_of(" \t\r", p), text.size());
    // Each corner is v, v/vt, v//vn or v/vt/vn; any present part that reads as 0 is the culprit.
    for (std::size_t q = p; q < end;) {
      const std::size_t slash = std::min(text.find('/', q), end);
      if (slash > q && std::atoi(text.substr(q, slash - q).c_str()) == 0) return static_cast<int>(p) + 1;
      q = slash + 1;
    }
    p = end;
  }
  return 0;
}

// tinyobjloader reports "... line N ..." in some messages; keep its text but lead with file:line
// (and the column, for the zero index it rejects in a face).
[[noreturn]] void throw_reader_error(const std::string& path, const std::string& message) {
  int line = 0;
  const auto at = message.find("line ");
  if (at != std::string::npos) line = std::atoi(message.c_str() + at + 5);
  if (line > 0 && message.find("`f' line") != std::string::npos) {
    std::ifstream in(path);
    std::string text;
    for (int n = 1; n <= line && std::getline(in, text); ++n) {
    }
    if (const int col = zero_index_column(text); col > 0) {
      throw InputError(path, line, col, "face index 0 is not valid (OBJ indices start at 1; negative ones count back)");
    }
  }
  std::string text = message;
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  throw InputError(path, line, 0, text.empty() ? "cannot parse OBJ file" : text);
}

// Checks every vertex coordinate, in file order. tinyobjloader reads a word it cannot parse
// ("nan", "inf", "1.5x") as 0 without complaint, so the text of each `v` statement is checked
// here, as well as the value it gave (1e999 overflows to infinity). `values` are its coordinates.
void check_vertex_coordinates(const std::string& path, const std::vector<tinyobj::real_t>& values) {
  std::ifstream in(path);
  std::string text;
  std::size_t vertex = 0;
  for (int line_no = 1; std::getline(in, text); ++line_no) {
    std::size_t p = text.find_first_not_of(" \t");
    if (p == std::string::npos || text[p] != 'v' || p + 1 >= text.size() ||
        (text[p + 1] != ' ' && text[p + 1] != '\t')) {
      continue;
    }
    p += 1;
    for (std::size_t k = 0; k < 3; ++k) {
      p = text.find_first_not_of(" \t\r", p);
      if (p == std::string::npos) break;  // a missing coordinate reads as 0, as OBJ readers do
      const std::size_t end = std::min(text.find_first_of(" \t\r", p), text.size());
      double value = 0.0;
      const std::size_t digits = text[p] == '+' ? p + 1 : p;  // from_chars takes no '+'; OBJ may
      const auto [ptr, ec] = std::from_chars(text.data() + digits, text.data() + end, value);
      const bool parsed = ptr == text.data() + end && (ec == std::errc() || ec == std::errc::result_out_of_range);
      const std::size_t i = 3 * vertex + k;
      if (!parsed || (ec == std::errc() && !std::isfinite(value)) || (i < values.size() && !std::isfinite(values[i]))) {
        throw InputError(path, line_no, static_cast<int>(p) + 1,
                         "vertex coordinate '" + text.substr(p, end - p) + "' is not a finite number");
      }
      p = end;
    }
    ++vertex;
  }
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
  check_vertex_coordinates(path, attrib.vertices);
  std::vector<Vec3> normals(normal_count);
  for (std::size_t i = 0; i < normal_count; ++i) {
    normals[i] = {attrib.normals[3 * i], attrib.normals[3 * i + 1], attrib.normals[3 * i + 2]};
    if (!is_finite(normals[i])) {
      const std::size_t bad = std::isfinite(normals[i].x) ? (std::isfinite(normals[i].y) ? 2 : 1) : 0;
      const Location at = locate(path, "vn", i, bad);
      throw InputError(path, at.line, at.col, "normal is not a finite number");
    }
  }
  auto vertex = [&](int i) {
    return Vec3{attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]};
  };

  std::size_t face_ordinal = 0;  // faces in file order, across shapes
  std::vector<int> corners, corner_normals;
  std::vector<Vec3> positions, face_normals;  // the face's corners and their normals
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
      positions.clear();
      face_normals.clear();
      for (std::size_t k = 0; k < corners.size(); ++k) {
        positions.push_back(vertex(corners[k]));
        if (all_normals) face_normals.push_back(normals[corner_normals[k]]);
      }
      add_polygon(scene.geometry, positions, face_normals, {}, object, report);
    }
  }
  return report;
}

}  // namespace raylab
