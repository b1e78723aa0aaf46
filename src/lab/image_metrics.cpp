#include "raylab/lab/image_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "raylab/core/error.h"
#include "raylab/core/srgb.h"

namespace raylab {
namespace {

// SSIM constants of Wang et al. (2004) for a dynamic range of 1: C1 = (0.01 L)^2, C2 = (0.03 L)^2.
constexpr double kC1 = 0.01 * 0.01;
constexpr double kC2 = 0.03 * 0.03;
// The paper's window: an 11 x 11 circular-symmetric Gaussian with sigma 1.5.
constexpr int kWindowRadius = 5;
constexpr double kWindowSigma = 1.5;

void check_sizes(const Film& image, const Film& reference) {
  if (image.width() == reference.width() && image.height() == reference.height()) return;
  throw InputError("", "the image is " + std::to_string(image.width()) + "x" + std::to_string(image.height()) +
                           " but the reference is " + std::to_string(reference.width()) + "x" +
                           std::to_string(reference.height()));
}

// Display luma (Rec. 709 weights applied to the sRGB-encoded channels, i.e. Y', not Y): SSIM
// models what a viewer sees, so it works on the encoded values, clamped to [0, 1] like a display.
std::vector<double> encoded_luma(const Film& film) {
  std::vector<double> out(film.pixels().size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Color c = film.pixels()[i];
    out[i] = 0.2126 * linear_to_srgb(c.x) + 0.7152 * linear_to_srgb(c.y) + 0.0722 * linear_to_srgb(c.z);
  }
  return out;
}

// Normalised 1-D Gaussian taps for radius `r` (the 2-D window is their outer product).
std::vector<double> gaussian_taps(int r) {
  std::vector<double> taps(static_cast<std::size_t>(2 * r + 1));
  double sum = 0.0;
  for (int i = -r; i <= r; ++i) {
    taps[static_cast<std::size_t>(i + r)] = std::exp(-(i * i) / (2.0 * kWindowSigma * kWindowSigma));
    sum += taps[static_cast<std::size_t>(i + r)];
  }
  for (double& t : taps) t /= sum;
  return taps;
}

// Weighted window means of `v` centred on every pixel whose window lies inside the image:
// (w - 2r) x (h - 2r) values, computed separably (rows, then columns).
std::vector<double> window_means(const std::vector<double>& v, int w, int h, const std::vector<double>& taps) {
  const int r = static_cast<int>(taps.size() / 2);
  const int ow = w - 2 * r, oh = h - 2 * r;
  std::vector<double> rows(static_cast<std::size_t>(ow) * static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k <= 2 * r; ++k) s += taps[static_cast<std::size_t>(k)] * v[std::size_t(y) * w + x + k];
      rows[std::size_t(y) * ow + x] = s;
    }
  }
  std::vector<double> out(static_cast<std::size_t>(ow) * static_cast<std::size_t>(oh));
  for (int y = 0; y < oh; ++y) {
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k <= 2 * r; ++k) s += taps[static_cast<std::size_t>(k)] * rows[std::size_t(y + k) * ow + x];
      out[std::size_t(y) * ow + x] = s;
    }
  }
  return out;
}

// Mean SSIM over every window position that fits in the image. Images smaller than the window
// use the largest centred window that fits (down to a single pixel, where only the luminance
// term is left). The formula is symmetric in its arguments term by term, so ssim(a, b) and
// ssim(b, a) agree to the bit, and ssim(a, a) is exactly 1.
double mean_ssim(const Film& a, const Film& b) {
  const int w = a.width(), h = a.height();
  if (w <= 0 || h <= 0) return 1.0;
  const int r = std::min(kWindowRadius, (std::min(w, h) - 1) / 2);
  const std::vector<double> taps = gaussian_taps(r);
  const std::vector<double> x = encoded_luma(a), y = encoded_luma(b);
  std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  const std::vector<double> mx = window_means(x, w, h, taps), my = window_means(y, w, h, taps);
  const std::vector<double> mxx = window_means(xx, w, h, taps), myy = window_means(yy, w, h, taps);
  const std::vector<double> mxy = window_means(xy, w, h, taps);
  double sum = 0.0;
  for (std::size_t i = 0; i < mx.size(); ++i) {
    const double vx = mxx[i] - mx[i] * mx[i], vy = myy[i] - my[i] * my[i], cxy = mxy[i] - mx[i] * my[i];
    sum +=
        ((2.0 * mx[i] * my[i] + kC1) * (2.0 * cxy + kC2)) / ((mx[i] * mx[i] + my[i] * my[i] + kC1) * (vx + vy + kC2));
  }
  return sum / static_cast<double>(mx.size());
}

// Nearest-rank percentile for the fraction num / den: the smallest value with at least that
// fraction of the values at or below it, i.e. sorted[ceil(num / den * n) - 1]. The rank is
// computed in integers: in floating point 0.999 * 2000 is a hair above 1998 and would round up
// to the wrong rank.
double nearest_rank(std::vector<float> values, std::size_t num, std::size_t den) {
  if (values.empty()) return 0.0;
  const std::size_t n = values.size();
  const std::size_t rank = (num * n + den - 1) / den;
  const std::size_t index = std::clamp<std::size_t>(rank, 1, n) - 1;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index), values.end());
  return values[index];
}

}  // namespace

std::vector<float> pixel_errors(const Film& image, const Film& reference) {
  check_sizes(image, reference);
  std::vector<float> out(image.pixels().size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Color a = image.pixels()[i], b = reference.pixels()[i];
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) sum += (double(a[k]) - double(b[k])) * (double(a[k]) - double(b[k]));
    out[i] = static_cast<float>(std::sqrt(sum / 3.0));
  }
  return out;
}

ImageError measure_error(const Film& image, const Film& reference) {
  check_sizes(image, reference);
  ImageError e;
  const std::size_t n = image.pixels().size();
  if (n == 0) {
    e.psnr = std::numeric_limits<double>::infinity();
    return e;
  }
  double linear_sum = 0.0, encoded_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Color a = image.pixels()[i], b = reference.pixels()[i];
    for (int k = 0; k < 3; ++k) {
      const double d = double(a[k]) - double(b[k]);
      const double de = double(linear_to_srgb(a[k])) - double(linear_to_srgb(b[k]));
      linear_sum += d * d;
      encoded_sum += de * de;
    }
  }
  const double values = 3.0 * static_cast<double>(n);
  e.rmse = std::sqrt(linear_sum / values);
  const double mse = encoded_sum / values;
  e.psnr = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
  e.ssim = mean_ssim(image, reference);
  e.p999 = nearest_rank(pixel_errors(image, reference), 999, 1000);
  return e;
}

}  // namespace raylab
