#include "raylab/io/rgb8_image.h"

#include <array>

#include "raylab/core/srgb.h"
#include "raylab/io/image_io.h"
#include "raylab/render/film.h"

namespace raylab {

Rgb8Image::Rgb8Image(int w, int h, Rgb8 fill)
    : width(w), height(h), pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}

void Rgb8Image::put(int x, int y, Rgb8 c) {
  if (x >= 0 && y >= 0 && x < width && y < height) at(x, y) = c;
}

void write_png(const Rgb8Image& image, const std::string& path) {
  // Through the film writer, which encodes linear values to sRGB: decoding each byte to linear
  // first makes the round trip exact (tested), and keeps one PNG writer and its atomic write.
  Film film(image.width, image.height);
  const std::array<float, 256>& linear = srgb8_to_linear_table();
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Rgb8 c = image.at(x, y);
      film.at(x, y) = Color{linear[c.r], linear[c.g], linear[c.b]};
    }
  }
  write_image(film, path);
}

}  // namespace raylab
