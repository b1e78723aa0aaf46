#include "raylab/io/off_loader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/io/read_file.h"
#include "raylab/io/text_scanner.h"

namespace raylab {
namespace {

// The next token on the current line; fails naming `what` when the line has ended (OFF is
// line-oriented: what follows the values a line must have is colour, and is skipped).
Token word(TextScanner& s, std::string_view what) {
  const Token t = s.next_on_line();
  if (t.text.empty()) s.fail(t, (s.at_end() ? "unexpected end of file, expected " : "expected ") + std::string(what));
  return t;
}

bool parse_integer(std::string_view text, std::int64_t& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return !text.empty() && ec == std::errc() && ptr == end;
}

std::int64_t to_integer(const TextScanner& s, const Token& t, std::string_view what) {
  std::int64_t value = 0;
  if (!parse_integer(t.text, value))
    s.fail(t, "expected " + std::string(what) + " (an integer), found " + quoted(t.text));
  return value;
}

std::int64_t to_count(const TextScanner& s, const Token& t, std::string_view what) {
  const std::int64_t value = to_integer(s, t, what);
  if (value < 0) s.fail(t, std::string(what) + " " + std::to_string(value) + " is negative");
  return value;
}

float to_float(const TextScanner& s, const Token& t, std::string_view what) {
  double d = 0.0;
  if (!parse_finite(t.text, d)) {
    s.fail(t, "expected " + std::string(what) + " (a finite number), found " + quoted(t.text));
  }
  const auto f = static_cast<float>(d);
  if (!std::isfinite(f)) s.fail(t, std::string(what) + " " + quoted(t.text) + " is out of float range");
  return f;
}

// Which optional per-vertex values the header keyword announces.
struct OffFormat {
  bool uvs = false;      // ST: texture coordinates, last on the line
  bool colours = false;  // C: colour, skipped
  bool normals = false;  // N: a normal after the position
};

// The variant named by header keyword `word` ([ST][C][N]OFF), or nullopt if it is not one.
std::optional<OffFormat> off_keyword(std::string_view word) {
  OffFormat f;
  if (word.starts_with("ST")) {
    f.uvs = true;
    word.remove_prefix(2);
  }
  if (word.starts_with("C")) {
    f.colours = true;
    word.remove_prefix(1);
  }
  if (word.starts_with("N")) {
    f.normals = true;
    word.remove_prefix(1);
  }
  if (word != "OFF") return std::nullopt;
  return f;
}

struct Counts {
  std::int64_t vertices = 0;
  std::int64_t faces = 0;
};

// Reads the header keyword (optional) and the counts line; leaves `s` on the next line.
Counts parse_header(TextScanner& s, OffFormat& format, std::size_t size) {
  const Token first = s.next("'OFF'");
  Token vertices = first;  // a file without the keyword starts with the counts
  std::int64_t unused = 0;
  if (const std::optional<OffFormat> f = off_keyword(first.text)) {
    format = *f;
    const Token rest = s.next_on_line();
    if (rest.text == "BINARY") s.fail(rest, "binary OFF is not supported");
    vertices = rest.text.empty() ? s.next("the vertex count") : rest;
  } else if (first.text.ends_with("OFF")) {
    s.fail(first, "unsupported OFF variant " + quoted(first.text) + " (raylab reads [ST][C][N]OFF)");
  } else if (!parse_integer(first.text, unused)) {
    s.fail(first, "not an OFF file (expected 'OFF' or the vertex count), found " + quoted(first.text));
  }
  Counts counts;
  counts.vertices = to_count(s, vertices, "vertex count");
  const Token faces = word(s, "the face count");
  counts.faces = to_count(s, faces, "face count");
  if (const Token edges = s.next_on_line(); !edges.text.empty()) to_count(s, edges, "edge count");
  if (const Token extra = s.next_on_line(); !extra.text.empty()) {
    s.fail(extra, "unexpected " + quoted(extra.text) + " after the counts");
  }
  s.skip_line();

  // Refuse counts the rest of the file cannot hold, before allocating for them: every value
  // takes at least two characters (a digit and a separator; the last one needs none), and every
  // face at least one value.
  const std::uint64_t per_vertex = 2 * (3 + (format.normals ? 3 : 0) + (format.uvs ? 2 : 0));
  std::uint64_t budget = size - s.offset() + 1;
  if (static_cast<std::uint64_t>(counts.vertices) > budget / per_vertex) {
    s.fail(vertices, "unexpected end of file: the header announces " + std::to_string(counts.vertices) +
                         " vertices, but the rest of the file has room for at most " +
                         std::to_string(budget / per_vertex));
  }
  budget -= static_cast<std::uint64_t>(counts.vertices) * per_vertex;
  if (static_cast<std::uint64_t>(counts.faces) > budget / 2) {
    s.fail(faces, "unexpected end of file: the header announces " + std::to_string(counts.faces) +
                      " faces, but the rest of the file has room for at most " + std::to_string(budget / 2));
  }
  return counts;
}

// The vertices of the file, then its faces built from them.
class OffReader {
 public:
  OffReader(TextScanner& s, const OffFormat& format, Geometry& geometry, std::uint32_t object)
      : m_s(s), m_format(format), m_geometry(geometry), m_object(object) {}

