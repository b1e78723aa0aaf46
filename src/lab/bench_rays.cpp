// The rays of `raylab bench`: 4x4 tiles of primary rays and the shadow and diffuse rays they spawn.

#include <algorithm>
#include <cmath>
#include <string>

#include "raylab/core/error.h"
#include "raylab/lab/bench.h"
#include "raylab/render/camera.h"

namespace raylab {
namespace {

// Side of a primary-ray tile: 16 rays, one packet of `raylab bench`.
constexpr int kTile = 4;

}  // namespace

Light bench_light(const Scene& scene, bool& from_scene) {
  for (const Light& l : scene.lights) {
    if (l.kind == Light::Kind::kPoint) {
      from_scene = true;
      return l;
    }
  }
  from_scene = false;
  const Box3 b = scene.geometry.bounds();
  const bool empty = !(b.lo.x <= b.hi.x && b.lo.y <= b.hi.y && b.lo.z <= b.hi.z);
  const Vec3 centre = empty ? Vec3{} : (b.lo + b.hi) * 0.5f;
  const Vec3 extent = empty ? Vec3{} : b.hi - b.lo;
  const float len = length(scene.camera.up);
  const Vec3 up = len > 0.f ? scene.camera.up / len : Vec3{0.f, 1.f, 0.f};
  // Half the bounds' thickness along `up` reaches the top; one diagonal more keeps the light
  // clear of the scene whatever its scale.
  const float half = 0.5f * (std::fabs(extent.x * up.x) + std::fabs(extent.y * up.y) + std::fabs(extent.z * up.z));
  Light light;
  light.kind = Light::Kind::kPoint;
  light.position = centre + up * (half + std::max(length(extent), 1e-3f));
  return light;
}

std::vector<Ray> tiled_primary_rays(const Scene& scene, int width, int height, std::vector<std::uint32_t>* pixel) {
  if (width < 1 || height < 1) {
    throw UsageError("ray set size must be at least 1x1, not " + std::to_string(width) + "x" + std::to_string(height));
  }
  const Camera camera(scene.camera, width, height);
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  if (pixel) pixel->clear(), pixel->reserve(rays.capacity());
  for (int ty = 0; ty < height; ty += kTile) {
    for (int tx = 0; tx < width; tx += kTile) {
      for (int y = ty; y < std::min(ty + kTile, height); ++y) {
        for (int x = tx; x < std::min(tx + kTile, width); ++x) {
          rays.push_back(camera.generate(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
          if (pixel) pixel->push_back(static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(width) + x);
        }
      }
    }
  }
  return rays;
}

RaySets make_bench_rays(const Scene& scene, const Accelerator& ours, const Light& light, int width, int height,
                        std::uint64_t seed) {
  RaySets sets;
  sets.width = width;
  sets.height = height;
  RaySet& primary = sets.sets[static_cast<int>(BenchRayKind::kPrimary)];
  primary.rays = tiled_primary_rays(scene, width, height, &primary.pixel);
  add_secondary_rays(scene, ours, &light, seed, sets);
  return sets;
}

}  // namespace raylab
