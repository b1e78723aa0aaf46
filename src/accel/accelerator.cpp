#include "raylab/accel/accelerator.h"

#include <cassert>

namespace raylab {

void Accelerator::intersect(std::span<Ray> rays, std::span<Hit> hits) const {
  assert(rays.size() == hits.size());
  for (std::size_t i = 0; i < rays.size(); ++i) intersect(rays[i], hits[i]);
}

void Accelerator::occluded(std::span<const Ray> rays, std::span<std::uint8_t> result) const {
  assert(rays.size() == result.size());
  for (std::size_t i = 0; i < rays.size(); ++i) result[i] = occluded(rays[i]) ? 1 : 0;
}

}  // namespace raylab
