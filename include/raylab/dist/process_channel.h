#pragma once
/// \file
/// The channel of this process's run: between the ranks of the MPI job when an MPI launcher
/// started the process, else a channel of one rank (the same coordination, all in this process).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "raylab/dist/channel.h"
#include "raylab/dist/mpi_channel.h"

namespace raylab::dist {

/// The channel this process renders over (see the file comment), for the life of the object.
class ProcessChannel {
 public:
  /// Starts MPI when launched_by_mpi() (UsageError when this build has no MPI), else makes a
  /// one-rank channel.
  ProcessChannel();
  ProcessChannel(const ProcessChannel&) = delete;
  ProcessChannel& operator=(const ProcessChannel&) = delete;

  /// The channel between the ranks.
  Channel& channel() { return *m_channel; }
  /// This machine's name as MPI knows it, or "local" without MPI.
  std::string host() const;

 private:
  std::optional<MpiSession> m_session;
  std::vector<std::unique_ptr<Channel>> m_local;
  Channel* m_channel = nullptr;
};

}  // namespace raylab::dist
