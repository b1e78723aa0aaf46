#include "raylab/io/image_io.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>

#include "exr_codec.h"
#include "raylab/core/error.h"
#include "raylab/io/atomic_file.h"
#include "raylab/io/file_extension.h"

namespace raylab {
namespace {

constexpr std::array<std::string_view, 3> kExtensions = {".png", ".exr", ".pfm"};

std::vector<unsigned char> encode_png(const Film& film) {
  std::vector<unsigned char> rgb(std::size_t(film.width()) * film.height() * 3);
  for (std::size_t i = 0; i < film.pixels().size(); ++i) {
    const Color c = film.pixels()[i];
    for (int k = 0; k < 3; ++k) {
      rgb[3 * i + k] = static_cast<unsigned char>(std::lround(linear_to_srgb(c[k]) * 255.f));
    }
  }
  std::vector<unsigned char> out;
  auto sink = [](void* context, void* data, int size) {
    auto* v = static_cast<std::vector<unsigned char>*>(context);
    v->insert(v->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
  };
  if (!stbi_write_png_to_func(sink, &out, film.width(), film.height(), 3, rgb.data(), film.width() * 3)) {
    throw InputError("", "PNG encoding failed");
  }
  return out;
}

// PFM: a text header, then little-endian float rows from the bottom of the image up. A film row
// is already the file's row (three floats a pixel, in this machine's little-endian order), so the
// file is the header followed by the film's rows, last first, each taken whole. (Appending pixel
// by pixel cost 36 instructions a pixel more, 3.6% of the whole process on SPD tetra: callgrind,
// docs/performance.md.)
std::string pfm_header(const Film& film) {
  return "PF\n" + std::to_string(film.width()) + " " + std::to_string(film.height()) + "\n-1.0\n";
}

// The file's bytes in order: `header` (pfm_header(film)), then the rows; they point into both.
std::vector<std::span<const unsigned char>> pfm_pieces(const Film& film, const std::string& header) {
  static_assert(sizeof(Color) == 3 * sizeof(float) && std::is_trivially_copyable_v<Color>);
  const std::size_t row_bytes = std::size_t(film.width()) * sizeof(Color);
  std::vector<std::span<const unsigned char>> pieces;
  pieces.reserve(std::size_t(film.height()) + 1);
  pieces.emplace_back(reinterpret_cast<const unsigned char*>(header.data()), header.size());
  if (row_bytes == 0) return pieces;  // an empty film has no row to take the address of
  for (int y = film.height() - 1; y >= 0; --y) {
    pieces.emplace_back(reinterpret_cast<const unsigned char*>(&film.at(0, y)), row_bytes);
  }
  return pieces;
}

std::vector<unsigned char> encode_pfm(const Film& film) {
  const std::string header = pfm_header(film);
  std::vector<unsigned char> out;
  out.reserve(header.size() + std::size_t(film.width()) * std::size_t(film.height()) * sizeof(Color));
  for (const std::span<const unsigned char> piece : pfm_pieces(film, header))
    out.insert(out.end(), piece.begin(), piece.end());
  return out;
}

// Layers are programmer input: a mismatch is a bug in the caller, not a user error.
void check_layers(const Film& film, std::span<const ImageLayer> layers) {
  const std::size_t pixels = std::size_t(film.width()) * std::size_t(film.height());
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const ImageLayer& l = layers[i];
    if (l.values.size() != pixels) {
      throw std::invalid_argument("image layer '" + l.name + "' has " + std::to_string(l.values.size()) +
                                  " values for " + std::to_string(pixels) + " pixels");
    }
    if (l.name.empty() || l.name == "R" || l.name == "G" || l.name == "B") {
      throw std::invalid_argument("image layer name '" + l.name + "' is empty or taken by the colour");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (layers[j].name == l.name) throw std::invalid_argument("image layer '" + l.name + "' is given twice");
    }
  }
}

// Through the EXR module (exr_codec.h), loaded the first time an EXR file is read or written.
std::vector<unsigned char> encode_exr(const Film& film, std::span<const ImageLayer> layers) {
  return exr_codec().encode(film, layers);
}

Film read_pfm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open file");
  std::string magic;
  int w = 0, h = 0;
  double scale = 0;
  in >> magic >> w >> h >> scale;
  in.get();
  if (magic != "PF" || w <= 0 || h <= 0 || !in) throw InputError(path, 1, 1, "not an RGB PFM file");
  if (scale > 0) throw InputError(path, 3, 1, "big-endian PFM is not supported");
  Film film(w, h);
  for (int y = h - 1; y >= 0; --y) {
    for (int x = 0; x < w; ++x) {
      float v[3];
      if (!in.read(reinterpret_cast<char*>(v), sizeof v)) throw InputError(path, "PFM file is truncated");
      film.at(x, y) = {v[0], v[1], v[2]};
    }
  }
  return film;
}

Film read_exr(const std::string& path) {
  const ExrCodec& codec = exr_codec();  // a missing module is not a damaged file
  try {
    return codec.read(path);
  } catch (const std::exception&) {
    // The file was readable (read_image checks first); OpenEXR's reason is a paragraph.
    throw InputError(path, "not an EXR image (or a damaged one)");
  }
}

Film read_png(const std::string& path) {
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 3);
  if (!data) {
    // The file was readable (read_image checks first): what stb_image could not do is decode it.
    const bool png = lowercase_extension(path) == ".png";
    throw InputError(path, png ? "not a PNG image (or a damaged one)"
                               : "not an image raylab reads (.png, .exr or .pfm, or another format stb_image reads)");
  }
  Film film(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = data + 3 * (std::size_t(y) * w + x);
      film.at(x, y) = {srgb_to_linear(p[0] / 255.f), srgb_to_linear(p[1] / 255.f), srgb_to_linear(p[2] / 255.f)};
    }
  }
  stbi_image_free(data);
  return film;
}

}  // namespace

