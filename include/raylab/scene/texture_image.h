#pragma once
/// \file
/// A decoded image texture in linear RGB, sampled bilinearly with repeat addressing.
///
/// Texture-coordinate convention (the one OBJ's `vt` uses, and the one every raylab loader
/// stores in Geometry::triangle_uvs): u runs left to right and v runs bottom to top, so (0, 0)
/// is the bottom-left corner of the image as its file shows it and (1, 1) the top-right corner.
/// Image files store their top row first, hence the flip of v inside sample(). glTF puts (0, 0)
/// at the top-left instead; the glTF loader stores 1 - v so that both end up here the same way.

#include <cstddef>
#include <vector>

#include "raylab/core/vec3.h"

namespace raylab {

/// Immutable linear-RGB float texels, row-major, row 0 at the top of the image.
class TextureImage {
 public:
  /// An image of `width` x `height` texels (both > 0), `texels` row-major from the top row.
  /// Throws std::invalid_argument when the sizes do not match or are not positive.
  TextureImage(int width, int height, std::vector<Color> texels);

  /// Width in texels.
  int width() const { return m_width; }
  /// Height in texels.
  int height() const { return m_height; }
  /// The texel in column `x` (0 = left) of row `y` (0 = top); both must be in range.
  Color texel(int x, int y) const { return m_texels[static_cast<std::size_t>(y) * m_width + x]; }

  /// Bilinear interpolation of the four texels around (u, v), with texel centres at
  /// ((x + 0.5) / width, 1 - (y + 0.5) / height) and repeat (wrap) addressing in both directions,
  /// so u = 1.25 reads as u = 0.25 and the left and right edges blend into each other.
  /// A non-finite coordinate reads the top-left texel (a degenerate triangle's uvs can be NaN;
  /// the result must still be a colour, and a fixed one keeps renders deterministic).
  Color sample(float u, float v) const;

 private:
  int m_width;
  int m_height;
  std::vector<Color> m_texels;
};

}  // namespace raylab
