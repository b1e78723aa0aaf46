// An animation across ranks (distributed_frames.h): the same hello, heartbeat, failure and
// interrupt rules as a distributed image, with whole frames as the unit of work.

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

#include "coordinator.h"
#include "dist_util.h"
#include "protocol.h"
#include "raylab/dist/distributed_frames.h"
#include "wire.h"

namespace raylab::dist {
namespace {

std::vector<std::uint8_t> encode_frame(const RenderedFrame& f) {
  wire::Writer w;
  w.put(f.frame).put(f.film.width()).put(f.film.height()).put_vector(f.film.pixels());
  w.put_vector(f.result.samples_per_pixel).put(f.result.stats).put(f.result.seconds);
  return w.take();
}

RenderedFrame decode_frame(const std::vector<std::uint8_t>& bytes) {
  wire::Reader r(bytes);
  RenderedFrame f;
  f.frame = r.get<int>();
  const int width = r.get<int>(), height = r.get<int>();
  const std::vector<Color> pixels = r.get_vector<Color>();
  if (width < 0 || height < 0 || pixels.size() != std::size_t(width) * std::size_t(height)) {
    throw std::runtime_error("a frame's pixels do not match its size");
  }
  f.film = Film(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) f.film.at(x, y) = pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
  }
  f.result.samples_per_pixel = r.get_vector<std::uint32_t>();
  f.result.stats = r.get<RenderStats>();
  f.result.seconds = r.get<double>();
  return f;
}

// Frames to render on this process's own thread, and those it has finished.
class FrameQueue {
 public:
  void push(int frame) {
    {
      const std::lock_guard lock(m_mutex);
      m_todo.push_back(frame);
    }
    m_changed.notify_one();
  }
  void close(bool drop) {
    {
      const std::lock_guard lock(m_mutex);
      if (drop) m_todo.clear();
      m_closed = true;
    }
    m_changed.notify_all();
  }
  std::optional<int> next() {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [&] { return !m_todo.empty() || m_closed; });
    if (m_todo.empty()) return std::nullopt;
    const int f = m_todo.front();
    m_todo.pop_front();
    return f;
  }
  void done(RenderedFrame f) {
    const std::lock_guard lock(m_mutex);
    m_finished.push_back(std::move(f));
  }
  std::vector<RenderedFrame> take_finished() {
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_finished, {});
  }
  std::size_t queued() {
    const std::lock_guard lock(m_mutex);
    return m_todo.size();
  }

 private:
  std::mutex m_mutex;
  std::condition_variable m_changed;
  std::deque<int> m_todo;
  std::vector<RenderedFrame> m_finished;
  bool m_closed = false;
};

// Runs render_frame on the queue's frames on a thread of its own; keeps the time and count.
class FrameThread {
 public:
  FrameThread(const FramesOptions& options, FrameQueue& queue)
      : m_thread([this, &options, &queue] {
          try {
            while (std::optional<int> f = queue.next()) {
              const auto start = Clock::now();
              RenderedFrame frame = options.render_frame(*f);
              busy += seconds_since(start);
              stats += frame.result.stats;
              ++frames;
              queue.done(std::move(frame));
            }
          } catch (...) {
            failure.set_current();
            queue.close(true);
          }
        }) {}
  void join() { m_thread.join(); }

  /// What this thread did, as rank `rank`'s report, for a run that began at `start`.
  RankReport report(int rank, const FramesOptions& options, Clock::time_point start) const {
    RankReport r;
    r.rank = rank;
    r.host = options.host;
    r.threads = options.threads;
    r.jobs = frames;
    r.stats = stats;
    r.busy_seconds = busy;
    r.wall_seconds = seconds_since(start);
    return r;
  }

  double busy = 0;
  RenderStats stats;
  int frames = 0;
  ThreadFailure failure;  // noticed by the message loop while the thread runs

 private:
  std::thread m_thread;
};

