#pragma once
/// \file
/// Many rays and their answers as the caller's own arrays: what a program (or numpy) hands to
/// the batched queries of RayQuery, read and written in place with no conversion pass.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "raylab/core/ray.h"

namespace raylab {

/// `count` rays read from the caller's arrays. Ray i starts at origins[i * origin_stride + 0..2]
/// and points along directions[i * direction_stride + 0..2] (x, y, z; the direction need not be
/// unit length, and `t` is measured in units of it). Strides count floats, so one (N, 6) array
/// of origin-then-direction rows is origins = data, directions = data + 3, both strides 6.
/// tmin and tmax are one value for every ray unless per-ray arrays are given.
struct RayBatch {
  std::size_t count = 0;                                ///< number of rays
  const float* origins = nullptr;                       ///< x, y, z of ray 0's origin
  std::ptrdiff_t origin_stride = 3;                     ///< floats from one origin to the next
  const float* directions = nullptr;                    ///< x, y, z of ray 0's direction
  std::ptrdiff_t direction_stride = 3;                  ///< floats from one direction to the next
  float tmin = 0.f;                                     ///< near limit of every ray (inclusive)
  float tmax = std::numeric_limits<float>::infinity();  ///< far limit of every ray (exclusive)
  const float* tmins = nullptr;                         ///< per-ray near limits (then `tmin` unused)
  std::ptrdiff_t tmin_stride = 1;                       ///< floats from one near limit to the next
  const float* tmaxs = nullptr;                         ///< per-ray far limits (then `tmax` unused)
  std::ptrdiff_t tmax_stride = 1;                       ///< floats from one far limit to the next

  /// Ray `i` as the accelerators take it.
  Ray ray(std::size_t i) const {
    const float* o = origins + static_cast<std::ptrdiff_t>(i) * origin_stride;
    const float* d = directions + static_cast<std::ptrdiff_t>(i) * direction_stride;
    Ray r;
    r.origin = {o[0], o[1], o[2]};
    r.direction = {d[0], d[1], d[2]};
    r.tmin = tmins != nullptr ? tmins[static_cast<std::ptrdiff_t>(i) * tmin_stride] : tmin;
    r.tmax = tmaxs != nullptr ? tmaxs[static_cast<std::ptrdiff_t>(i) * tmax_stride] : tmax;
    return r;
  }

  /// A batch reading `rays` in place (each Ray's own tmin and tmax).
  static RayBatch of(std::span<const Ray> rays) {
    RayBatch b;
    b.count = rays.size();
    constexpr std::ptrdiff_t kStride = sizeof(Ray) / sizeof(float);
    if (rays.empty()) return b;
    b.origins = &rays[0].origin.x;
    b.directions = &rays[0].direction.x;
    b.origin_stride = b.direction_stride = kStride;
    b.tmins = &rays[0].tmin;
    b.tmaxs = &rays[0].tmax;
    b.tmin_stride = b.tmax_stride = kStride;
    return b;
  }
};

/// Where the answers of a closest-hit batch go: arrays of the caller's, one entry per ray (two
/// for `uv`, three for `normal`). Any pointer may be null: that answer is not written.
struct HitArrays {
  float* t = nullptr;                 ///< distance in units of the direction; +inf on a miss
  std::int32_t* prim_id = nullptr;    ///< primitive hit (triangle index for a mesh); -1 on a miss
  std::int32_t* object_id = nullptr;  ///< object of that primitive; -1 on a miss
  float* uv = nullptr;                ///< barycentric weights of vertex 1 and 2 (triangles); 0 on a miss
  float* normal = nullptr;            ///< unit geometric normal of the primitive as wound, not turned
                                      ///< toward the ray; 0 on a miss
};

}  // namespace raylab
