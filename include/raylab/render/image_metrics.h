#pragma once
/// \file
/// Image error measures for `raylab quality`: how far a rendered image is from a reference.

#include <vector>

#include "raylab/render/film.h"

namespace raylab {

/// Error of an image against a reference of the same size.
struct ImageError {
  double rmse = 0.0;        ///< root-mean-square difference of linear RGB over all channels
  double psnr = 0.0;        ///< dB, on sRGB-encoded values in [0, 1] (peak 1); infinity when equal
  double ssim = 1.0;        ///< mean structural similarity of sRGB-encoded luma (Wang et al. 2004)
  double p999 = 0.0;        ///< 99.9th percentile of the per-pixel error (see pixel_errors)
};

/// Per-pixel error: the root-mean-square over the three channels of the linear RGB difference,
/// row-major. Throws InputError when the sizes differ.
std::vector<float> pixel_errors(const Film& image, const Film& reference);

/// All the measures of ImageError. Throws InputError when the sizes differ.
ImageError measure_error(const Film& image, const Film& reference);

}  // namespace raylab
