#pragma once
/// \file
/// Image files: PNG (8-bit sRGB), OpenEXR (float RGB) and PFM, chosen by extension.

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

/// Encodes `film` as bytes of the format named by `extension` (".png", ".pfm", ".exr").
std::vector<unsigned char> encode_image(const Film& film, std::string_view extension);

/// Reads a PNG (decoded to linear), PFM or EXR file into a film; throws InputError on failure.
Film read_image(const std::string& path);

/// Root-mean-square difference of two images of equal size, over all channels, measured on
/// display-encoded values scaled to 0..255 (so "1.0" is one 8-bit step). Throws InputError if
/// the sizes differ.
double image_rmse(const Film& a, const Film& b);

}  // namespace raylab
