#pragma once
/// \file
/// The ranks of a distributed render and the messages between them, as the render sees them:
/// numbered processes that send tagged byte strings to one another. MPI carries them in a real
/// run (mpi_channel.h); threads of one process carry them in the tests (local_channel.h), so that
/// the coordination is tested without a launcher.

#include <cstdint>
#include <optional>
#include <vector>

namespace raylab::dist {

/// A message that arrived: who sent it, its tag and its bytes.
struct Message {
  int from = 0;                     ///< the sending rank
  int tag = 0;                      ///< what kind of message it is (the protocol's numbers)
  std::vector<std::uint8_t> bytes;  ///< its contents
};

/// This process's end of the connections between the ranks (see the file comment).
class Channel {
 public:
  virtual ~Channel() = default;
  /// This process's rank, 0 to size() - 1; rank 0 coordinates.
  virtual int rank() const = 0;
  /// Number of ranks.
  virtual int size() const = 0;
  /// Sends `bytes` under `tag` to rank `to` without waiting for it to arrive; messages from one
  /// rank to another arrive in the order sent.
  virtual void send(int to, int tag, std::vector<std::uint8_t> bytes) = 0;
  /// The next message for this rank, from any rank, waiting at most `seconds` for one; nullopt
  /// when none came in that time.
  virtual std::optional<Message> receive(double seconds) = 0;
  /// Waits at most `seconds` for the messages sent so far to leave this process (before it exits).
  virtual void flush(double seconds) = 0;
};

}  // namespace raylab::dist
