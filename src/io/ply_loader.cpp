#include "raylab/io/ply_loader.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/io/read_file.h"
#include "raylab/io/text_scanner.h"

namespace raylab {
namespace {

// ------------------------------------------------------------------------------------------------
// Scalar types

enum class Scalar : std::uint8_t { kI8, kU8, kI16, kU16, kI32, kU32, kF32, kF64 };

constexpr std::size_t size_of(Scalar t) {
  constexpr std::size_t kSizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return kSizes[static_cast<int>(t)];
}

constexpr bool is_integer(Scalar t) { return t != Scalar::kF32 && t != Scalar::kF64; }

std::optional<Scalar> scalar_named(std::string_view name) {
  struct Named {
    std::string_view name;
    Scalar type;
  };
  static constexpr Named kNames[] = {
      {"char", Scalar::kI8},   {"int8", Scalar::kI8},     {"uchar", Scalar::kU8},   {"uint8", Scalar::kU8},
      {"short", Scalar::kI16}, {"int16", Scalar::kI16},   {"ushort", Scalar::kU16}, {"uint16", Scalar::kU16},
      {"int", Scalar::kI32},   {"int32", Scalar::kI32},   {"uint", Scalar::kU32},   {"uint32", Scalar::kU32},
      {"float", Scalar::kF32}, {"float32", Scalar::kF32}, {"double", Scalar::kF64}, {"float64", Scalar::kF64}};
  for (const Named& n : kNames) {
    if (n.name == name) return n.type;
  }
  return std::nullopt;
}

// Largest value of integer type `t`: the bound of a list length in an ASCII body.
std::int64_t max_of(Scalar t) {
  switch (t) {
    case Scalar::kI8:
      return std::numeric_limits<std::int8_t>::max();
    case Scalar::kU8:
      return std::numeric_limits<std::uint8_t>::max();
    case Scalar::kI16:
      return std::numeric_limits<std::int16_t>::max();
    case Scalar::kU16:
      return std::numeric_limits<std::uint16_t>::max();
    case Scalar::kI32:
      return std::numeric_limits<std::int32_t>::max();
    default:
      return std::numeric_limits<std::uint32_t>::max();
  }
}

// A `T` stored at `p`, byte-swapped when the file's byte order is not the machine's.
template <class T>
T load(const char* p, bool swap) {
  std::array<char, sizeof(T)> raw;
  std::memcpy(raw.data(), p, sizeof(T));
  if (swap) std::reverse(raw.begin(), raw.end());
  return std::bit_cast<T>(raw);
}

// The value of type `t` at `p`, as a double (exact for every PLY type).
double load_number(Scalar t, const char* p, bool swap) {
  switch (t) {
    case Scalar::kI8:
      return load<std::int8_t>(p, swap);
    case Scalar::kU8:
      return load<std::uint8_t>(p, swap);
    case Scalar::kI16:
      return load<std::int16_t>(p, swap);
    case Scalar::kU16:
      return load<std::uint16_t>(p, swap);
    case Scalar::kI32:
      return load<std::int32_t>(p, swap);
    case Scalar::kU32:
      return load<std::uint32_t>(p, swap);
    case Scalar::kF32:
      return load<float>(p, swap);
    case Scalar::kF64:
      return load<double>(p, swap);
  }
  return 0.0;
}

// The value of integer type `t` at `p` (list lengths and indices, whose types the header checks).
std::int64_t load_integer(Scalar t, const char* p, bool swap) {
  switch (t) {
    case Scalar::kI8:
      return load<std::int8_t>(p, swap);
    case Scalar::kU8:
      return load<std::uint8_t>(p, swap);
    case Scalar::kI16:
      return load<std::int16_t>(p, swap);
    case Scalar::kU16:
      return load<std::uint16_t>(p, swap);
    case Scalar::kI32:
      return load<std::int32_t>(p, swap);
    case Scalar::kU32:
      return load<std::uint32_t>(p, swap);
    default:
      return 0;
  }
}

// ------------------------------------------------------------------------------------------------
// Header

struct Property {
  std::string name;
  Scalar type = Scalar::kF32;       // the value's type, or a list's item type
  Scalar count_type = Scalar::kU8;  // a list's length type
  bool list = false;
  int line = 0, col = 0;  // where it is declared, for errors about how it is used
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  int line = 0, col = 0;  // of its count
};

enum class Encoding { kAscii, kLittleEndian, kBigEndian };

struct Header {
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
};

// The next token on the current line; fails naming `what` when the line has ended.
Token word(TextScanner& s, std::string_view what) {
  const Token t = s.next_on_line();
  if (t.text.empty()) s.fail(t, (s.at_end() ? "unexpected end of file, expected " : "expected ") + std::string(what));
  return t;
}

// Checks that nothing more is on the current line and moves to the next one.
void end_of_line(TextScanner& s) {
  const Token t = s.next_on_line();
  if (!t.text.empty()) s.fail(t, "unexpected " + quoted(t.text) + " at the end of the line");
  s.skip_line();
}

Scalar scalar_type(const TextScanner& s, const Token& t) {
  if (const std::optional<Scalar> type = scalar_named(t.text)) return *type;
  s.fail(t, "unknown PLY type " + quoted(t.text) +
                " (expected char, uchar, short, ushort, int, uint, float, double, or int8 ... float64)");
}

Encoding parse_format(TextScanner& s) {
  const Token name = word(s, "a PLY format (ascii, binary_little_endian or binary_big_endian)");
  Encoding encoding = Encoding::kAscii;
  if (name.text == "binary_little_endian") {
    encoding = Encoding::kLittleEndian;
  } else if (name.text == "binary_big_endian") {
    encoding = Encoding::kBigEndian;
  } else if (name.text != "ascii") {
    s.fail(name,
           "unknown PLY format " + quoted(name.text) + " (expected ascii, binary_little_endian or binary_big_endian)");
  }
  const Token version = word(s, "a format version");
  if (version.text != "1.0" && version.text != "1") {
    s.fail(version, "unsupported PLY version " + quoted(version.text) + " (expected 1.0)");
  }
  return encoding;
}

Element parse_element(TextScanner& s) {
  Element e;
  e.name = std::string(word(s, "an element name").text);
  const Token count = word(s, "an element count");
  const char* end = count.text.data() + count.text.size();
  const auto [ptr, ec] = std::from_chars(count.text.data(), end, e.count);
  if (ec != std::errc() || ptr != end) {
    s.fail(count, "expected an element count (a non-negative integer), found " + quoted(count.text));
  }
  e.line = count.line;
  e.col = count.col;
  return e;
}

Property parse_property(TextScanner& s) {
  Property p;
  const Token type = word(s, "a property type");
  p.line = type.line;
  p.col = type.col;
  if (type.text == "list") {
    p.list = true;
    const Token count = word(s, "a list length type");
    p.count_type = scalar_type(s, count);
    if (!is_integer(p.count_type)) s.fail(count, "a list length must have an integer type");
    p.type = scalar_type(s, word(s, "a list item type"));
  } else {
    p.type = scalar_type(s, type);
  }
  p.name = std::string(word(s, "a property name").text);
  return p;
}

// Reads the header; leaves `s` at the first byte of the body.
Header parse_header(TextScanner& s) {
  const Token magic = s.next_on_line();
  if (magic.text != "ply") s.fail(magic, "not a PLY file (the first line must be 'ply')");
  end_of_line(s);
  Header header;
  bool have_format = false;
  for (;;) {
    const Token key = s.next("'end_header'");
    if (key.text == "end_header") {
      if (!have_format) s.fail(key, "the header has no 'format' line");
      end_of_line(s);
      return header;
    }
    if (key.text == "comment" || key.text == "obj_info") {
      s.skip_line();
      continue;
    }
    if (key.text == "format") {
      if (have_format) s.fail(key, "a second 'format' line");
      header.encoding = parse_format(s);
      have_format = true;
    } else if (key.text == "element") {
      header.elements.push_back(parse_element(s));
    } else if (key.text == "property") {
      if (header.elements.empty()) s.fail(key, "a property before any element");
      header.elements.back().properties.push_back(parse_property(s));
    } else {
      s.fail(key, "unknown PLY header line " + quoted(key.text));
    }
    end_of_line(s);
  }
}

// Fewest bytes one record of `e` can take: its binary size with empty lists, or two characters
// (a digit and a separator) per value in ASCII.
std::uint64_t min_record_bytes(const Element& e, bool ascii) {
  std::uint64_t n = 0;
  for (const Property& p : e.properties) n += ascii ? 2 : size_of(p.list ? p.count_type : p.type);
  return n;
}

// Refuses element counts that the body cannot hold, before anything is allocated for them.
void check_counts(const Header& header, std::uint64_t body_bytes, const std::string& file) {
  const bool ascii = header.encoding == Encoding::kAscii;
  std::uint64_t budget = body_bytes + (ascii ? 1 : 0);  // the last ASCII value needs no separator
  for (const Element& e : header.elements) {
    const std::uint64_t min = min_record_bytes(e, ascii);
    if (min == 0) continue;
    if (e.count > budget / min) {
      throw InputError(file, e.line, e.col,
                       "unexpected end of file: element " + quoted(e.name) + " announces " + std::to_string(e.count) +
                           " records of at least " + std::to_string(min) + " bytes" + (ascii ? " (as text)" : "") +
                           ", but the rest of the file has room for at most " + std::to_string(budget / min));
    }
    budget -= e.count * min;
  }
}

// ------------------------------------------------------------------------------------------------
// What is read: vertices, and faces built from them

// What a vertex property is used for.
enum Slot : std::uint8_t { kX, kY, kZ, kNx, kNy, kNz, kU, kV, kSlots, kSkip = kSlots };

constexpr const char* kSlotNames[kSlots] = {"x", "y", "z", "nx", "ny", "nz", "u", "v"};

Slot slot_named(std::string_view name) {
  if (name == "x") return kX;
  if (name == "y") return kY;
  if (name == "z") return kZ;
  if (name == "nx") return kNx;
  if (name == "ny") return kNy;
  if (name == "nz") return kNz;
  if (name == "u" || name == "s" || name == "texture_u" || name == "texture_s") return kU;
  if (name == "v" || name == "t" || name == "texture_v" || name == "texture_t") return kV;
  return kSkip;
}

// The use of each property of the vertex element. Normals (uvs) are read only when all three
// (both) components are present; a lone `nx` is skipped like any unknown property.
struct VertexLayout {
  std::vector<Slot> slots;
  bool normals = false;
  bool uvs = false;
};

VertexLayout vertex_layout(const Element& e, const std::string& file) {
  VertexLayout layout;
  std::array<bool, kSlots> seen{};
  for (const Property& p : e.properties) {
    const Slot slot = slot_named(p.name);
    if (slot != kSkip && p.list) {
      throw InputError(file, p.line, p.col, "vertex property " + quoted(p.name) + " must be a scalar, not a list");
    }
    if (slot != kSkip) seen[slot] = true;
    layout.slots.push_back(slot);
  }
  if (!seen[kX] || !seen[kY] || !seen[kZ]) {
    throw InputError(file, e.line, e.col, "element 'vertex' needs properties x, y and z");
  }
  layout.normals = seen[kNx] && seen[kNy] && seen[kNz];
  layout.uvs = seen[kU] && seen[kV];
  for (Slot& slot : layout.slots) {
    if ((!layout.normals && slot >= kNx && slot <= kNz) || (!layout.uvs && (slot == kU || slot == kV))) slot = kSkip;
  }
  return layout;
}

// Index of the list that holds a face's (or strip's) vertex indices.
std::size_t index_property(const Element& e, const std::string& file) {
  for (std::size_t i = 0; i < e.properties.size(); ++i) {
    const Property& p = e.properties[i];
    if (p.name != "vertex_indices" && p.name != "vertex_index") continue;
    if (!p.list) throw InputError(file, p.line, p.col, quoted(p.name) + " must be a list");
    if (!is_integer(p.type)) throw InputError(file, p.line, p.col, quoted(p.name) + " must list integers");
    return i;
  }
  throw InputError(file, e.line, e.col, "element " + quoted(e.name) + " has no 'vertex_indices' list");
}

// The vertices read so far, and the triangles made of them.
class MeshSink {
 public:
  MeshSink(Geometry& geometry, std::uint32_t object) : m_geometry(geometry), m_object(object) {}

