#pragma once
/// \file
/// The Channel of a real distributed run: MPI point-to-point messages between the ranks of the
/// job the launcher started. Only in builds configured with MPI (see launcher.h's mpi_available).

#include <memory>
#include <string>

#include "raylab/dist/channel.h"

namespace raylab::dist {

/// MPI for the life of the object: initialised on construction (one thread makes MPI calls: the
/// one that constructs it), finalised on destruction. One per process.
class MpiSession {
 public:
  /// Initialises MPI; throws std::runtime_error when this build has no MPI or it fails to start.
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// The channel between the job's ranks (MPI_COMM_WORLD).
  Channel& channel();
  /// This machine's name as MPI knows it.
  std::string host() const;
  /// Ends the whole job at once with `code` (MPI_Abort): for a rank that cannot tell the others.
  [[noreturn]] void abort(int code);

 private:
  struct State;
  std::unique_ptr<State> m_state;
};

}  // namespace raylab::dist
