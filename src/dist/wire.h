#pragma once
// Internal to the dist module: the bytes of the messages between ranks. Values are copied as
// they lie in memory: every rank of a run is the same program on the same kind of machine (one
// build, one byte order), which a hello message checks before any work is exchanged.

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace raylab::dist::wire {

/// Appends values to a message's bytes.
class Writer {
 public:
  /// Appends a trivially copyable value.
  template <class T>
  Writer& put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    m_bytes.insert(m_bytes.end(), p, p + sizeof(T));
    return *this;
  }
  /// Appends a vector (a std::vector, whatever its allocator) of trivially copyable values,
  /// preceded by its length.
  template <class Vector>
  Writer& put_vector(const Vector& values) {
    using T = typename Vector::value_type;
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(values.size());
    const auto* p = reinterpret_cast<const std::uint8_t*>(values.data());
    m_bytes.insert(m_bytes.end(), p, p + values.size() * sizeof(T));
    return *this;
  }
  /// Appends a string, preceded by its length.
  Writer& put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    m_bytes.insert(m_bytes.end(), s.begin(), s.end());
    return *this;
  }
  /// The bytes written, moved out.
  std::vector<std::uint8_t> take() { return std::move(m_bytes); }

 private:
  std::vector<std::uint8_t> m_bytes;
};

/// Reads values back in the order a Writer put them; throws std::runtime_error when the bytes
/// end early or hold an impossible length (a message from another program, or a bug).
class Reader {
 public:
  /// A reader over `bytes` (which must outlive it).
  explicit Reader(const std::vector<std::uint8_t>& bytes) : m_bytes(bytes) {}

  /// The next value of type T.
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    T value;
    std::memcpy(&value, m_bytes.data() + m_at, sizeof(T));
    m_at += sizeof(T);
    return value;
  }
  /// The next vector of T.
  template <class T>
  std::vector<T> get_vector() {
    const auto n = get<std::uint64_t>();
    if (n > (m_bytes.size() - m_at) / sizeof(T)) throw std::runtime_error("a message ends before its array does");
    std::vector<T> values(static_cast<std::size_t>(n));
    if (n > 0) std::memcpy(values.data(), m_bytes.data() + m_at, static_cast<std::size_t>(n) * sizeof(T));
    m_at += static_cast<std::size_t>(n) * sizeof(T);
    return values;
  }
  /// The next string.
  std::string get_string() {
    const auto n = get<std::uint64_t>();
    if (n > m_bytes.size() - m_at) throw std::runtime_error("a message ends before its text does");
    std::string s(reinterpret_cast<const char*>(m_bytes.data() + m_at), static_cast<std::size_t>(n));
    m_at += static_cast<std::size_t>(n);
    return s;
  }

 private:
  void need(std::size_t n) const {
    if (n > m_bytes.size() - m_at) throw std::runtime_error("a message is shorter than its contents");
  }
  const std::vector<std::uint8_t>& m_bytes;
  std::size_t m_at = 0;
};

}  // namespace raylab::dist::wire
