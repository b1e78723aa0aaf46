#include "ply_body.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace raylab::ply_detail {
namespace {

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
      FaceRecord face(m_mesh, strips, m_corners);
      walk(
          e, r, [](std::size_t, std::size_t) {},
          [&](std::size_t i, std::size_t n, std::size_t at) {
            if (i != k) return;
            for (std::size_t j = 0; j < n; ++j, at += size_of(p.type)) {
              const std::int64_t v = load_integer(p.type, m_bytes.data() + at, m_swap);
              if (!strips || v != -1) check_index(v, at);
              face.add(v);
            }
          });
      face.finish();
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

}  // namespace

void read_binary_body(const Header& header, std::string_view bytes, std::size_t offset, bool swap,
                      const std::string& file, MeshSink& mesh) {
  BinaryBody body(file, bytes, offset, swap, mesh);
  read_elements(header, body, file);
}

}  // namespace raylab::ply_detail
