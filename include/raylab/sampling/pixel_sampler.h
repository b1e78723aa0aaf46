#pragma once
/// \file
/// Pixel sample patterns: where inside a pixel each of its samples lies. Every sampler is
/// stateless and addressable by (pixel, sample index, seed), so an image does not depend on the
/// thread count, the tile order or the number of processes.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace raylab {

/// A 2D sample position inside the unit square.
struct Sample2 {
  float x = 0.5f;
  float y = 0.5f;
};

/// A sample pattern over the pixel: `spp()` positions per pixel in [0, 1)^2.
class PixelSampler {
 public:
  virtual ~PixelSampler() = default;

  /// Position of sample `index` (0 <= index < spp()) within pixel (px, py), in [0, 1)^2. The
  /// same arguments always give the same position.
  virtual Sample2 sample(int px, int py, int index) const = 0;

  /// The sampler's name as the command line spells it ("jittered", "cmj", ...).
  virtual std::string_view name() const = 0;

  /// Samples per pixel.
  int spp() const { return m_spp; }

  /// The seed every random choice of this sampler derives from.
  std::uint64_t seed() const { return m_seed; }

 protected:
  /// For implementations: `spp` must already be a count the sampler uses exactly.
  PixelSampler(int spp, std::uint64_t seed) : m_spp(spp), m_seed(seed) {}

 private:
  int m_spp;
  std::uint64_t m_seed;
};

/// Names of the uniform (non-adaptive) samplers:
///  - center: one sample at (0.5, 0.5);
///  - regular: the centres of an n x n grid of strata, the same in every pixel;
///  - random: independent uniform positions;
///  - jittered: one uniform position in each stratum of an n x n grid (sample `index` in column
///    index % n, row index / n);
///  - cmj: correlated multi-jittered (Kensler 2013), stratified over a cols x rows grid
///    (rows = the largest divisor of spp not above sqrt(spp)) and over the spp columns and the
///    spp rows of the pixel at once;
///  - sobol: Owen-scrambled Sobol' (0,2)-sequence; 2^k samples form a (0, k, 2)-net.
/// All but center and regular draw a different pattern in every pixel and for every seed.
std::span<const std::string_view> pixel_sampler_names();

/// True when `name` is one of pixel_sampler_names().
bool is_pixel_sampler(std::string_view name);

/// The sample count sampler `name` uses for a request of `requested` (>= 1) samples: the nearest
/// valid count (center: 1; regular and jittered: a square n*n; sobol: a power of two; random and
/// cmj: any). Ties round up. Throws UsageError listing the names when `name` is unknown.
int valid_spp(std::string_view name, int requested);

/// Creates sampler `name` for `valid_spp(name, spp)` samples per pixel and seed `seed`. Throws
/// UsageError listing the valid names when `name` is unknown.
std::unique_ptr<PixelSampler> make_pixel_sampler(std::string_view name, int spp, std::uint64_t seed);

/// The notice to show when `valid_spp(name, requested)` differs from `requested`
/// ("--spp 10 rounded to 9 for the jittered sampler (it needs a square count n*n)"), or "" when
/// it does not. Throws like valid_spp().
std::string spp_rounding_notice(std::string_view name, int requested);

/// A seed for the other random decisions made along sample `index` of pixel (px, py) (area
/// light samples), independent of the sample's position.
std::uint64_t sample_path_seed(std::uint64_t seed, int px, int py, int index);

}  // namespace raylab
