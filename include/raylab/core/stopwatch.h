#pragma once
/// \file
/// Wall-clock timing for measurements and timeouts: the steady clock, never the calendar one.

#include <chrono>

namespace raylab {

/// The clock every timing in raylab reads (monotonic: a changed system time cannot make a
/// measurement negative).
using SteadyClock = std::chrono::steady_clock;

/// Seconds from `start` to now.
inline double seconds_since(SteadyClock::time_point start) {
  return std::chrono::duration<double>(SteadyClock::now() - start).count();
}

}  // namespace raylab
