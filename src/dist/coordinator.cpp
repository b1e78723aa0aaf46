// Rank 0 of a distributed render: the tile scheduler, the message loop, and what happens when
// the run ends (completely, by an interrupt, or by a rank's failure).

#include "coordinator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "dist_util.h"
#include "protocol.h"

namespace raylab::dist {
namespace {

// What rank 0 knows of another rank.
struct Peer {
  bool greeted = false;    // its hello arrived and agreed
  int threads = 0;         // its render threads
  int held = 0;            // jobs sent and not yet back
  double job_seconds = 0;  // a running mean of the time its jobs take (0 until one is back)
  bool reported = false;   // its report arrived
  bool stopping = false;   // it said it stops (a signal, or answering rank 0's abort)
  RankReport report;
  Clock::time_point last_heard;
};

// The scheduler and message loop of rank 0 (see the file comment). Its own render threads take
// jobs through the TileJobSource interface, from the same queue as the other ranks.
class Coordinator final : public TileJobSource {
 public:
  Coordinator(Channel& channel, TileRenderer& renderer, Film& film, const DistributedOptions& options,
              RenderProgress& progress)
      : m_channel(channel),
        m_renderer(renderer),
        m_film(film),
        m_options(options),
        m_progress(progress),
        m_peers(static_cast<std::size_t>(channel.size())) {
    for (Peer& p : m_peers) p.last_heard = Clock::now();
    const std::vector<int> unfinished = m_progress.unfinished_tiles();
    m_tiles_total = m_progress.passes * m_progress.tile_count();
    m_tiles_done = m_progress.passes_done * m_progress.tile_count() +
                   (m_progress.tile_count() - static_cast<int>(unfinished.size()));
    m_pending.assign(unfinished.begin(), unfinished.end());
  }

  DistributedResult run() {
    const auto start = Clock::now();
    ThreadFailure local_failure;
    std::thread threads([&] {
      try {
        m_renderer.run(*this);
      } catch (...) {
        local_failure.set_current();
        stop_handing_out();
      }
    });
    DistributedResult result;
    auto last_checkpoint = Clock::now();
    auto last_heartbeat = Clock::now();
    while (!m_progress.complete()) {
      if (local_failure) {
        fail(0, "rank 0 failed: " + local_failure.message());
        break;
      }
      if (m_options.render.should_stop && m_options.render.should_stop()) {
        result.outcome = DistributedOutcome::kInterrupted;
        break;
      }
      std::optional<Message> m = m_channel.receive(kPollSeconds);
      if (m) handle(*m, result);
      if (!m_failure.empty()) break;
      if (result.outcome == DistributedOutcome::kInterrupted) break;
      check_silence();
      if (!m_failure.empty()) break;
      if (m_options.render.on_checkpoint && m_options.render.checkpoint_seconds > 0 &&
          seconds_since(last_checkpoint) >= m_options.render.checkpoint_seconds) {
        m_options.render.on_checkpoint(snapshot());
        last_checkpoint = Clock::now();
      }
      advance_pass_if_done();
      hand_out();
      if (seconds_since(last_heartbeat) >= kHeartbeatSeconds) {
        // The workers wait on rank 0 between passes; this tells them it is alive.
        for (int r = 1; r < m_channel.size(); ++r) m_channel.send(r, protocol::kHeartbeat, {});
        last_heartbeat = Clock::now();
      }
    }
    stop_handing_out();
    if (!m_failure.empty()) {
      result.outcome = DistributedOutcome::kFailed;
      end_early(result, m_failure);
    } else if (result.outcome == DistributedOutcome::kInterrupted) {
      end_interrupted(result);
    } else {
      for (int r = 1; r < m_channel.size(); ++r) m_channel.send(r, protocol::kStop, {});
      collect_reports();
      // A rank whose hello comes only now (it started late) is still checked: one that loaded
      // another scene fails the run whether or not the others finished without it.
      if (!m_failure.empty()) {
        result.outcome = DistributedOutcome::kFailed;
        end_early(result, m_failure);
      }
    }
    threads.join();
    develop(m_progress, m_film);
    result.render.seconds = seconds_since(start);
    result.render.samples_per_pixel = samples_per_pixel(m_progress);
    if (!m_renderer.notice().empty()) result.render.notices.push_back(m_renderer.notice());
    RankReport own;
    own.rank = 0;
    own.host = m_options.host;
    own.threads = m_renderer.threads();
    own.stats = m_renderer.stats();
    {
      const std::lock_guard lock(m_mutex);
      own.jobs = m_local_jobs;
      own.busy_seconds = m_local_busy;
    }
    own.wall_seconds = result.render.seconds;
    result.ranks.push_back(own);
    for (const Peer& p : m_peers) {  // in rank order
      if (p.reported) result.ranks.push_back(p.report);
    }
    for (const RankReport& r : result.ranks) result.render.stats += r.stats;
    result.render.interrupted = !m_progress.complete();
    if (result.outcome == DistributedOutcome::kComplete && !m_progress.complete()) {
      throw std::logic_error("distributed render ended incomplete without a reason");
    }
    return result;
  }

