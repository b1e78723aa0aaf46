#include "raylab/io/texture_io.h"

// Debian ships stb_image as a prebuilt shared library (libstb), which image_io.cpp already links,
// so this file only includes the interface. That has one consequence for safety: the library's
// decoder was compiled with its own STBI_MAX_DIMENSIONS (2^24 per side), and defining the macro
// here would change nothing. Compiling a second stb_image implementation into raylab just for
// the macro would put two copies of every stbi_* symbol in one program. So the size limit is
// raylab's own: the header is read first (by raylab and by stbi_info_from_memory) and an image
// above kMaxTextureSide / kMaxTextureTexels is refused before stbi_load is ever called.
#include <stb/stb_image.h>

#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <optional>
#include <type_traits>
#include <vector>

#include "raylab/core/error.h"
#include "raylab/io/image_io.h"
#include "raylab/io/read_file.h"
#include "raylab/render/film.h"

namespace raylab {
namespace {

enum class ImageFormat { kPng, kJpeg };

struct ImageSize {
  std::uint64_t width = 0;
  std::uint64_t height = 0;
};

// Throws the InputError of one texture, `element` leading the message when given.
[[noreturn]] void fail(const std::string& file, const std::string& element, const std::string& message) {
  throw InputError(file, element.empty() ? message : element + ": " + message);
}

// PNG or JPEG by signature. stb_image also reads TGA, whose header has no signature at all, so
// without this check almost any bytes would "decode" as a TGA picture instead of being refused.
std::optional<ImageFormat> sniff_format(std::span<const unsigned char> bytes) {
  static constexpr std::array<unsigned char, 8> kPng = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() >= kPng.size() && std::memcmp(bytes.data(), kPng.data(), kPng.size()) == 0) return ImageFormat::kPng;
  if (bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff) return ImageFormat::kJpeg;
  return std::nullopt;
}

std::uint64_t read_be32(const unsigned char* p) {
  return (std::uint64_t{p[0]} << 24) | (std::uint64_t{p[1]} << 16) | (std::uint64_t{p[2]} << 8) | p[3];
}

// The size a PNG's IHDR chunk (always the first, at a fixed offset) claims.
std::optional<ImageSize> png_header_size(std::span<const unsigned char> bytes) {
  if (bytes.size() < 24 || std::memcmp(bytes.data() + 12, "IHDR", 4) != 0) return std::nullopt;
  return ImageSize{read_be32(bytes.data() + 16), read_be32(bytes.data() + 20)};
}

// The size the first start-of-frame segment of a JPEG claims, found by walking the segments
// that precede it.
std::optional<ImageSize> jpeg_header_size(std::span<const unsigned char> bytes) {
  std::size_t p = 2;  // after SOI
  while (p + 4 <= bytes.size()) {
    if (bytes[p] != 0xff) return std::nullopt;
    const unsigned char marker = bytes[p + 1];
    if (marker == 0xff) {  // fill byte
      ++p;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) {  // segments without a length
      p += 2;
      continue;
    }
    if (marker == 0xd9 || marker == 0xda) return std::nullopt;  // end of image, or scan data: no frame header
    const std::size_t length = (std::size_t{bytes[p + 2]} << 8) | bytes[p + 3];
    const bool frame = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
    if (frame) {
      if (p + 9 > bytes.size()) return std::nullopt;
      const std::uint64_t height = (std::uint64_t{bytes[p + 5]} << 8) | bytes[p + 6];
      const std::uint64_t width = (std::uint64_t{bytes[p + 7]} << 8) | bytes[p + 8];
      return ImageSize{width, height};
    }
    p += 2 + length;
  }
  return std::nullopt;
}

void check_size_limits(ImageSize size, const std::string& file, const std::string& element) {
  if (size.width <= kMaxTextureSide && size.height <= kMaxTextureSide &&
      size.width * size.height <= kMaxTextureTexels) {
    return;
  }
  fail(file, element,
       "image of " + std::to_string(size.width) + " x " + std::to_string(size.height) +
           " texels is too large (textures are limited to " + std::to_string(kMaxTextureSide) + " per side and " +
           std::to_string(kMaxTextureTexels) + " texels); refused before decoding");
}

std::string failure_reason() {
  const char* reason = stbi_failure_reason();
  return reason != nullptr ? reason : "unknown reason";
}

const char* format_name(ImageFormat format) { return format == ImageFormat::kPng ? "PNG" : "JPEG"; }

// Reads and checks the size from the header only; nothing is decoded yet. The size is read twice:
// by raylab, so that the limit and the message rest on what the file claims (stb_image refuses
// some huge headers itself, but then tries its other formats and reports only "unknown image
// type"), and by stbi_info_from_memory, so that what stb_image will decode is checked as well.
ImageSize checked_header_size(std::span<const unsigned char> bytes, ImageFormat format, const std::string& file,
                              const std::string& element) {
  const std::optional<ImageSize> claimed =
      format == ImageFormat::kPng ? png_header_size(bytes) : jpeg_header_size(bytes);
  if (!claimed) fail(file, element, std::string("not a valid ") + format_name(format) + " image (no image header)");
  check_size_limits(*claimed, file, element);
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height, &channels) == 0) {
    fail(file, element, std::string("not a valid ") + format_name(format) + " image (" + failure_reason() + ")");
  }
  const ImageSize size{static_cast<std::uint64_t>(width), static_cast<std::uint64_t>(height)};
  if (size.width != claimed->width || size.height != claimed->height) {
    fail(file, element, "inconsistent image header");
  }
  return size;
}

