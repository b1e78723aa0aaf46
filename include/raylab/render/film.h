#pragma once
/// \file
/// The image being rendered: linear RGB per pixel.

#include <stdexcept>
#include <utility>
#include <vector>

#include "raylab/core/vec3.h"

namespace raylab {

/// A width x height image of linear RGB, rows from top to bottom.
class Film {
 public:
  /// A black image.
  Film(int width, int height) : m_width(width), m_height(height), m_pixels(std::size_t(width) * height) {}
  /// The image whose pixels, row-major from the top row, are `pixels` (taken over, not copied);
  /// throws std::invalid_argument unless it holds width x height of them.
  Film(int width, int height, std::vector<Color> pixels)
      : m_width(width), m_height(height), m_pixels(std::move(pixels)) {
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
  const std::vector<Color>& pixels() const { return m_pixels; }

 private:
  int m_width;
  int m_height;
  std::vector<Color> m_pixels;
};

}  // namespace raylab