  std::vector<Vec3> positions, normals;
  std::vector<Vec2> uvs;
  MeshLoadReport report;

  // Makes room for `count` vertices laid out as `layout`.
  void resize_vertices(std::uint64_t count, const VertexLayout& layout) {
    positions.resize(count);
    if (layout.normals) normals.resize(count);
    if (layout.uvs) uvs.resize(count);
    report.vertices += count;
  }
  // Stores vertex `i` from the slot values `v`.
  void set_vertex(std::uint64_t i, const float* v) {
    positions[i] = {v[kX], v[kY], v[kZ]};
    if (!normals.empty()) normals[i] = {v[kNx], v[kNy], v[kNz]};
    if (!uvs.empty()) uvs[i] = {v[kU], v[kV]};
  }
  // Grows the triangle arrays once for about `n` more triangles.
  void reserve(std::uint64_t n) {
    const std::size_t total = m_geometry.triangles.size() + n;
    m_geometry.triangles.reserve(total);
    m_geometry.triangle_objects.reserve(total);
    if (!normals.empty()) m_geometry.triangle_normals.reserve(total);
    if (!uvs.empty()) m_geometry.triangle_uvs.reserve(total);
  }
  // Adds the triangle of vertices `a b c` (checked indices).
  void triangle(std::size_t a, std::size_t b, std::size_t c) {
    const Triangle t{positions[a], positions[b], positions[c]};
    std::array<Vec3, 3> n;
    std::array<Vec2, 3> uv;
    if (!normals.empty()) n = {normals[a], normals[b], normals[c]};
    if (!uvs.empty()) uv = {uvs[a], uvs[b], uvs[c]};
    add_triangle(m_geometry, t, normals.empty() ? nullptr : &n, uvs.empty() ? nullptr : &uv, m_object, report);
  }
  // Adds the polygon of vertices `corners` (checked indices), triangulated.
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

// A triangle strip being expanded: each vertex after the first two makes a triangle with the two
// before it, and every other triangle swaps its first two corners so that all keep the winding
// of the first.
class Strip {
 public:
  void restart() { m_count = 0; }
  void add(std::size_t v, MeshSink& mesh) {
    if (m_count >= 2) {
      if (m_count % 2 == 0) {
        mesh.triangle(m_a, m_b, v);
      } else {
        mesh.triangle(m_b, m_a, v);
      }
    }
    m_a = m_b;
    m_b = v;
    ++m_count;
  }

