#pragma once
/// \file
/// The fixed ray sets that `raylab compare` traces through every acceleration structure:
/// primary rays through pixel centres, shadow rays toward the first light, and one diffuse
/// bounce. Built once per scene, deterministically, so that every structure answers exactly
/// the same questions.

#include <cstdint>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/core/ray.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// The kinds of ray in a comparison.
enum class BenchRayKind : int { kPrimary = 0, kShadow, kDiffuse, kCount };

/// Number of ray kinds, for arrays indexed by BenchRayKind.
inline constexpr int kBenchRayKinds = static_cast<int>(BenchRayKind::kCount);

/// Name of a kind for tables ("primary", "shadow", "diffuse").
const char* bench_ray_kind_name(BenchRayKind kind);

/// Image size and seed of the ray sets.
struct RaySetOptions {
  int width = 512;         ///< primary rays per row
  int height = 512;        ///< rows
  std::uint64_t seed = 0;  ///< seed of the light-sample and bounce directions
};

/// One kind of ray: the rays and, for each, the pixel of the primary ray it came from.
struct RaySet {
  std::vector<Ray> rays;
  std::vector<std::uint32_t> pixel;  ///< row-major pixel index (y * width + x) of each ray
};

/// All three kinds for one scene and image size.
struct RaySets {
  int width = 0;
  int height = 0;
  RaySet sets[kBenchRayKinds];  ///< indexed by BenchRayKind

  /// The rays of `kind`.
  const RaySet& operator[](BenchRayKind kind) const { return sets[static_cast<int>(kind)]; }
  /// Rays of every kind together.
  std::size_t total_rays() const;
};

/// Primary rays of `scene`'s camera through the centre of every pixel of a width x height
/// image, row-major from the top row (unit directions, so `t` is distance).
std::vector<Ray> primary_rays(const Scene& scene, int width, int height);

/// Builds the three ray sets. Primary rays as `primary_rays`; `reference` finds their hits.
/// From each hit whose surface faces the scene's first light, one shadow ray toward it: to a
/// point light's position, to a point on a sphere or quad light chosen per pixel from the seed,
/// or along a directional light without limit; it starts just off the surface and stops just
/// short of the light (as the Whitted integrator does). From every hit, one cosine-weighted
/// diffuse ray about the geometric normal on the side the primary ray came from, its direction
/// drawn from (pixel, seed). No lights: no shadow rays. Throws UsageError for a size < 1.
RaySets make_ray_sets(const Scene& scene, const Accelerator& reference, const RaySetOptions& options = {});

/// Fills the shadow and diffuse sets of `sets` from its primary set (rays and pixels, in any
/// order, e.g. the 4x4 tiles of `raylab bench`) as make_ray_sets does, toward `light` (nullptr:
/// no shadow rays). Random numbers are drawn per (pixel, seed), so a pixel's rays do not depend on
/// the order of the primary rays. Secondary rays keep the order of their primary rays.
void add_secondary_rays(const Scene& scene, const Accelerator& reference, const Light* light, std::uint64_t seed,
                        RaySets& sets);

}  // namespace raylab
