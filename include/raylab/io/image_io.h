#pragma once
/// \file
/// Image files: PNG (8-bit sRGB), OpenEXR (float RGB plus extra layers) and PFM, chosen by
/// extension.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "raylab/core/srgb.h"  // linear_to_srgb, srgb_to_linear (moved to core; kept visible here)
#include "raylab/render/film.h"

namespace raylab {

/// Extensions the writer accepts, with the dot (".png", ".exr", ".pfm").
std::span<const std::string_view> image_extensions();

/// Throws UsageError listing the valid extensions unless `path` ends with one (case-insensitive).
void check_image_extension(const std::string& path);

/// Writes `film` to `path`, format by extension, atomically (see write_file_atomically).
/// PNG gets the sRGB transfer curve and 8 bits; EXR and PFM keep linear floats.
void write_image(const Film& film, const std::string& path);

/// A per-pixel value stored next to the colour in an EXR file (sample count, traversal cost).
struct ImageLayer {
  /// The EXR channel name, used as given. By the OpenEXR naming convention "layer.channel"
  /// groups channels in viewers, so a single-valued layer is best called e.g. "samples.Y".
  std::string name;
  std::vector<float> values;  ///< width x height values, row-major from the top row
};

/// Writes `film` to `path` like write_image(film, path), and for .exr each of `layers` as one
/// more FLOAT channel next to R, G and B. PNG and PFM have no room for extra channels: there
/// the layers are ignored. Throws std::invalid_argument when a layer has the wrong number of
/// values, an empty name, or a name used twice or by R, G or B.
void write_image(const Film& film, const std::string& path, std::span<const ImageLayer> layers);

/// Encodes `film` as bytes of the format named by `extension` (".png", ".pfm", ".exr"); `layers`
/// as in write_image (EXR only).
std::vector<unsigned char> encode_image(const Film& film, std::string_view extension,
                                        std::span<const ImageLayer> layers = {});

/// Reads a PNG (decoded to linear), PFM or EXR file into a film; throws InputError on failure.
Film read_image(const std::string& path);

/// Every channel of EXR file `path` (R, G, B and the extra layers) as named in the file, in the
/// file's (alphabetical) order, each converted to float, width x height values row-major from
/// the top. Throws InputError naming the file when it cannot be read.
std::vector<ImageLayer> read_exr_channels(const std::string& path);

/// Root-mean-square difference of two images of equal size, over all channels, measured on
/// display-encoded values scaled to 0..255 (so "1.0" is one 8-bit step). Throws InputError if
/// the sizes differ.
double image_rmse(const Film& a, const Film& b);

/// Where two images of equal size differ: each channel is the absolute difference of the
/// display-encoded (sRGB) values times `scale`, clamped to 1, stored so that a PNG of the result
/// shows exactly that value (black where the images agree). Throws InputError if the sizes differ.
Film difference_image(const Film& a, const Film& b, float scale);

}  // namespace raylab
