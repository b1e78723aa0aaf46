// A worker rank of a distributed render: says hello, renders the jobs rank 0 sends on all its
// threads, sends each back as it finishes, and reports its work when told to stop.

#include <chrono>
#include <exception>
#include <thread>

#include "coordinator.h"
#include "dist_util.h"
#include "job_queue.h"
#include "protocol.h"

namespace raylab::dist {
namespace {}  // namespace

DistributedResult serve(Channel& channel, TileRenderer& renderer, const DistributedOptions& options) {
  const auto start = Clock::now();
  DistributedResult result;
  channel.send(0, protocol::kHello,
               protocol::encode(
                   protocol::Hello{options.agreement, protocol::build_signature(), renderer.threads(), options.host}));
  JobQueue queue;
  ThreadFailure failure;
  std::thread threads([&] {
    try {
      renderer.run(queue);
    } catch (...) {
      failure.set_current();
      queue.abandon();
    }
  });
  auto last_sent = Clock::now();
  auto send = [&](int tag, std::vector<std::uint8_t> bytes) {
    channel.send(0, tag, std::move(bytes));
    last_sent = Clock::now();
  };
  auto send_finished = [&] {
    for (auto& [job, seconds] : queue.take_finished()) send(protocol::kResult, protocol::encode(job, seconds));
  };
  bool stopped = false;  // told kStop: report and end
  auto heard_from_root = Clock::now();
  while (true) {
    if (failure) break;
    if (options.render.should_stop && options.render.should_stop()) {
      // Say so at once: rank 0 tells an interrupted job from a dead rank by who says this.
      send(protocol::kInterrupted, {});
      queue.abandon();
      result.outcome = DistributedOutcome::kInterrupted;
      break;
    }
    send_finished();
    if (seconds_since(last_sent) >= kHeartbeatSeconds) send(protocol::kHeartbeat, {});
    // A short wait: finished jobs go out at the top of the loop, and a thread may be waiting
    // for the job that this result brings.
    std::optional<Message> m = channel.receive(kWorkerPollSeconds);
    if (!m) {
      if (seconds_since(heard_from_root) > options.rank_timeout_seconds) {
        // Rank 0 sends a heartbeat every second: it has died, and no launcher ended this rank.
        queue.abandon();
        result.outcome = DistributedOutcome::kFailed;
        result.message = "rank 0 has not answered for " + seconds_text(options.rank_timeout_seconds);
        break;
      }
      continue;
    }
    heard_from_root = Clock::now();
    if (m->tag == protocol::kJob) {
      queue.push(protocol::decode_job(m->bytes));
    } else if (m->tag == protocol::kStop) {
      queue.close();
      stopped = true;
      break;
    } else if (m->tag == protocol::kAbort) {
      // Answered, so that rank 0 can tell this live rank from a dead one.
      send(protocol::kInterrupted, {});
      queue.abandon();
      result.outcome = DistributedOutcome::kFailed;
      result.message = "rank 0 ended the run";
      break;
    }
  }
  threads.join();
  if (failure) {
    result.message = failure.message();
    send(protocol::kFailed, protocol::encode_text(result.message));
    result.outcome = DistributedOutcome::kFailed;
  } else if (stopped) {
    send_finished();
    RankReport report;
    report.rank = channel.rank();
    report.host = options.host;
    report.threads = renderer.threads();
    report.jobs = queue.jobs_done();
    report.stats = renderer.stats();
    report.busy_seconds = queue.busy_seconds();
    report.wall_seconds = seconds_since(start);
    send(protocol::kReport, protocol::encode(report));
    result.ranks.push_back(report);
  }
  result.render.stats = renderer.stats();
  result.render.seconds = seconds_since(start);
  channel.flush(10.0);
  return result;
}

}  // namespace raylab::dist
