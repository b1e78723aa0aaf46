#include "raylab/io/stl_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "raylab/core/error.h"
#include "raylab/io/binary_reader.h"
#include "raylab/io/read_file.h"
#include "raylab/io/text_scanner.h"

namespace raylab {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kPreambleBytes = kHeaderBytes + 4;  // header and triangle count
constexpr std::size_t kRecordBytes = 50;                  // normal, 3 vertices, attribute word

// Keywords compare without case: some exporters write "FACET NORMAL".
bool same_keyword(std::string_view text, std::string_view keyword) {
  return std::equal(text.begin(), text.end(), keyword.begin(), keyword.end(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == static_cast<unsigned char>(b);
  });
}

// True when the first word of the file is "solid", as ASCII STL begins.
bool starts_with_solid(std::string_view bytes) {
  const std::size_t start = bytes.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos) return false;
  const std::string_view word = bytes.substr(start, 5);
  return same_keyword(word, "solid") &&
         (bytes.size() == start + 5 || std::isspace(static_cast<unsigned char>(bytes[start + 5])));
}

// ------------------------------------------------------------------------------------------------
// Binary

void parse_binary(BinaryReader& in, std::uint32_t count, Geometry& geometry, std::uint32_t object,
                  MeshLoadReport& report) {
  geometry.triangles.reserve(geometry.triangles.size() + count);
  geometry.triangle_objects.reserve(geometry.triangles.size() + count);
  report.vertices = 3 * static_cast<std::size_t>(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    in.skip(12, "a facet normal");  // ignored: the geometric normal follows the vertex order
    Vec3 p[3];
    for (Vec3& v : p) {
      for (int axis = 0; axis < 3; ++axis) {
        const std::size_t at = in.offset();
        v[axis] = in.read<float>(false, "a vertex");
        if (!std::isfinite(v[axis])) in.fail(at, "vertex coordinate is not a finite number");
      }
    }
    in.skip(2, "an attribute word");
    add_triangle(geometry, Triangle{p[0], p[1], p[2]}, nullptr, nullptr, object, report);
  }
}

// ------------------------------------------------------------------------------------------------
// ASCII

class AsciiStl {
 public:
  AsciiStl(TextScanner& s, Geometry& geometry, std::uint32_t object) : m_s(s), m_geometry(geometry), m_object(object) {}

  // Reads solids until the end of the file; several solids may follow each other.
  void solids() {
    keyword("solid");
    m_s.skip_line();  // the solid's name
    for (;;) {
      const Token t = m_s.next("'facet' or 'endsolid'");
      if (same_keyword(t.text, "facet")) {
        facet();
      } else if (same_keyword(t.text, "endsolid")) {
        m_s.skip_line();
        if (m_s.at_end()) return;
        keyword("solid");
        m_s.skip_line();
      } else {
        m_s.fail(t, "expected 'facet' or 'endsolid', found " + quoted(t.text));
      }
    }
  }

  MeshLoadReport report;

 private:
  void keyword(std::string_view word) {
    const Token t = m_s.next(word);
    if (!same_keyword(t.text, word)) m_s.fail(t, "expected '" + std::string(word) + "', found " + quoted(t.text));
  }

  float coordinate() {
    const Token t = m_s.next("a vertex coordinate");
    double d = 0.0;
    if (!parse_finite(t.text, d))
      m_s.fail(t, "expected a vertex coordinate (a finite number), found " + quoted(t.text));
    const auto f = static_cast<float>(d);
    if (!std::isfinite(f)) m_s.fail(t, "vertex coordinate " + quoted(t.text) + " is out of float range");
    return f;
  }

  // The rest of a facet after its keyword. The normal's three values are not checked: exporters
  // write "nan" for degenerate facets, which are dropped anyway.
  void facet() {
    keyword("normal");
    for (int i = 0; i < 3; ++i) m_s.next("a facet normal value");
    keyword("outer");
    keyword("loop");
    Vec3 p[3];
    for (Vec3& v : p) {
      keyword("vertex");
      v.x = coordinate();
      v.y = coordinate();
      v.z = coordinate();
    }
    keyword("endloop");
    keyword("endfacet");
    report.vertices += 3;
    add_triangle(m_geometry, Triangle{p[0], p[1], p[2]}, nullptr, nullptr, m_object, report);
  }

  TextScanner& m_s;
  Geometry& m_geometry;
  std::uint32_t m_object;
};

}  // namespace

MeshLoadReport parse_stl(std::string_view bytes, const std::string& file, Geometry& geometry, std::uint32_t object) {
  MeshLoadReport report;
  const bool ascii = starts_with_solid(bytes);
  if (bytes.size() >= kPreambleBytes) {
    BinaryReader in(file, bytes, kHeaderBytes);
    const std::uint32_t count = in.read<std::uint32_t>(false, "the triangle count");
    const std::uint64_t expected = kPreambleBytes + kRecordBytes * std::uint64_t{count};
    // An ASCII file is one that says "solid" and is not exactly the size of a binary one;
    // a binary file may carry bytes after its records.
    if (expected == bytes.size() || (!ascii && expected < bytes.size())) {
      parse_binary(in, count, geometry, object, report);
      return report;
    }
    if (!ascii) {
      in.fail(kHeaderBytes, "unexpected end of file: the binary STL header announces " + std::to_string(count) +
                                " triangles, which need " + std::to_string(expected) + " bytes, but the file has " +
                                std::to_string(bytes.size()));
    }
  } else if (!ascii) {
    throw InputError::at_byte(file, bytes.size(),
                              "unexpected end of file: too short for binary STL (" + std::to_string(bytes.size()) +
                                  " of at least 84 bytes), and it does not start with 'solid' as ASCII STL does");
  }
  TextScanner scanner(file, bytes, 0);
  AsciiStl reader(scanner, geometry, object);
  reader.solids();
  return reader.report;
}

MeshLoadReport load_stl(const std::string& path, Scene& scene, std::uint32_t object) {
  const std::string bytes = read_file(path);
  return parse_stl(bytes, path, scene.geometry, object);
}

}  // namespace raylab