 private:
  std::size_t m_a = 0, m_b = 0;
  std::uint64_t m_count = 0;
};

std::string out_of_range(std::int64_t index, std::size_t vertex_count) {
  return "vertex index " + std::to_string(index) + " is out of range (the file has " + std::to_string(vertex_count) +
         " vertices)";
}

// ------------------------------------------------------------------------------------------------
// Binary body

// One scalar vertex property in a fixed-size record.
struct Field {
  Slot slot;
  Scalar type;
  std::size_t offset;
};

bool has_list(const Element& e) {
  return std::any_of(e.properties.begin(), e.properties.end(), [](const Property& p) { return p.list; });
}

std::size_t record_size(const Element& e) {
  std::size_t n = 0;
  for (const Property& p : e.properties) n += size_of(p.type);
  return n;
}

// Reads the records of a binary body. Layouts are worked out once per element, so that the loops
// over records do no more than switch on a property's type; the most common layouts (float x y z
// in the machine's byte order, faces as one uchar/int list) have loops of their own.
class BinaryBody {
 public:
  BinaryBody(const std::string& file, std::string_view bytes, std::size_t offset, bool swap, MeshSink& mesh)
      : m_file(file), m_bytes(bytes), m_pos(offset), m_swap(swap), m_mesh(mesh) {}

