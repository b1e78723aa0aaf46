#include "ply_body.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace raylab::ply_detail {
namespace {

// Reads the records of an ASCII body as whitespace-separated tokens (the line breaks between
// records carry no meaning), each error at its token's line and column.
class AsciiBody {
 public:
  AsciiBody(TextScanner& s, MeshSink& mesh) : m_s(s), m_mesh(mesh) {}

  void vertices(const Element& e) {
    const VertexLayout layout = vertex_layout(e, m_s.file());
    m_mesh.resize_vertices(e.count, layout);
    for (std::uint64_t r = 0; r < e.count; ++r) {
      float v[kSlots] = {};
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const Slot slot = layout.slots[i];
        if (slot == kSkip) {
          skip_property(e.properties[i]);
        } else {
          v[slot] = value(kSlotNames[slot]);
        }
      }
      m_mesh.set_vertex(r, v);
    }
  }

  void faces(const Element& e, bool strips) {
    const std::size_t k = index_property(e, m_s.file());
    const Property& p = e.properties[k];
    const auto vertex_count = static_cast<std::int64_t>(m_mesh.positions.size());
    for (std::uint64_t r = 0; r < e.count; ++r) {
      FaceRecord face(m_mesh, strips, m_corners);
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        if (i != k) {
          skip_property(e.properties[i]);
          continue;
        }
        const std::int64_t n = m_s.integer("list length", 0, max_of(p.count_type));
        for (std::int64_t j = 0; j < n; ++j) face.add(m_s.integer("vertex index", strips ? -1 : 0, vertex_count - 1));
      }
      face.finish();
    }
  }

  void skip(const Element& e) {
    if (e.properties.empty()) return;
    for (std::uint64_t r = 0; r < e.count; ++r) {
      for (const Property& p : e.properties) skip_property(p);
    }
  }

 private:
  void skip_property(const Property& p) {
    if (!p.list) {
      m_s.next("a property value");
      return;
    }
    const std::int64_t n = m_s.integer("list length", 0, max_of(p.count_type));
    for (std::int64_t j = 0; j < n; ++j) m_s.next("a list item");
  }

  // The next token as a finite float; `name` is the property it is for.
  float value(const char* name) {
    const Token t = m_s.next("a vertex property value");
    double d = 0.0;
    if (!parse_finite(t.text, d)) {
      m_s.fail(t, std::string("expected vertex ") + name + " (a finite number), found " + quoted(t.text));
    }
    const auto f = static_cast<float>(d);
    if (!std::isfinite(f)) m_s.fail(t, std::string("vertex ") + name + " " + quoted(t.text) + " is out of float range");
    return f;
  }

  TextScanner& m_s;
  MeshSink& m_mesh;
  std::vector<std::size_t> m_corners;
};

}  // namespace

void read_ascii_body(const Header& header, TextScanner& s, MeshSink& mesh) {
  AsciiBody body(s, mesh);
  read_elements(header, body, s.file());
}

}  // namespace raylab::ply_detail
