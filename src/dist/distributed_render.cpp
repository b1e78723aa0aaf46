#include "raylab/dist/distributed_render.h"
#include "raylab/core/stopwatch.h"

#include <algorithm>
#include <chrono>

#include "coordinator.h"
#include "protocol.h"

namespace raylab::dist {

DistributedResult render_distributed(Channel& channel, TileRenderer& renderer, Film& film,
                                     const DistributedOptions& options) {
  if (channel.rank() == 0) return coordinate(channel, renderer, film, options);
  return serve(channel, renderer, options);
}

void call_off(Channel& channel) {
  for (int r = 1; r < channel.size(); ++r) channel.send(r, protocol::kAbort, {});
  channel.flush(5.0);
}

void report_failure(Channel& channel, const std::string& message, double seconds) {
  channel.send(0, protocol::kFailed, protocol::encode_text(message));
  const auto start = std::chrono::steady_clock::now();
  while (seconds_since(start) < seconds) {
    std::optional<Message> m = channel.receive(0.05);
    if (m && m->tag == protocol::kAbort) break;
  }
  channel.flush(1.0);
}

double load_imbalance(const std::vector<RankReport>& ranks) {
  double most = 0, total = 0;
  for (const RankReport& r : ranks) {
    most = std::max(most, r.busy_seconds);
    total += r.busy_seconds;
  }
  return total > 0 ? most / (total / static_cast<double>(ranks.size())) : 0.0;
}

}  // namespace raylab::dist