  void vertices(const Element& e) {
    const VertexLayout layout = vertex_layout(e, m_file);
    m_mesh.resize_vertices(e.count, layout);
    if (has_list(e)) {
      variable_vertices(e, layout);
    } else {
      fixed_vertices(e, layout);
    }
  }

  void faces(const Element& e, bool strips) {
    const std::size_t k = index_property(e, m_file);
    const Property& p = e.properties[k];
    if (!strips) {
      // Room for one triangle per face, as far as the bytes left can hold triangles.
      m_mesh.reserve(std::min<std::uint64_t>(e.count, remaining() / (size_of(p.count_type) + 3 * size_of(p.type))));
    }
    // The common layout, one list of uchar length and int indices, has its own loop.
    if (!strips && e.properties.size() == 1 && p.count_type == Scalar::kU8) {
      if (p.type == Scalar::kI32) return fast_faces<std::int32_t>(e);
      if (p.type == Scalar::kU32) return fast_faces<std::uint32_t>(e);
    }
    for (std::uint64_t r = 0; r < e.count; ++r) {
      m_corners.clear();
      Strip strip;
      walk(
          e, r, [](std::size_t, std::size_t) {},
          [&](std::size_t i, std::size_t n, std::size_t at) {
            if (i != k) return;
            for (std::size_t j = 0; j < n; ++j, at += size_of(p.type)) {
              const std::int64_t v = load_integer(p.type, m_bytes.data() + at, m_swap);
              if (strips && v == -1) {
                strip.restart();
                continue;
              }
              check_index(v, at);
              if (strips) {
                strip.add(static_cast<std::size_t>(v), m_mesh);
              } else {
                m_corners.push_back(static_cast<std::size_t>(v));
              }
            }
          });
      if (!strips) m_mesh.polygon(m_corners);
    }
  }

