#include "raylab/dist/launcher.h"

#include <cstdlib>
#include <string>

#include "raylab/core/error.h"

namespace raylab::dist {
namespace {

// The first of `names` that the environment sets.
const char* first_set(std::initializer_list<const char*> names) {
  for (const char* name : names) {
    if (const char* value = std::getenv(name)) return value;
  }
  return nullptr;
}

}  // namespace

bool launched_by_mpi() {
  return first_set({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_NTASKS"}) != nullptr &&
         first_set({"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "SLURM_PROCID"}) != nullptr;
}

int launcher_rank() {
  const char* value = first_set({"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "SLURM_PROCID"});
  if (value == nullptr) return 0;
  try {
    return std::stoi(value);
  } catch (const std::exception&) {
    return 0;
  }
}

bool mpi_available() {
#ifdef RAYLAB_HAVE_MPI
  return true;
#else
  return false;
#endif
}

void require_mpi_build() {
  if (!mpi_available()) {
    throw UsageError(
        "this process was started by an MPI launcher, but this raylab was built without MPI "
        "(install libopenmpi-dev and rebuild, or run raylab without mpirun)");
  }
}

}  // namespace raylab::dist