  void vertices(std::int64_t count) {
    m_positions.resize(static_cast<std::size_t>(count));
    if (m_format.normals) m_normals.resize(m_positions.size());
    if (m_format.uvs) m_uvs.resize(m_positions.size());
    for (std::size_t i = 0; i < m_positions.size(); ++i) vertex(i);
    report.vertices = m_positions.size();
  }

  // Reads `count` faces; `bytes_left` bounds how many triangles they can make, for the reserve.
  void faces(std::int64_t count, std::size_t bytes_left) {
    // A triangle takes at least 8 characters ("3 0 1 2\n").
    const std::size_t expected = std::min(static_cast<std::size_t>(count), bytes_left / 8);
    m_geometry.triangles.reserve(m_geometry.triangles.size() + expected);
    m_geometry.triangle_objects.reserve(m_geometry.triangles.size() + expected);
    for (std::int64_t f = 0; f < count; ++f) face();
  }

  MeshLoadReport report;

 private:
  void vertex(std::size_t i) {
    const Token x = m_s.next("a vertex");
    m_positions[i] = {to_float(m_s, x, "vertex x"), to_float(m_s, word(m_s, "vertex y"), "vertex y"),
                      to_float(m_s, word(m_s, "vertex z"), "vertex z")};
    if (m_format.normals) {
      m_normals[i] = {to_float(m_s, word(m_s, "normal x"), "normal x"),
                      to_float(m_s, word(m_s, "normal y"), "normal y"),
                      to_float(m_s, word(m_s, "normal z"), "normal z")};
    }
    if (m_format.uvs) {
      // Texture coordinates come last, after a colour of 1, 3 or 4 values if there is one.
      m_rest.clear();
      for (Token t = m_s.next_on_line(); !t.text.empty(); t = m_s.next_on_line()) m_rest.push_back(t);
      if (m_rest.size() < 2) m_s.fail(m_s.next_on_line(), "expected texture coordinates s t");
      m_uvs[i] = {to_float(m_s, m_rest[m_rest.size() - 2], "texture s"), to_float(m_s, m_rest.back(), "texture t")};
    }
    m_s.skip_line();  // a colour, or nothing
  }

  void face() {
    const Token n = m_s.next("a face");
    const std::int64_t corners = to_count(m_s, n, "face vertex count");
    m_corners.clear();
    m_corner_normals.clear();
    m_corner_uvs.clear();
    for (std::int64_t k = 0; k < corners; ++k) {
      const Token t = word(m_s, "a vertex index");
      const std::int64_t v = to_integer(m_s, t, "vertex index");
      if (v < 0 || static_cast<std::uint64_t>(v) >= m_positions.size()) {
        m_s.fail(t, "vertex index " + std::to_string(v) + " is out of range (the file has " +
                        std::to_string(m_positions.size()) + " vertices)");
      }
      const auto i = static_cast<std::size_t>(v);
      m_corners.push_back(m_positions[i]);
      if (m_format.normals) m_corner_normals.push_back(m_normals[i]);
      if (m_format.uvs) m_corner_uvs.push_back(m_uvs[i]);
    }
    m_s.skip_line();  // a colour, or nothing
    add_polygon(m_geometry, m_corners, m_corner_normals, m_corner_uvs, m_object, report);
  }

  TextScanner& m_s;
  OffFormat m_format;
  Geometry& m_geometry;
  std::uint32_t m_object;
  std::vector<Vec3> m_positions, m_normals, m_corners, m_corner_normals;
  std::vector<Vec2> m_uvs, m_corner_uvs;
  std::vector<Token> m_rest;
};

}  // namespace

MeshLoadReport parse_off(std::string_view bytes, const std::string& file, Geometry& geometry, std::uint32_t object) {
  TextScanner scanner(file, bytes, '#');
  OffFormat format;
  const Counts counts = parse_header(scanner, format, bytes.size());
  OffReader reader(scanner, format, geometry, object);
  reader.vertices(counts.vertices);
  reader.faces(counts.faces, bytes.size() - scanner.offset());
  return reader.report;
}

MeshLoadReport load_off(const std::string& path, Scene& scene, std::uint32_t object) {
  const std::string bytes = read_file(path);
  return parse_off(bytes, path, scene.geometry, object);
}

}  // namespace raylab