  void skip(const Element& e) {
    if (e.properties.empty()) return;
    if (!has_list(e)) {
      const std::size_t size = record_size(e);
      check_fixed(e, size);
      m_pos += e.count * size;
      return;
    }
    for (std::uint64_t r = 0; r < e.count; ++r) {
      walk(
          e, r, [](std::size_t, std::size_t) {}, [](std::size_t, std::size_t, std::size_t) {});
    }
  }

 private:
  std::size_t remaining() const { return m_bytes.size() - m_pos; }

  [[noreturn]] void truncated(std::size_t at, const Element& e, std::uint64_t record) const {
    throw InputError::at_byte(m_file, at,
                              "unexpected end of file in element " + quoted(e.name) + " (record " +
                                  std::to_string(record + 1) + " of " + std::to_string(e.count) + ")");
  }
  void need(std::size_t n, const Element& e, std::uint64_t record) const {
    if (n > remaining()) truncated(m_pos, e, record);
  }
  // Checks that all `e.count` records of fixed size `size` are there.
  void check_fixed(const Element& e, std::size_t size) const {
    const std::uint64_t whole = remaining() / size;
    if (e.count > whole) truncated(m_pos + whole * size, e, whole);
  }
  void check_index(std::int64_t v, std::size_t at) const {
    // A negative index converts to a value past any vertex count.
    if (static_cast<std::uint64_t>(v) >= m_mesh.positions.size()) [[unlikely]] {
      throw InputError::at_byte(m_file, at, out_of_range(v, m_mesh.positions.size()));
    }
  }

