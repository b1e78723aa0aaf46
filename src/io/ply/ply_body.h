#pragma once
// Internal to the PLY reader: reading the body, element by element in file order, in either
// encoding. Each encoding has its own reader class with the same three calls (vertices, faces,
// skip); read_elements decides which element gets which.

#include <cstddef>
#include <string>
#include <string_view>

#include "ply_header.h"
#include "ply_mesh.h"
#include "raylab/core/error.h"
#include "raylab/io/text_scanner.h"

namespace raylab::ply_detail {

/// Reads the elements of `header` in file order through `body`: vertices, faces and strips,
/// skipping all others. Fails for a second vertex element or faces before the vertices.
template <class Body>
void read_elements(const Header& header, Body& body, const std::string& file) {
  bool have_vertices = false;
  for (const Element& e : header.elements) {
    if (e.name == "vertex") {
      if (have_vertices) throw InputError(file, e.line, e.col, "a second 'vertex' element");
      body.vertices(e);
      have_vertices = true;
    } else if (e.name == "face" || e.name == "tristrips") {
      if (!have_vertices && e.count > 0) {
        throw InputError(file, e.line, e.col, "element " + quoted(e.name) + " comes before element 'vertex'");
      }
      body.faces(e, e.name == "tristrips");
    } else {
      body.skip(e);
    }
  }
}

/// Reads the ASCII body that `s` stands at the start of into `mesh`.
void read_ascii_body(const Header& header, TextScanner& s, MeshSink& mesh);

/// Reads the binary body of `bytes` that starts at `offset` into `mesh`; `swap` when the file's
/// byte order is not the machine's. Errors name the byte offset in file `file`.
void read_binary_body(const Header& header, std::string_view bytes, std::size_t offset, bool swap,
                      const std::string& file, MeshSink& mesh);

}  // namespace raylab::ply_detail
