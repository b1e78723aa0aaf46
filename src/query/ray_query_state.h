#pragma once
// What a RayQuery holds (internal to src/query).

#include <memory>
#include <mutex>

#include "raylab/accel/accelerator.h"
#include "raylab/query/ray_query.h"
#include "raylab/scene/scene.h"

namespace raylab {

/// The scene (whose `geometry` holds every primitive, instances baked) and the structure over
/// it, built on first use when the program did not build one.
struct RayQuery::State {
  Scene scene;
  std::unique_ptr<Accelerator> accel;
  std::mutex build_mutex;  ///< guards the first-use build of `accel`
};

}  // namespace raylab
