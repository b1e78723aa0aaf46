#pragma once
/// \file
/// A running 64-bit hash for fingerprints and checksums: eight bytes at a time, multiply and
/// rotate, as the fast non-cryptographic hashes do. It catches accidents (a changed scene, a
/// damaged file), not forgeries.

#include <bit>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace raylab {

/// Accumulates words and byte strings into a 64-bit value.
class Hash64 {
 public:
  /// Adds one 64-bit word.
  void word(std::uint64_t w) { m_state = std::rotl((m_state ^ w) * 0x9E3779B97F4A7C15ull, 31) * 0xBF58476D1CE4E5B9ull; }
  /// Adds `n` bytes, preceded by their count (so that where one string ends and the next starts
  /// changes the result).
  void bytes(const void* data, std::size_t n) {
    word(n);
    const auto* p = static_cast<const unsigned char*>(data);
    for (; n >= 8; n -= 8, p += 8) {
      std::uint64_t w;
      std::memcpy(&w, p, 8);
      word(w);
    }
    std::uint64_t tail = 0;
    if (n > 0) std::memcpy(&tail, p, n);  // p may be null when nothing is left (an empty array)
    word(tail);
  }
  /// The hash of one byte string: stable across runs, builds and machines, so fit for names of
  /// cache files and keys written to disk.
  static std::uint64_t of(std::string_view text) {
    Hash64 h;
    h.bytes(text.data(), text.size());
    return h.value();
  }
  /// The hash of everything added so far.
  std::uint64_t value() const { return m_state; }

 private:
  std::uint64_t m_state = 0x6A09E667F3BCC908ull;
};

}  // namespace raylab
