#pragma once
// Internal to the dist module: the clock, timing and error text every role of a distributed run uses.

#include <chrono>
#include <exception>
#include <string>

namespace raylab::dist {

using Clock = std::chrono::steady_clock;

/// Seconds from `t` to now.
inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// Longest wait for a message before a message loop looks around again (signals, timeouts).
inline constexpr double kPollSeconds = 0.02;

/// A worker's wait for a message before it looks for finished jobs to send back.
inline constexpr double kWorkerPollSeconds = 0.001;

/// A worker with nothing else to say says it is alive this often, so that only a dead or hung
/// process stays silent for long.
inline constexpr double kHeartbeatSeconds = 1.0;

/// The message of the exception `e` holds ("unknown error" for one that is not a std::exception).
inline std::string what(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const std::exception& x) {
    return x.what();
  } catch (...) {
    return "unknown error";
  }
}

}  // namespace raylab::dist
