// MpiSession: MPI through the module that holds it (libraylab_mpi, mpi_backend.h), loaded only
// when a session starts; in a build configured without MPI it cannot start, and says so.

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "mpi_backend.h"
#include "raylab/dist/launcher.h"
#include "raylab/dist/mpi_channel.h"

#ifdef RAYLAB_HAVE_MPI
#include <dlfcn.h>
#endif

namespace raylab::dist {
namespace {

#ifdef RAYLAB_HAVE_MPI
// The module beside this library: the folder of the file that holds mpi_available.
std::string mpi_module_path() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&mpi_available), &info) == 0 || info.dli_fname == nullptr) {
    return kMpiModuleFile;  // the loader's own search, as a last resort
  }
  const std::string library = info.dli_fname;
  const std::size_t slash = library.rfind('/');
  return (slash == std::string::npos ? std::string() : library.substr(0, slash + 1)) + kMpiModuleFile;
}

// Loads the module and starts MPI. RTLD_GLOBAL: Open MPI's own components, which it loads in
// turn, look up libmpi's symbols in the global scope.
MpiBackend* start_mpi() {
  const std::string path = mpi_module_path();
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (module == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(std::string("cannot load raylab's MPI module: ") + (why ? why : path.c_str()));
  }
  // Never closed: MPI stays loaded until the process ends, as when it was linked.
  const auto entry = reinterpret_cast<MpiBackendEntry>(dlsym(module, kMpiBackendSymbol));
  if (entry == nullptr) throw std::runtime_error(path + " has no " + kMpiBackendSymbol);
  return entry();
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
