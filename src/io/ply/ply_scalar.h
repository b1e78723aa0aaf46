#pragma once
// Internal to the PLY reader: the eight scalar types a PLY property can have, and how a value of
// one is read from a binary body. One dispatch from type to C++ type serves every reader, so that
// the list of types is written once.

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace raylab::ply_detail {

/// A PLY scalar type: `char`/`int8` ... `double`/`float64`.
enum class Scalar : std::uint8_t { kI8, kU8, kI16, kU16, kI32, kU32, kF32, kF64 };

/// Bytes a value of type `t` takes in a binary body.
constexpr std::size_t size_of(Scalar t) {
  constexpr std::size_t kSizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return kSizes[static_cast<int>(t)];
}

/// Whether `t` is one of the integer types (list lengths and vertex indices must be).
constexpr bool is_integer(Scalar t) { return t != Scalar::kF32 && t != Scalar::kF64; }

/// Returns `f(T{})` with `T` the C++ type of `t`, so that code generic in `T` serves all types.
template <class F>
constexpr auto visit_scalar(Scalar t, F&& f) {
  switch (t) {
    case Scalar::kI8:
      return f(std::int8_t{});
    case Scalar::kU8:
      return f(std::uint8_t{});
    case Scalar::kI16:
      return f(std::int16_t{});
    case Scalar::kU16:
      return f(std::uint16_t{});
    case Scalar::kI32:
      return f(std::int32_t{});
    case Scalar::kU32:
      return f(std::uint32_t{});
    case Scalar::kF32:
      return f(float{});
    default:
      return f(double{});
  }
}

/// Largest value of integer type `t`: the bound of a list length in an ASCII body. The float
/// types, which the header refuses as a length type, answer the largest uint.
inline std::int64_t max_of(Scalar t) {
  return visit_scalar(t, [](auto zero) -> std::int64_t {
    using T = decltype(zero);
    if constexpr (std::is_integral_v<T>) {
      return std::numeric_limits<T>::max();
    } else {
      return std::numeric_limits<std::uint32_t>::max();
    }
  });
}

/// A `T` stored at `p`, byte-swapped when the file's byte order is not the machine's.
template <class T>
T load(const char* p, bool swap) {
  std::array<char, sizeof(T)> raw;
  std::memcpy(raw.data(), p, sizeof(T));
  if (swap) std::reverse(raw.begin(), raw.end());
  return std::bit_cast<T>(raw);
}

/// The value of type `t` at `p`, as a double (exact for every PLY type).
inline double load_number(Scalar t, const char* p, bool swap) {
  return visit_scalar(t, [&](auto zero) { return static_cast<double>(load<decltype(zero)>(p, swap)); });
}

/// The value of integer type `t` at `p` (list lengths and indices, whose types the header
/// checks); 0 for the float types.
inline std::int64_t load_integer(Scalar t, const char* p, bool swap) {
  return visit_scalar(t, [&](auto zero) -> std::int64_t {
    using T = decltype(zero);
    if constexpr (std::is_integral_v<T>) {
      return load<T>(p, swap);
    } else {
      return 0;
    }
  });
}

}  // namespace raylab::ply_detail