  // Reads record `r` of `e` at the current position, calling `scalar(i, at)` for each scalar
  // property and `list(i, n, at)` for each list (`at`: the offset of the value or of the first
  // item), after checking that the bytes are there.
  template <class OnScalar, class OnList>
  void walk(const Element& e, std::uint64_t r, OnScalar&& scalar, OnList&& list) {
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const Property& p = e.properties[i];
      if (!p.list) {
        need(size_of(p.type), e, r);
        scalar(i, m_pos);
        m_pos += size_of(p.type);
        continue;
      }
      need(size_of(p.count_type), e, r);
      const std::int64_t n = load_integer(p.count_type, m_bytes.data() + m_pos, m_swap);
      if (n < 0) throw InputError::at_byte(m_file, m_pos, "negative list length " + std::to_string(n));
      m_pos += size_of(p.count_type);
      if (static_cast<std::uint64_t>(n) > remaining() / size_of(p.type)) truncated(m_pos, e, r);
      list(i, static_cast<std::size_t>(n), m_pos);
      m_pos += static_cast<std::size_t>(n) * size_of(p.type);
    }
  }

  // Fails at the first value of `v` (slot values of a vertex) that is not finite.
  void check_finite(const float* v, const std::array<std::size_t, kSlots>& offsets, bool normals, bool uvs) const {
    for (int s = 0; s < kSlots; ++s) {
      if ((s >= kNx && s <= kNz && !normals) || (s >= kU && !uvs)) continue;
      if (!std::isfinite(v[s])) {
        throw InputError::at_byte(m_file, offsets[s],
                                  std::string("vertex ") + kSlotNames[s] + " is not a finite number");
      }
    }
  }
  bool all_finite(const float* v) const {
    bool ok = std::isfinite(v[kX]) && std::isfinite(v[kY]) && std::isfinite(v[kZ]);
    if (!m_mesh.normals.empty()) ok = ok && std::isfinite(v[kNx]) && std::isfinite(v[kNy]) && std::isfinite(v[kNz]);
    if (!m_mesh.uvs.empty()) ok = ok && std::isfinite(v[kU]) && std::isfinite(v[kV]);
    return ok;
  }

  void fixed_vertices(const Element& e, const VertexLayout& layout) {
    const std::size_t size = record_size(e);
    check_fixed(e, size);
    std::vector<Field> fields;
    std::array<std::size_t, kSlots> offsets{};
    std::array<Scalar, kSlots> types{};
    for (std::size_t i = 0, offset = 0; i < e.properties.size(); offset += size_of(e.properties[i].type), ++i) {
      const Slot slot = layout.slots[i];
      if (slot == kSkip) continue;
      fields.push_back({slot, e.properties[i].type, offset});
      offsets[slot] = offset;
      types[slot] = e.properties[i].type;
    }
    // Fast path: x y z as consecutive floats in the machine's byte order, copied in one go.
    const bool packed = !m_swap && types[kX] == Scalar::kF32 && types[kY] == Scalar::kF32 &&
                        types[kZ] == Scalar::kF32 && offsets[kY] == offsets[kX] + 4 && offsets[kZ] == offsets[kX] + 8;
    if (packed) std::erase_if(fields, [](const Field& f) { return f.slot <= kZ; });
    const char* base = m_bytes.data() + m_pos;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const char* record = base + i * size;
      float v[kSlots] = {};
      if (packed) std::memcpy(v, record + offsets[kX], 3 * sizeof(float));
      for (const Field& f : fields) v[f.slot] = static_cast<float>(load_number(f.type, record + f.offset, m_swap));
      if (!all_finite(v)) [[unlikely]] {
        std::array<std::size_t, kSlots> at;
        for (int s = 0; s < kSlots; ++s) at[s] = m_pos + i * size + offsets[s];
        check_finite(v, at, layout.normals, layout.uvs);
      }
      m_mesh.set_vertex(i, v);
    }
    m_pos += e.count * size;
  }

