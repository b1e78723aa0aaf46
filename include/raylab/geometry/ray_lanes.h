#pragma once
/// \file
/// N rays lane by lane (N = 4, 8 or 16): the form the ray-parallel shape tests take (one shape
/// against the rays of a packet, sphere_rays.h and cylinder_rays.h).

#include "raylab/core/ray.h"
#include "raylab/simd/isa_namespace.h"
#include "raylab/simd/wide_float.h"

namespace raylab {
RAYLAB_ISA_BEGIN

/// The origins and directions of N rays, one ray per lane.
template <int N>
struct RayLanes {
  using F = simd::WideFloat<N>;
  F ox, oy, oz;  ///< the origins' coordinates
  F dx, dy, dz;  ///< the directions' coordinates

  /// The rays whose origin and direction coordinates are N consecutive floats from each pointer.
  static RayLanes load(const float* origin_x, const float* origin_y, const float* origin_z, const float* direction_x,
                       const float* direction_y, const float* direction_z) {
    return {F::load(origin_x),    F::load(origin_y),    F::load(origin_z),
            F::load(direction_x), F::load(direction_y), F::load(direction_z)};
  }

  /// The ray of lane `lane` (origin and direction; the default interval), bit for bit.
  Ray ray(int lane) const {
    alignas(N * sizeof(float)) float lanes[6][N];
    ox.store(lanes[0]);
    oy.store(lanes[1]);
    oz.store(lanes[2]);
    dx.store(lanes[3]);
    dy.store(lanes[4]);
    dz.store(lanes[5]);
    Ray r;
    r.origin = {lanes[0][lane], lanes[1][lane], lanes[2][lane]};
    r.direction = {lanes[3][lane], lanes[4][lane], lanes[5][lane]};
    return r;
  }
};

RAYLAB_ISA_END
}  // namespace raylab
