#pragma once
// How the ray queries share out a batch (internal to src/query): in parallel on TBB, with a
// check for a stop request between waves, and answers that do not depend on the thread count.

#include <cstddef>
#include <functional>

#include "raylab/query/ray_query.h"

namespace raylab {

/// Rays handed to one task at a time: enough to amortise the scheduling, few enough to balance.
inline constexpr std::size_t kQueryChunk = 256;

/// Calls `work(begin, end)` on disjoint ranges covering [0, count), each at most kQueryChunk
/// long, on `options.threads` threads (all cores for 0). Between waves of a few tens of
/// thousands of items it asks `options.should_stop` from the calling thread and throws
/// QueryInterrupted when it says so. Each item is handled by exactly one call, so results
/// written per item do not depend on the threads.
void run_query_batch(std::size_t count, const QueryOptions& options,
                     const std::function<void(std::size_t, std::size_t)>& work);

}  // namespace raylab
