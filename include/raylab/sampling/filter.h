#pragma once
/// \file
/// Pixel reconstruction filters: how much a sample at offset (dx, dy) from a pixel's centre
/// counts towards that pixel.

#include <span>
#include <string_view>

namespace raylab {

/// The reconstruction filters raylab offers.
enum class FilterKind { kBox, kTent, kGaussian, kMitchell };

/// A separable reconstruction filter, normalised so that its integral over the plane is 1 and
/// zero at and beyond its radius along either axis (|dx| >= radius or |dy| >= radius).
///  - box: constant over the square of half-width `radius` (default 0.5: the pixel itself, the
///    plain average of the pixel's samples);
///  - tent: linear fall-off to zero at `radius` (default 1);
///  - gaussian: exp(-x^2 / (2 sigma^2)) with sigma = radius / 3, shifted down so that it reaches
///    zero at `radius` (default 1.5);
///  - mitchell: Mitchell & Netravali's cubic with B = C = 1/3, stretched to `radius` (default 2);
///    it has negative lobes.
class Filter {
 public:
  /// A filter of kind `kind` and radius `radius` (> 0 and finite; pixels). Throws UsageError
  /// for any other radius.
  Filter(FilterKind kind, float radius);

  /// The filter's weight for a sample at offset (dx, dy) pixels from the pixel centre.
  float evaluate(float dx, float dy) const { return evaluate_1d(dx) * evaluate_1d(dy); }

  /// The normalised one-dimensional profile (integrates to 1 over the line).
  float evaluate_1d(float x) const;

  /// Half-width of the filter's support in pixels.
  float radius() const { return m_radius; }

  /// Which filter this is.
  FilterKind kind() const { return m_kind; }

 private:
  FilterKind m_kind;
  float m_radius;
  float m_scale = 1.f;  ///< 1-D normalisation constant
};

/// Names of the filters: box, tent, gaussian, mitchell.
std::span<const std::string_view> filter_names();

/// The default radius of filter `name` (box 0.5, tent 1, gaussian 1.5, mitchell 2).
float default_filter_radius(std::string_view name);

/// Creates filter `name` with radius `radius` (0 = the filter's default). Throws UsageError
/// listing the valid names when `name` is unknown, or when `radius` is negative, above 8 or NaN.
Filter make_filter(std::string_view name, float radius = 0.f);

}  // namespace raylab