  // Rank 0's own threads.
  std::optional<TileJob> next() override {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [&] { return !m_pending.empty() || m_stopping; });
    if (m_stopping) return std::nullopt;
    return take_job(0);
  }

  void done(TileJob job, double seconds) override {
    int done_now = 0;
    {
      const std::lock_guard lock(m_mutex);
      m_local_busy += seconds;
      ++m_local_jobs;
      done_now = commit(0, std::move(job));
    }
    if (done_now > 0 && m_options.render.on_progress) m_options.render.on_progress(done_now, m_tiles_total);
  }

 private:
  // The first pending tile as a job for `rank`; m_mutex held.
  TileJob take_job(int rank) {
    const int t = m_pending.front();
    m_pending.pop_front();
    m_holder[t] = rank;
    TileJob job;
    job.tile = t;
    job.first = m_progress.samples_before(m_progress.passes_done);
    job.end = m_progress.samples_before(m_progress.passes_done + 1);
    job.sums = m_progress.tiles[static_cast<std::size_t>(t)];
    return job;
  }

  // Puts a finished job into the state if `rank` holds it; returns the tiles done so far, or 0
  // when the job was not expected (a late answer for a tile that is no longer its). m_mutex held.
  int commit(int rank, TileJob job) {
    const auto held = m_holder.find(job.tile);
    if (held == m_holder.end() || held->second != rank ||
        job.first != m_progress.samples_before(m_progress.passes_done)) {
      return 0;
    }
    const TileSums& expected = m_progress.tiles[static_cast<std::size_t>(job.tile)];
    if (job.sums.x0 != expected.x0 || job.sums.y0 != expected.y0 || job.sums.x1 != expected.x1 ||
        job.sums.y1 != expected.y1 || job.sums.sum.size() != expected.sum.size() ||
        job.sums.weight.size() != expected.weight.size()) {
      throw std::runtime_error("tile " + std::to_string(job.tile) + " came back with another shape");
    }
    m_holder.erase(held);
    m_progress.tiles[static_cast<std::size_t>(job.tile)] = std::move(job.sums);
    m_progress.tile_done[static_cast<std::size_t>(job.tile)] = 1;
    return ++m_tiles_done;
  }

  void handle(const Message& m, DistributedResult& result) {
    if (m.from <= 0 || m.from >= m_channel.size()) return;
    Peer& peer = m_peers[static_cast<std::size_t>(m.from)];
    peer.last_heard = Clock::now();
    try {
      switch (m.tag) {
        case protocol::kHello: {
          const protocol::Hello hello = protocol::decode_hello(m.bytes);
          if (hello.build != protocol::build_signature()) {
            fail(m.from, "rank " + std::to_string(m.from) + " (" + hello.host +
                             ") runs another build of raylab than rank 0: every rank must run the same program");
          } else if (hello.agreement != m_options.agreement) {
            fail(m.from, "rank " + std::to_string(m.from) + " (" + hello.host +
                             ") loaded another scene or other settings than rank 0: every rank must read the "
                             "same scene file with the same options");
          } else {
            peer.greeted = true;
            peer.threads = std::max(1, hello.threads);
            peer.report.host = hello.host;
          }
          break;
        }
        case protocol::kResult: {
          double seconds = 0;
          TileJob job = protocol::decode_job(m.bytes, &seconds);
          peer.job_seconds = peer.job_seconds == 0 ? seconds : 0.8 * peer.job_seconds + 0.2 * seconds;
          int done_now = 0;
          {
            const std::lock_guard lock(m_mutex);
            done_now = commit(m.from, std::move(job));
          }
          if (done_now > 0) {
            --peer.held;
            if (m_options.render.on_progress) m_options.render.on_progress(done_now, m_tiles_total);
          }
          break;
        }
        case protocol::kFailed:
          fail(m.from, "rank " + std::to_string(m.from) + " failed: " + protocol::decode_text(m.bytes));
          break;
        case protocol::kInterrupted:
          peer.stopping = true;
          result.outcome = DistributedOutcome::kInterrupted;
          break;
        case protocol::kReport:
          peer.report = protocol::decode_report(m.bytes);
          peer.reported = true;
          break;
        default:
          break;  // heartbeats: last_heard is all they carry
      }
    } catch (const std::runtime_error& e) {
      fail(m.from, "rank " + std::to_string(m.from) + " sent a message rank 0 cannot read (" + e.what() + ")");
    }
  }