FramesResult coordinate_frames(Channel& channel, const FramesOptions& options) {
  const auto start = Clock::now();
  FramesResult result;
  std::deque<int> pending(options.frames.begin(), options.frames.end());
  std::map<int, int> holder;  // frame -> rank
  std::vector<int> remaining_credit(static_cast<std::size_t>(channel.size()), 0);
  std::vector<bool> reported(static_cast<std::size_t>(channel.size()), false);
  std::vector<bool> stopping(static_cast<std::size_t>(channel.size()), false);  // said it stops
  std::vector<Clock::time_point> last_heard(static_cast<std::size_t>(channel.size()), Clock::now());
  std::vector<RankReport> reports(static_cast<std::size_t>(channel.size()));
  std::size_t delivered = 0;
  std::string failure;
  FrameQueue local;
  // Rank 0 keeps one frame queued for itself at a time, so that the others get the rest.
  auto feed_local = [&] {
    if (local.queued() == 0 &&
        std::count_if(holder.begin(), holder.end(), [](auto& h) { return h.second == 0; }) == 0 && !pending.empty()) {
      holder[pending.front()] = 0;
      local.push(pending.front());
      pending.pop_front();
    }
  };
  auto held_by = [&](int rank) {
    std::vector<int> frames;
    for (const auto& [f, r] : holder) {
      if (r == rank) frames.push_back(f);
    }
    return frames;
  };
  auto fail = [&](int rank, const std::string& message) {
    if (!failure.empty()) return;
    const std::vector<int> frames = held_by(rank);
    failure = message + held_suffix("frame", frames);
  };
  auto deliver = [&](int rank, RenderedFrame f) {
    const auto h = holder.find(f.frame);
    if (h == holder.end() || h->second != rank || f.result.interrupted) return;  // a cut-short frame is no frame
    holder.erase(h);
    ++delivered;
    if (options.on_frame) options.on_frame(f);
  };
  bool interrupt = false;
  auto handle = [&](const Message& m) {
    if (m.from <= 0 || m.from >= channel.size()) return;
    const auto r = static_cast<std::size_t>(m.from);
    last_heard[r] = Clock::now();
    try {
      if (m.tag == protocol::kHello) {
        const protocol::Hello hello = protocol::decode_hello(m.bytes);
        if (hello.build != protocol::build_signature() || hello.agreement != options.agreement) {
          fail(m.from, "rank " + std::to_string(m.from) + " (" + hello.host +
                           ") loaded another scene or other settings than rank 0, or runs another build");
        } else {
          remaining_credit[r] = 1;
        }
      } else if (m.tag == protocol::kFrameImage) {
        deliver(m.from, decode_frame(m.bytes));
        ++remaining_credit[r];
      } else if (m.tag == protocol::kFailed) {
        fail(m.from, "rank " + std::to_string(m.from) + " failed: " + protocol::decode_text(m.bytes));
      } else if (m.tag == protocol::kInterrupted) {
        stopping[r] = true;
        interrupt = true;
      } else if (m.tag == protocol::kReport) {
        reports[r] = protocol::decode_report(m.bytes);
        reported[r] = true;
      }
    } catch (const std::runtime_error& e) {
      fail(m.from, "rank " + std::to_string(m.from) + " sent a message rank 0 cannot read (" + e.what() + ")");
    }
  };

  feed_local();
  FrameThread own(options, local);
  auto last_heartbeat = Clock::now();
  while (delivered < options.frames.size()) {
    if (seconds_since(last_heartbeat) >= kHeartbeatSeconds) {
      for (int r = 1; r < channel.size(); ++r) channel.send(r, protocol::kHeartbeat, {});
      last_heartbeat = Clock::now();
    }
    if (own.failure) {
      fail(0, "rank 0 failed: " + own.failure.message());
      break;
    }
    if (options.should_stop && options.should_stop()) interrupt = true;
    if (interrupt) break;
    for (RenderedFrame& f : local.take_finished()) deliver(0, std::move(f));
    if (std::optional<Message> m = channel.receive(kPollSeconds)) handle(*m);
    if (!failure.empty() || interrupt) break;
    for (int r = 1; r < channel.size(); ++r) {
      if (!held_by(r).empty() &&
          seconds_since(last_heard[static_cast<std::size_t>(r)]) > options.rank_timeout_seconds) {
        fail(r, "rank " + std::to_string(r) + " has not answered for " + seconds_text(options.rank_timeout_seconds) +
                    " (dead or hung?)");
      }
    }
    if (!failure.empty()) break;
    for (int r = 1; r < channel.size(); ++r) {
      while (remaining_credit[static_cast<std::size_t>(r)] > 0 && !pending.empty()) {
        holder[pending.front()] = r;
        channel.send(r, protocol::kFrame, protocol::encode_int(pending.front()));
        pending.pop_front();
        --remaining_credit[static_cast<std::size_t>(r)];
      }
    }
    feed_local();
  }
  const bool complete = failure.empty() && !interrupt;
  local.close(!complete);
  if (complete) {
    for (int r = 1; r < channel.size(); ++r) channel.send(r, protocol::kStop, {});
    const auto wait = Clock::now();
    while (seconds_since(wait) < options.rank_timeout_seconds &&
           std::count(reported.begin() + 1, reported.end(), true) < channel.size() - 1) {
      if (std::optional<Message> m = channel.receive(kPollSeconds)) handle(*m);
    }
  } else {
    for (int r = 1; r < channel.size(); ++r) channel.send(r, protocol::kAbort, {});
    if (failure.empty()) {
      // As for one image: who does not say it was interrupted too is the rank that died.
      const auto wait = Clock::now();
      while (seconds_since(wait) < options.interrupt_grace_seconds) {
        if (std::optional<Message> m = channel.receive(kPollSeconds)) handle(*m);
        for (RenderedFrame& f : local.take_finished()) deliver(0, std::move(f));
      }
      std::vector<std::pair<int, std::vector<int>>> silent;
      for (int r = 1; r < channel.size(); ++r) {
        std::vector<int> frames = held_by(r);
        if (!frames.empty() && !stopping[static_cast<std::size_t>(r)]) silent.emplace_back(r, std::move(frames));
      }
      if (!silent.empty()) failure = silent_ranks_message("frame", silent);
    }
    result.message = failure.empty() ? "interrupted: the frames written so far stay" : failure;
    result.outcome = failure.empty() ? DistributedOutcome::kInterrupted : DistributedOutcome::kFailed;
    if (options.on_stopping) options.on_stopping(result.message);
    channel.flush(1.0);
  }
  own.join();
  if (complete) {
    for (RenderedFrame& f : local.take_finished()) deliver(0, std::move(f));
  }
  for (const auto& [frame, rank] : holder) result.unfinished.push_back(frame);
  result.unfinished.insert(result.unfinished.end(), pending.begin(), pending.end());
  std::sort(result.unfinished.begin(), result.unfinished.end());
  result.ranks.push_back(own.report(0, options, start));
  for (int r = 1; r < channel.size(); ++r) {
    if (reported[static_cast<std::size_t>(r)]) result.ranks.push_back(reports[static_cast<std::size_t>(r)]);
  }
  return result;
}

