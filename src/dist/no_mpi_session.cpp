// MpiSession in a build configured without MPI: it cannot start, and says so.

#include <cstdlib>
#include <stdexcept>

#include "raylab/dist/mpi_channel.h"

namespace raylab::dist {

struct MpiSession::State {};

MpiSession::MpiSession() {
  throw std::runtime_error("this raylab was built without MPI (install libopenmpi-dev and rebuild)");
}

MpiSession::~MpiSession() = default;

Channel& MpiSession::channel() { throw std::logic_error("no MPI"); }

std::string MpiSession::host() const { return {}; }

void MpiSession::abort(int code) { std::exit(code); }

}  // namespace raylab::dist