  void variable_vertices(const Element& e, const VertexLayout& layout) {
    for (std::uint64_t r = 0; r < e.count; ++r) {
      float v[kSlots] = {};
      std::array<std::size_t, kSlots> at{};
      walk(
          e, r,
          [&](std::size_t i, std::size_t offset) {
            const Slot s = layout.slots[i];
            if (s == kSkip) return;
            v[s] = static_cast<float>(load_number(e.properties[i].type, m_bytes.data() + offset, m_swap));
            at[s] = offset;
          },
          [](std::size_t, std::size_t, std::size_t) {});
      if (!all_finite(v)) check_finite(v, at, layout.normals, layout.uvs);
      m_mesh.set_vertex(r, v);
    }
  }

  template <class Index>
  void fast_faces(const Element& e) {
    const char* const data = m_bytes.data();
    const std::size_t size = m_bytes.size();
    std::size_t pos = m_pos;
    for (std::uint64_t r = 0; r < e.count; ++r) {
      if (pos >= size) truncated(pos, e, r);
      const std::size_t n = static_cast<unsigned char>(data[pos]);
      const std::size_t items = pos + 1;
      if (n * sizeof(Index) > size - items) truncated(items, e, r);
      if (n == 3) {
        const std::int64_t a = load<Index>(data + items, m_swap);
        const std::int64_t b = load<Index>(data + items + sizeof(Index), m_swap);
        const std::int64_t c = load<Index>(data + items + 2 * sizeof(Index), m_swap);
        check_index(a, items);
        check_index(b, items + sizeof(Index));
        check_index(c, items + 2 * sizeof(Index));
        m_mesh.triangle(static_cast<std::size_t>(a), static_cast<std::size_t>(b), static_cast<std::size_t>(c));
      } else {
        m_corners.clear();
        for (std::size_t j = 0; j < n; ++j) {
          const std::size_t at = items + j * sizeof(Index);
          const std::int64_t v = load<Index>(data + at, m_swap);
          check_index(v, at);
          m_corners.push_back(static_cast<std::size_t>(v));
        }
        m_mesh.polygon(m_corners);
      }
      pos = items + n * sizeof(Index);
    }
    m_pos = pos;
  }

  const std::string& m_file;
  std::string_view m_bytes;
  std::size_t m_pos;
  bool m_swap;
  MeshSink& m_mesh;
  std::vector<std::size_t> m_corners;
};

// ------------------------------------------------------------------------------------------------
// ASCII body

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
      m_corners.clear();
      Strip strip;
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        if (i != k) {
          skip_property(e.properties[i]);
          continue;
        }
        const std::int64_t n = m_s.integer("list length", 0, max_of(p.count_type));
        for (std::int64_t j = 0; j < n; ++j) {
          const std::int64_t v = m_s.integer("vertex index", strips ? -1 : 0, vertex_count - 1);
          if (v == -1) {
            strip.restart();
          } else if (strips) {
            strip.add(static_cast<std::size_t>(v), m_mesh);
          } else {
            m_corners.push_back(static_cast<std::size_t>(v));
          }
        }
      }
      if (!strips) m_mesh.polygon(m_corners);
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

// Reads the elements in file order: vertices, faces and strips, skipping all others.
template <class Body>
void read_body(const Header& header, Body& body, const std::string& file) {
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

}  // namespace

MeshLoadReport parse_ply(std::string_view bytes, const std::string& file, Geometry& geometry, std::uint32_t object) {
  TextScanner scanner(file, bytes, 0);
  const Header header = parse_header(scanner);
  const std::size_t body_offset = scanner.offset();
  check_counts(header, bytes.size() - body_offset, file);
  MeshSink mesh(geometry, object);
  if (header.encoding == Encoding::kAscii) {
    AsciiBody body(scanner, mesh);
    read_body(header, body, file);
  } else {
    const bool big = header.encoding == Encoding::kBigEndian;
    BinaryBody body(file, bytes, body_offset, big != (std::endian::native == std::endian::big), mesh);
    read_body(header, body, file);
  }
  return mesh.report;
}

MeshLoadReport load_ply(const std::string& path, Scene& scene, std::uint32_t object) {
  const std::string bytes = read_file(path);
  return parse_ply(bytes, path, scene.geometry, object);
}

}  // namespace raylab
