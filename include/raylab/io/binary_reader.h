#pragma once
/// \file
/// Bounds-checked little- and big-endian reads from bytes in memory, for binary PLY and STL.

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "raylab/core/error.h"

namespace raylab {

/// Reads scalars from a byte buffer; every read is checked against the end, and a short read
/// throws InputError "file: byte N: unexpected end of file ...".
class BinaryReader {
 public:
  /// Reads `bytes` (which must outlive the reader) of file `file`, starting at `offset`.
  BinaryReader(std::string file, std::string_view bytes, std::size_t offset = 0)
      : m_file(std::move(file)), m_bytes(bytes), m_pos(offset) {}

  /// Reads a `T` (arithmetic) stored little-endian (`big_endian` false) or big-endian.
  template <class T>
  T read(bool big_endian, std::string_view what) {
    require(sizeof(T), what);
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, m_bytes.data() + m_pos, sizeof(T));
    if (big_endian != (std::endian::native == std::endian::big)) {
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    }
    T value;
    std::memcpy(&value, raw, sizeof(T));
    m_pos += sizeof(T);
    return value;
  }
  /// Skips `n` bytes (checked).
  void skip(std::size_t n, std::string_view what) {
    require(n, what);
    m_pos += n;
  }
  /// Throws unless `n` more bytes are available.
  void require(std::size_t n, std::string_view what) const {
    if (n > m_bytes.size() - m_pos) {
      throw InputError::at_byte(m_file, m_pos,
                                "unexpected end of file reading " + std::string(what) + " (" + std::to_string(n) +
                                    " bytes needed, " + std::to_string(m_bytes.size() - m_pos) + " left)");
    }
  }
  /// Bytes left to read.
  std::size_t remaining() const { return m_bytes.size() - m_pos; }
  /// Current byte offset.
  std::size_t offset() const { return m_pos; }
  /// Throws InputError at `offset`.
  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    throw InputError::at_byte(m_file, offset, message);
  }

 private:
  std::string m_file;
  std::string_view m_bytes;
  std::size_t m_pos;
};

}  // namespace raylab