  // Sends pending tiles to the ranks that can take them.
  void hand_out() {
    for (int r = 1; r < m_channel.size(); ++r) {
      Peer& p = m_peers[static_cast<std::size_t>(r)];
      while (p.greeted && p.held < jobs_to_hold(p)) {
        TileJob job;
        {
          const std::lock_guard lock(m_mutex);
          if (m_pending.empty() || m_stopping) return;
          job = take_job(r);
        }
        ++p.held;
        m_channel.send(r, protocol::kJob, protocol::encode(job));
      }
    }
  }

  // How many jobs rank `p` should hold: enough per thread that its threads never wait for the
  // next job while a result travels to rank 0 and a job back (kLatencySeconds), plus one; no
  // more, so that the last jobs of a pass are not stuck behind a long queue on one rank.
  static int jobs_to_hold(const Peer& p) {
    constexpr double kLatencySeconds = 0.005;
    const int per_thread =
        p.job_seconds > 0 ? static_cast<int>(std::clamp(std::ceil(kLatencySeconds / p.job_seconds), 1.0, 32.0)) : 2;
    return p.threads * per_thread + 1;
  }

  // When every tile has finished the pass under way: the next pass, or the end.
  void advance_pass_if_done() {
    {
      const std::lock_guard lock(m_mutex);
      if (!m_pending.empty() || !m_holder.empty()) return;
      if (std::find(m_progress.tile_done.begin(), m_progress.tile_done.end(), 0) != m_progress.tile_done.end()) return;
      ++m_progress.passes_done;
      if (m_progress.complete()) return;
      std::fill(m_progress.tile_done.begin(), m_progress.tile_done.end(), 0);
    }
    // Nothing is out: no thread touches the state while the image of this pass is developed.
    if (m_options.render.on_pass) {
      develop(m_progress, m_film);
      m_options.render.on_pass(m_progress.passes_done, m_film);
    }
    {
      const std::lock_guard lock(m_mutex);
      for (int t = 0; t < m_progress.tile_count(); ++t) m_pending.push_back(t);
    }
    m_changed.notify_all();
  }

  // A rank that holds tiles and has said nothing for too long is taken for dead.
  void check_silence() {
    for (int r = 1; r < m_channel.size(); ++r) {
      const Peer& p = m_peers[static_cast<std::size_t>(r)];
      if (held_by(r).empty() || seconds_since(p.last_heard) < m_options.rank_timeout_seconds) continue;
      fail(r, "rank " + std::to_string(r) + " has not answered for " + seconds_text(m_options.rank_timeout_seconds) +
                  " (dead or hung?)");
      return;
    }
  }

  std::vector<int> held_by(int rank) {
    const std::lock_guard lock(m_mutex);
    std::vector<int> tiles;
    for (const auto& [tile, holder] : m_holder) {
      if (holder == rank) tiles.push_back(tile);
    }
    return tiles;
  }

  // Records the first failure, with the tiles the failing rank held.
  void fail(int rank, const std::string& message) {
    if (!m_failure.empty()) return;
    const std::vector<int> tiles = held_by(rank);
    m_failure = message + held_suffix("tile", tiles) +
                (tiles.empty() ? "" : " of pass " + std::to_string(m_progress.passes_done + 1));
  }

