#include "small_objects.h"

#include <array>
#include <cmath>

namespace raylab::detail {
namespace {

// The footprint of world box `b`, or nothing when it is not small or not wholly in front.
bool small_footprint(const Box3& b, const Camera& camera, int width, int height, float max_pixels, PixelRect& out) {
  if (b.empty()) return false;
  float x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{(corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y, (corner & 4) ? b.hi.z : b.lo.z};
    float x = 0.f, y = 0.f;
    if (!camera.project(p, x, y)) return false;
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
  if (!(x1 - x0 <= max_pixels && y1 - y0 <= max_pixels)) return false;
  out.x0 = std::max(0, static_cast<int>(std::floor(x0)) - 1);
  out.y0 = std::max(0, static_cast<int>(std::floor(y0)) - 1);
  out.x1 = std::min(width, static_cast<int>(std::floor(x1)) + 2);
  out.y1 = std::min(height, static_cast<int>(std::floor(y1)) + 2);
  return out.x0 < out.x1 && out.y0 < out.y1;
}

}  // namespace

std::vector<PixelRect> small_object_footprints(const Scene& scene, const Camera& camera, int width, int height,
                                               float max_pixels) {
  std::vector<PixelRect> out;
  if (!(max_pixels > 0.f)) return out;
  // Bounds per object of the flat geometry (an object may hold many primitives: a mesh is small
  // only when all of it is).
  std::vector<Box3> objects(scene.objects.size());
  const Geometry& g = scene.geometry;
  for (std::uint32_t id = 0; id < g.size(); ++id) {
    const std::uint32_t object = g.object_of(id);
    if (object < objects.size()) objects[object].extend(g.bounds(id));
  }
  PixelRect r;
  for (const Box3& b : objects) {
    if (small_footprint(b, camera, width, height, max_pixels, r)) out.push_back(r);
  }
  for (const Instance& inst : scene.instances) {
    const Box3 local = scene.prototypes[inst.prototype].bounds();
    if (local.empty()) continue;
    Box3 world;
    for (int corner = 0; corner < 8; ++corner) {
      world.extend(inst.to_world.point({(corner & 1) ? local.hi.x : local.lo.x, (corner & 2) ? local.hi.y : local.lo.y,
                                        (corner & 4) ? local.hi.z : local.lo.z}));
    }
    if (small_footprint(world, camera, width, height, max_pixels, r)) out.push_back(r);
  }
  return out;
}

}  // namespace raylab::detail
