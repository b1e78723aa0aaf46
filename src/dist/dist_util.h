#pragma once
// Internal to the dist module: the clock, timing and error text every role of a distributed run uses.

#include <atomic>
#include <chrono>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "raylab/core/index_ranges.h"
#include "raylab/core/stopwatch.h"

namespace raylab::dist {

using Clock = SteadyClock;

/// Longest wait for a message before a message loop looks around again (signals, timeouts).
inline constexpr double kPollSeconds = 0.02;

/// A worker's wait for a message before it looks for finished jobs to send back.
inline constexpr double kWorkerPollSeconds = 0.001;

/// A worker with nothing else to say says it is alive this often, so that only a dead or hung
/// process stays silent for long.
inline constexpr double kHeartbeatSeconds = 1.0;

/// "tile 7", "tiles 3, 5-9": the work a rank held, for messages (`unit`: "tile" or "frame").
inline std::string held_text(const std::string& unit, const std::vector<int>& items) {
  return unit + (items.size() > 1 ? "s " : " ") + index_ranges(items);
}

/// Appended to a rank's failure: what it held ("; it held tiles 3-4", "; it held no tile").
inline std::string held_suffix(const std::string& unit, const std::vector<int>& items) {
  return items.empty() ? "; it held no " + unit : "; it held " + held_text(unit, items);
}

/// The message for ranks that held work and did not answer when the run was stopped: with a
/// launcher that stops every rank when one dies, they are the dead ones. `silent` pairs a rank
/// with what it held.
inline std::string silent_ranks_message(const std::string& unit,
                                        const std::vector<std::pair<int, std::vector<int>>>& silent) {
  std::string message = "a rank stopped during the render:";
  for (const auto& [rank, items] : silent) {
    message += " rank " + std::to_string(rank) + " held " + held_text(unit, items) + " and did not answer;";
  }
  return message + " it has probably died, and the launcher stopped the others";
}

/// An exception that ended a render thread, for the message loop to notice while other threads
/// still run: set once by the failing thread, read by any (the flag orders the two).
class ThreadFailure {
 public:
  /// Records the exception being handled; call from a catch block.
  void set_current() {
    m_error = std::current_exception();
    m_set.store(true, std::memory_order_release);
  }
  /// Whether a thread has failed.
  explicit operator bool() const { return m_set.load(std::memory_order_acquire); }
  /// The failure's message ("unknown error" for what is not a std::exception); only once set.
  std::string message() const {
    try {
      std::rethrow_exception(m_error);
    } catch (const std::exception& x) {
      return x.what();
    } catch (...) {
      return "unknown error";
    }
  }

 private:
  std::exception_ptr m_error;
  std::atomic<bool> m_set{false};
};

}  // namespace raylab::dist
