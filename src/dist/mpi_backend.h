#pragma once
/// \file
/// Internal to src/dist: what the MPI module (libraylab_mpi, mpi_module.cpp) gives MpiSession.
/// MPI's libraries are loaded only by a run under an MPI launcher: linked into libraylab_dist,
/// they were loaded (and relocated) at the start of every raylab process, about 1.3 ms on the
/// Intel Xeon and 3 ms on the AMD EPYC Zen 5 machine (docs/performance.md, "Page faults on a
/// virtual machine").

#include <string>

#include "raylab/dist/channel.h"

namespace raylab::dist {

/// MPI started for this process: its channel, its host name, the job's abort. Destroying it
/// finalises MPI.
class MpiBackend {
 public:
  virtual ~MpiBackend() = default;
  /// The channel between the job's ranks (MPI_COMM_WORLD).
  virtual Channel& channel() = 0;
  /// This machine's name as MPI knows it.
  virtual std::string host() const = 0;
  /// Ends the whole job at once with `code` (MPI_Abort).
  [[noreturn]] virtual void abort(int code) = 0;
};

/// The file name of the module, which lies beside libraylab_dist (build tree and installed).
inline constexpr const char* kMpiModuleFile = "libraylab_mpi.so";
/// The module's one entry point, `MpiBackend* raylab_mpi_backend()`: starts MPI and returns the
/// backend (the caller owns it); throws std::runtime_error when MPI fails to start.
inline constexpr const char* kMpiBackendSymbol = "raylab_mpi_backend";
/// The entry point's type.
using MpiBackendEntry = MpiBackend* (*)();

}  // namespace raylab::dist