FramesResult serve_frames(Channel& channel, const FramesOptions& options) {
  const auto start = Clock::now();
  FramesResult result;
  channel.send(
      0, protocol::kHello,
      protocol::encode(protocol::Hello{options.agreement, protocol::build_signature(), options.threads, options.host}));
  auto last_sent = Clock::now();
  FrameQueue queue;
  FrameThread thread(options, queue);
  bool stopped = false;
  auto heard_from_root = Clock::now();
  while (true) {
    if (thread.failure) break;
    if (options.should_stop && options.should_stop()) {
      channel.send(0, protocol::kInterrupted, {});
      result.outcome = DistributedOutcome::kInterrupted;
      break;
    }
    for (const RenderedFrame& f : queue.take_finished()) {
      if (f.result.interrupted) continue;
      channel.send(0, protocol::kFrameImage, encode_frame(f));
      last_sent = Clock::now();
    }
    if (seconds_since(last_sent) >= kHeartbeatSeconds) {
      channel.send(0, protocol::kHeartbeat, {});
      last_sent = Clock::now();
    }
    std::optional<Message> m = channel.receive(kPollSeconds);
    if (!m) {
      if (seconds_since(heard_from_root) > options.rank_timeout_seconds) {  // rank 0 has died
        result.outcome = DistributedOutcome::kFailed;
        break;
      }
      continue;
    }
    heard_from_root = Clock::now();
    if (m->tag == protocol::kFrame) queue.push(protocol::decode_int(m->bytes));
    if (m->tag == protocol::kStop) {
      stopped = true;
      break;
    }
    if (m->tag == protocol::kAbort) {
      channel.send(0, protocol::kInterrupted, {});  // rank 0 tells live ranks from dead ones by this
      result.outcome = DistributedOutcome::kFailed;
      break;
    }
  }
  queue.close(!stopped);
  thread.join();
  if (thread.failure) {
    channel.send(0, protocol::kFailed, protocol::encode_text(thread.failure.message()));
    result.outcome = DistributedOutcome::kFailed;
  } else if (stopped) {
    const RankReport report = thread.report(channel.rank(), options, start);
    channel.send(0, protocol::kReport, protocol::encode(report));
    result.ranks.push_back(report);
  }
  channel.flush(10.0);
  return result;
}

}  // namespace

FramesResult render_frames_distributed(Channel& channel, const FramesOptions& options) {
  if (channel.rank() == 0) return coordinate_frames(channel, options);
  return serve_frames(channel, options);
}

}  // namespace raylab::dist