std::span<const std::string_view> image_extensions() { return kExtensions; }

void check_image_extension(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  if (std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end()) return;
  throw UsageError("cannot write '" + path + "': unknown image format '" + (ext.empty() ? "(none)" : ext) +
                   "' (valid: .png, .exr, .pfm)");
}

std::vector<unsigned char> encode_image(const Film& film, std::string_view extension,
                                        std::span<const ImageLayer> layers) {
  check_layers(film, layers);
  if (extension == ".png") return encode_png(film);
  if (extension == ".pfm") return encode_pfm(film);
  if (extension == ".exr") return encode_exr(film, layers);
  throw UsageError("unknown image format '" + std::string(extension) + "' (valid: .png, .exr, .pfm)");
}

void write_image(const Film& film, const std::string& path) { write_image(film, path, {}); }

void write_image(const Film& film, const std::string& path, std::span<const ImageLayer> layers) {
  check_image_extension(path);
  const std::string extension = lowercase_extension(path);
  if (extension == ".pfm") {
    // Straight from the film's rows: a copy of the image would take as many fresh pages as the
    // film, each a costly fault on a virtual machine (docs/performance.md, "Page faults").
    check_layers(film, layers);
    const std::string header = pfm_header(film);
    write_pieces_atomically(path, pfm_pieces(film, header));
    return;
  }
  const std::vector<unsigned char> bytes = encode_image(film, extension, layers);
  write_file_atomically(path, bytes);
}

namespace {

// "cannot read: no such file" and the like, before a decoder words it its own way (stb_image
// says "can't fopen", OpenEXR a paragraph).
void check_readable(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (status.type() == std::filesystem::file_type::not_found) throw InputError(path, "cannot read: no such file");
  if (std::filesystem::is_directory(status)) throw InputError(path, "cannot read: it is a folder");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) {
    std::string reason = std::strerror(errno);
    if (!reason.empty()) reason[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(reason[0])));
    throw InputError(path, "cannot read: " + reason);
  }
  std::fclose(f);
}

}  // namespace

Film read_image(const std::string& path) {
  check_readable(path);
  const std::string ext = lowercase_extension(path);
  if (ext == ".pfm") return read_pfm(path);
  if (ext == ".exr") return read_exr(path);
  return read_png(path);
}

std::vector<ImageLayer> read_exr_channels(const std::string& path) {
  const ExrCodec& codec = exr_codec();  // a missing module is not a damaged file
  try {
    return codec.read_channels(path);
  } catch (const std::exception& e) {
    throw InputError(path, std::string("cannot read EXR: ") + e.what());
  }
}

namespace {

void require_same_size(const Film& a, const Film& b) {
  if (a.width() != b.width() || a.height() != b.height()) {
    throw InputError("", "images differ in size: " + std::to_string(a.width()) + "x" + std::to_string(a.height()) +
                             " and " + std::to_string(b.width()) + "x" + std::to_string(b.height()));
  }
}

}  // namespace

double image_rmse(const Film& a, const Film& b) {
  require_same_size(a, b);
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double d = 255.0 * (linear_to_srgb(a.pixels()[i][k]) - linear_to_srgb(b.pixels()[i][k]));
      sum += d * d;
    }
  }
  const double n = 3.0 * static_cast<double>(a.pixels().size());
  return n > 0 ? std::sqrt(sum / n) : 0.0;
}

Film difference_image(const Film& a, const Film& b, float scale) {
  require_same_size(a, b);
  Film out(a.width(), a.height());
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      for (int k = 0; k < 3; ++k) {
        const float d = std::abs(linear_to_srgb(a.at(x, y)[k]) - linear_to_srgb(b.at(x, y)[k]));
        out.at(x, y)[k] = srgb_to_linear(std::min(1.f, d * scale));
      }
    }
  }
  return out;
}

}  // namespace raylab
