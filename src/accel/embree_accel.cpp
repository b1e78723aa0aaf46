#include "raylab/accel/embree_accel.h"

#include "raylab/core/error.h"

// PLACEHOLDER, being written.

namespace raylab {

bool embree_available() { return false; }

std::unique_ptr<Accelerator> make_embree_accelerator(const Geometry&, std::span<const std::uint32_t>) {
  throw UsageError("raylab was built without Embree 3");
}

}  // namespace raylab
