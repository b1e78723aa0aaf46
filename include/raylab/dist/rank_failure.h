#pragma once
/// \file
/// A rank failing outside the distributed protocol (before the render, or an exception out of
/// it: the scene did not load, a bug, a resource running out): the other ranks must hear of it at
/// once rather than wait for this rank until they time out.

#include <exception>

#include "raylab/dist/channel.h"

namespace raylab::dist {

/// Ends this rank's run for `e`; call it from the catch block that caught `e`. Rank 0 calls the
/// run off (call_off) and rethrows `e` (the program reports it). Any other rank tells rank 0,
/// which names it (report_failure), and returns the exit status for the process without a
/// message: 2 for a UsageError, 1 for an InputError, 3 for anything else.
int fail_outside_protocol(Channel& channel, const std::exception& e);

}  // namespace raylab::dist
