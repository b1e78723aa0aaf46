#pragma once
/// \file
/// A plain 8-bit sRGB picture (heat maps, their legends) and its PNG writer.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

/// An 8-bit sRGB colour.
struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  /// Channel-wise equality.
  constexpr bool operator==(const Rgb8&) const = default;
};

/// An 8-bit sRGB image, rows from the top.
struct Rgb8Image {
  int width = 0;
  int height = 0;
  std::vector<Rgb8> pixels;  ///< row-major

  /// A `width` x `height` image filled with `fill`.
  Rgb8Image(int w, int h, Rgb8 fill = {});
  /// Pixel (x, y); no range check.
  Rgb8& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// Pixel (x, y); no range check.
  const Rgb8& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// Sets (x, y) when it lies inside the image; drawing is clipped this way.
  void put(int x, int y, Rgb8 c);
};

/// Writes `image` as a PNG file, atomically (InputError when it cannot be written); the bytes
/// read back are exactly the image's.
void write_png(const Rgb8Image& image, const std::string& path);

}  // namespace raylab
