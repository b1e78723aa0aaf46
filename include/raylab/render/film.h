#pragma once
/// \file
/// The image being rendered: linear RGB per pixel.

#include <stdexcept>
#include <utility>
#include <vector>

#include "raylab/core/uninitialized_vector.h"
#include "raylab/core/vec3.h"

namespace raylab {

/// A width x height image of linear RGB, rows from top to bottom.
class Film {
 public:
  /// Where the pixels live: a vector whose blocks of 1 MiB or more come in huge pages
  /// (uninitialized_vector.h), as a 512 x 512 image's does.
  using Pixels = UninitializedVector<Color>;

  /// A black image.
  Film(int width, int height) : m_width(width), m_height(height), m_pixels(std::size_t(width) * height) {}
  /// The image whose pixels, row-major from the top row, are `pixels` (taken over, not copied);
  /// throws std::invalid_argument unless it holds width x height of them.
  Film(int width, int height, Pixels pixels) : m_width(width), m_height(height), m_pixels(std::move(pixels)) {
    if (width < 0 || height < 0 || m_pixels.size() != std::size_t(width) * std::size_t(height)) {
      throw std::invalid_argument("Film: the pixels are not width x height");
    }
  }

  int width() const { return m_width; }
  int height() const { return m_height; }
  /// Pixel (x, y); no range check.
  Color& at(int x, int y) { return m_pixels[std::size_t(y) * m_width + x]; }
  /// Pixel (x, y); no range check.
  const Color& at(int x, int y) const { return m_pixels[std::size_t(y) * m_width + x]; }
  /// All pixels, row-major from the top row.
  const Pixels& pixels() const { return m_pixels; }

 private:
  int m_width;
  int m_height;
  Pixels m_pixels;
};

}  // namespace raylab
