#pragma once
/// \file
/// Image error measures for `raylab quality`: how far a rendered image is from a reference.

#include <vector>

#include "raylab/render/film.h"

namespace raylab {

/// Error of an image against a reference of the same size.
struct ImageError {
  double rmse = 0.0;  ///< root-mean-square difference of linear RGB over all channels
  /// dB, 10 log10(1 / MSE) with the MSE taken over the three sRGB-encoded channels clamped to
  /// [0, 1] (peak 1); infinity when the encoded images are equal.
  double psnr = 0.0;
  /// Mean structural similarity (Wang et al. 2004) of the display luma Y' = 0.2126 R' + 0.7152 G'
  /// + 0.0722 B' (Rec. 709 weights on the sRGB-encoded, clamped channels): an 11 x 11 Gaussian
  /// window (sigma 1.5), C1 = 0.01^2, C2 = 0.03^2 for the range [0, 1], averaged over every
  /// window position that lies inside the image (no padding; images smaller than 11 pixels use
  /// the largest window that fits). 1 for equal images; symmetric in its two arguments.
  double ssim = 1.0;
  /// 99.9th percentile of pixel_errors by nearest rank: the ceil(0.999 n)-th smallest value.
  double p999 = 0.0;
};

/// Per-pixel error: the root-mean-square over the three channels of the linear RGB difference,
/// row-major. Throws InputError naming both sizes when they differ.
std::vector<float> pixel_errors(const Film& image, const Film& reference);

/// All the measures of ImageError. Throws InputError naming both sizes when they differ.
ImageError measure_error(const Film& image, const Film& reference);

}  // namespace raylab