  void stop_handing_out() {
    {
      const std::lock_guard lock(m_mutex);
      m_stopping = true;
    }
    m_changed.notify_all();
  }

  // A consistent copy of the state: the finished tiles, with tiles out counted as unfinished.
  RenderProgress snapshot() {
    const std::lock_guard lock(m_mutex);
    return m_progress;
  }

  // Waits a moment for results in flight and for the others to say why they stop; then the
  // message, the checkpoint, and the other ranks told to stop.
  void end_interrupted(DistributedResult& result) {
    for (int r = 1; r < m_channel.size(); ++r) m_channel.send(r, protocol::kAbort, {});
    const auto start = Clock::now();
    while (seconds_since(start) < m_options.interrupt_grace_seconds) {
      std::optional<Message> m = m_channel.receive(kPollSeconds);
      if (m) handle(*m, result);
    }
    std::vector<std::pair<int, std::vector<int>>> silent;
    for (int r = 1; r < m_channel.size(); ++r) {
      std::vector<int> tiles = held_by(r);
      // A live rank says it stops (on its own signal, or answering the abort); a dead one cannot.
      if (!tiles.empty() && !m_peers[static_cast<std::size_t>(r)].stopping) silent.emplace_back(r, std::move(tiles));
    }
    if (!silent.empty()) {
      result.outcome = DistributedOutcome::kFailed;
      end_early(result, silent_ranks_message("tile", silent), false);
      return;
    }
    result.message = "interrupted: saving the finished tiles";
    if (m_options.on_stopping) m_options.on_stopping(result.message);
    if (m_options.render.on_checkpoint) m_options.render.on_checkpoint(snapshot());
  }

  // Ends a failed run: the message, a checkpoint of the finished tiles, the others told to stop.
  void end_early(DistributedResult& result, const std::string& message, bool tell_others = true) {
    result.message = message;
    if (m_options.on_stopping) m_options.on_stopping(message);
    if (tell_others) {
      for (int r = 1; r < m_channel.size(); ++r) m_channel.send(r, protocol::kAbort, {});
    }
    if (m_options.render.on_checkpoint) m_options.render.on_checkpoint(snapshot());
    m_channel.flush(1.0);
  }

  // After kStop: every rank's report (a rank that never answers is left out of the table), and
  // the hello of any rank that has not said it yet.
  void collect_reports() {
    const auto start = Clock::now();
    auto missing = [&] {
      for (int r = 1; r < m_channel.size(); ++r) {
        if (!m_peers[static_cast<std::size_t>(r)].reported) return true;
      }
      return false;
    };
    DistributedResult ignored;  // (an interrupt now changes nothing: every tile is in)
    while (missing() && m_failure.empty() && seconds_since(start) < m_options.rank_timeout_seconds) {
      std::optional<Message> m = m_channel.receive(kPollSeconds);
      if (m) handle(*m, ignored);
    }
  }

  Channel& m_channel;
  TileRenderer& m_renderer;
  Film& m_film;
  const DistributedOptions& m_options;
  RenderProgress& m_progress;
  std::vector<Peer> m_peers;  // by rank (entry 0 unused)

  std::mutex m_mutex;  // guards what the render threads share with the loop (below)
  std::condition_variable m_changed;
  std::deque<int> m_pending;    // tiles of the pass under way not yet handed out
  std::map<int, int> m_holder;  // tile -> the rank rendering it
  bool m_stopping = false;      // no more jobs for anyone
  int m_tiles_done = 0;
  int m_tiles_total = 0;
  int m_local_jobs = 0;
  double m_local_busy = 0;

  std::string m_failure;  // the first failure (the loop's thread only)
};

}  // namespace

std::string seconds_text(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g s", s);
  return text;
}

DistributedResult coordinate(Channel& channel, TileRenderer& renderer, Film& film, const DistributedOptions& options) {
  RenderProgress own;
  RenderProgress& progress = options.render.progress != nullptr ? *options.render.progress : own;
  if (progress.tiles.empty()) {
    progress = renderer.start_progress(options.render.passes);
  } else {
    renderer.check_progress(progress);
  }
  Coordinator coordinator(channel, renderer, film, options, progress);
  return coordinator.run();
}

}  // namespace raylab::dist
