// MpiSession: MPI through the module that holds it (libraylab_mpi, mpi_backend.h), loaded only
// when a session starts; in a build configured without MPI it cannot start, and says so.

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "../core/sibling_module.h"
#include "mpi_backend.h"
#include "raylab/dist/launcher.h"
#include "raylab/dist/mpi_channel.h"

namespace raylab::dist {
namespace {

#ifdef RAYLAB_HAVE_MPI
// Loads the module beside this library and starts MPI. The global scope: Open MPI's own
// components, which it loads in turn, look up libmpi's symbols there.
MpiBackend* start_mpi() {
  void* entry = sibling_module_symbol(reinterpret_cast<const void*>(&mpi_available), kMpiModuleFile, kMpiBackendSymbol,
                                      ModuleScope::kGlobal);
  return reinterpret_cast<MpiBackendEntry>(entry)();
}
#endif

}  // namespace

struct MpiSession::State {
  std::unique_ptr<MpiBackend> backend;
};

MpiSession::MpiSession() : m_state(std::make_unique<State>()) {
#ifdef RAYLAB_HAVE_MPI
  m_state->backend.reset(start_mpi());
#else
  throw std::runtime_error("this raylab was built without MPI (install libopenmpi-dev and rebuild)");
#endif
}

MpiSession::~MpiSession() = default;  // the backend finalises MPI

Channel& MpiSession::channel() {
  if (!m_state->backend) throw std::logic_error("no MPI");
  return m_state->backend->channel();
}

std::string MpiSession::host() const { return m_state->backend ? m_state->backend->host() : std::string(); }

void MpiSession::abort(int code) {
  if (m_state->backend) m_state->backend->abort(code);
  std::exit(code);
}

}  // namespace raylab::dist
