#include "raylab/accel/cylinder_frames.h"

#include <algorithm>

namespace raylab {

CylinderFrames CylinderFrames::of(const Geometry& geometry, std::span<const std::uint32_t> ids) {
  const auto first = static_cast<std::uint32_t>(geometry.triangles.size() + geometry.spheres.size());
  const auto end = first + static_cast<std::uint32_t>(geometry.cylinders.size());
  std::uint32_t lo = end, hi = first;
  for (const std::uint32_t id : ids) {
    if (id < first || id >= end) continue;
    lo = std::min(lo, id);
    hi = std::max(hi, id + 1);
  }
  CylinderFrames out;
  if (lo >= hi) return out;
  out.begin = lo;
  out.frames.reserve(hi - lo);
  for (std::uint32_t id = lo; id < hi; ++id) out.frames.push_back(cylinder_frame(geometry.cylinders[id - first]));
  return out;
}

}  // namespace raylab