// Decodes `bytes` to RGB with `load` (stb_image's 8-bit or 16-bit decoder, whose samples the
// image keeps) and maps each sample to linear with `to_linear`. The decoded size must be the one
// the header promised, on which the size limits were checked.
template <class Load, class ToLinear>
std::vector<Color> decode_rgb(std::span<const unsigned char> bytes, ImageSize size, const std::string& file,
                              const std::string& element, Load load, ToLinear to_linear) {
  int width = 0, height = 0, channels = 0;
  auto* data = load(bytes.data(), static_cast<int>(bytes.size()), &width, &height, &channels, 3);
  if (data == nullptr) fail(file, element, "cannot decode image: " + failure_reason());
  std::unique_ptr<std::remove_pointer_t<decltype(data)>, void (*)(void*)> owner(data, stbi_image_free);
  if (static_cast<std::uint64_t>(width) != size.width || static_cast<std::uint64_t>(height) != size.height) {
    fail(file, element, "image size changed between header and decoding");
  }
  std::vector<Color> texels(size.width * size.height);
  for (std::size_t i = 0; i < texels.size(); ++i) {
    texels[i] = {to_linear(data[3 * i]), to_linear(data[3 * i + 1]), to_linear(data[3 * i + 2])};
  }
  return texels;
}

}  // namespace

std::shared_ptr<const TextureImage> decode_texture(std::span<const unsigned char> bytes, const std::string& file,
                                                   const std::string& element, TextureEncoding encoding) {
  const std::optional<ImageFormat> format = sniff_format(bytes);
  if (!format) fail(file, element, "not a PNG or JPEG image (textures must be one of the two)");
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) fail(file, element, "image file is larger than 2 GiB");
  const ImageSize size = checked_header_size(bytes, *format, file, element);
  const bool sixteen_bit =
      *format == ImageFormat::kPng && stbi_is_16_bit_from_memory(bytes.data(), static_cast<int>(bytes.size())) != 0;
  // 16-bit PNGs keep their precision: decoding them to 8 bits first would band smooth gradients.
  const bool srgb = encoding == TextureEncoding::kSrgb;
  std::vector<Color> texels = sixteen_bit ? decode_rgb(bytes, size, file, element, stbi_load_16_from_memory,
                                                       [srgb](stbi_us v) {
                                                         const float s = static_cast<float>(v) / 65535.f;
                                                         return srgb ? srgb_to_linear(s) : s;
                                                       })
                                          : decode_rgb(bytes, size, file, element, stbi_load_from_memory,
                                                       [srgb, &table = srgb8_to_linear_table()](stbi_uc v) {
                                                         return srgb ? table[v] : static_cast<float>(v) / 255.f;
                                                       });
  return std::make_shared<const TextureImage>(static_cast<int>(size.width), static_cast<int>(size.height),
                                              std::move(texels));
}

std::shared_ptr<const TextureImage> load_texture(const std::string& path, TextureEncoding encoding) {
  const std::string bytes = read_file(path);
  return decode_texture(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()), path, "",
                        encoding);
}

std::optional<std::vector<unsigned char>> encode_texture_png(const TextureImage& image, TextureEncoding encoding) {
  // The PNG writer stores linear_to_srgb(value) in 8 bits, and stores code c exactly when given
  // table[c]: the film holds table[code] for the code each texel needs in its encoding.
  const std::array<float, 256>& table = srgb8_to_linear_table();
  const bool srgb = encoding == TextureEncoding::kSrgb;
  Film film(image.width(), image.height());
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const Color c = image.texel(x, y);
      Color stored;
      for (int k = 0; k < 3; ++k) {
        // The 8-bit value stored must decode to this very float.
        const long code = std::lround((srgb ? linear_to_srgb(c[k]) : c[k]) * 255.f);
        if (code < 0 || code > 255) return std::nullopt;
        const float decoded = srgb ? table[static_cast<std::size_t>(code)] : static_cast<float>(code) / 255.f;
        if (decoded != c[k]) return std::nullopt;
        stored[k] = table[static_cast<std::size_t>(code)];
      }
      film.at(x, y) = stored;
    }
  }
  return encode_image(film, ".png");
}

}  // namespace raylab
