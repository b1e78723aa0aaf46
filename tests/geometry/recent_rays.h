#pragma once
// The last rays a shape test checked, with their intervals, lane by lane (structure of arrays):
// the rays that the ray-parallel tests (sphere_rays.h, cylinder_rays.h) take together, so that
// every case of a test of the one-ray forms also runs in a lane of the ray-parallel forms.

#include "raylab/core/ray.h"

namespace raylab::test {

/// The last kSize rays pushed, each in the lane it was pushed to (round robin).
struct RecentRays {
  static constexpr int kSize = 16;                                   ///< the widest ray-parallel test
  alignas(64) float ox[kSize] = {}, oy[kSize] = {}, oz[kSize] = {};  ///< the origins, by lane
  alignas(64) float dx[kSize] = {}, dy[kSize] = {}, dz[kSize] = {};  ///< the directions, by lane
  alignas(64) float tmin[kSize] = {}, tmax[kSize] = {};              ///< the intervals, by lane
  int next = 0;                                                      ///< the lane the next ray goes to

  /// Puts `ray` with the interval [lo, hi) in the next lane.
  void push(const Ray& ray, float lo = 0.f, float hi = 0.f) {
    ox[next] = ray.origin.x, oy[next] = ray.origin.y, oz[next] = ray.origin.z;
    dx[next] = ray.direction.x, dy[next] = ray.direction.y, dz[next] = ray.direction.z;
    tmin[next] = lo, tmax[next] = hi;
    next = (next + 1) % kSize;
  }
  /// The ray of lane `i`, with its interval.
  Ray ray(int i) const { return Ray{{ox[i], oy[i], oz[i]}, tmin[i], {dx[i], dy[i], dz[i]}, tmax[i]}; }
};

}  // namespace raylab::test
