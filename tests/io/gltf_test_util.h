#pragma once
// Test helper: the pieces that glTF fixtures are made of, shared by the glTF test files: base64
// for data: URIs, and PNG bytes encoded in memory.

#include <stb/stb_image_write.h>

#include <cstdint>
#include <string>
#include <vector>

namespace raylab::test {

/// `in` in base64 (RFC 4648, with padding), for data: URIs.
inline std::string base64(const std::vector<unsigned char>& in) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t{in[i]} << 16) | (i + 1 < in.size() ? std::uint32_t{in[i + 1]} << 8 : 0) |
                            (i + 2 < in.size() ? std::uint32_t{in[i + 2]} : 0);
    out += kDigits[(n >> 18) & 63];
    out += kDigits[(n >> 12) & 63];
    out += i + 1 < in.size() ? kDigits[(n >> 6) & 63] : '=';
    out += i + 2 < in.size() ? kDigits[n & 63] : '=';
  }
  return out;
}

/// An 8-bit RGB PNG of `width` x `height` texels, `rgb` row by row from the top, as bytes.
inline std::vector<unsigned char> png_bytes(int width, int height, const unsigned char* rgb) {
  std::vector<unsigned char> out;
  const auto sink = [](void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<unsigned char>*>(context);
    bytes->insert(bytes->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
  };
  stbi_write_png_to_func(sink, &out, width, height, 3, rgb, width * 3);
  return out;
}

}  // namespace raylab::test
