#pragma once
// Internal to the dist module: the jobs a worker rank has been given, between its message loop
// (which pushes them as they arrive and sends back the finished ones) and its render threads.

#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "raylab/render/tile_renderer.h"

namespace raylab::dist {

/// A TileJobSource fed from outside (see the file comment).
class JobQueue final : public TileJobSource {
 public:
  /// Adds a job for the threads.
  void push(TileJob job) {
    {
      const std::lock_guard lock(m_mutex);
      m_jobs.push_back(std::move(job));
    }
    m_changed.notify_one();
  }
  /// No more jobs will come: the threads stop once the queue is empty.
  void close() {
    {
      const std::lock_guard lock(m_mutex);
      m_closed = true;
    }
    m_changed.notify_all();
  }
  /// Drops the jobs not started; the threads stop after the jobs under way.
  void abandon() {
    {
      const std::lock_guard lock(m_mutex);
      m_jobs.clear();
      m_closed = true;
    }
    m_changed.notify_all();
  }
  std::optional<TileJob> next() override {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [&] { return !m_jobs.empty() || m_closed; });
    if (m_jobs.empty()) return std::nullopt;
    TileJob job = std::move(m_jobs.front());
    m_jobs.pop_front();
    return job;
  }
  void done(TileJob job, double seconds) override {
    const std::lock_guard lock(m_mutex);
    m_busy_seconds += seconds;
    ++m_jobs_done;
    m_finished.emplace_back(std::move(job), seconds);
  }
  /// The jobs finished since the last call, with the seconds each took.
  std::vector<std::pair<TileJob, double>> take_finished() {
    const std::lock_guard lock(m_mutex);
    return std::exchange(m_finished, {});
  }
  /// Thread-seconds spent on jobs so far.
  double busy_seconds() {
    const std::lock_guard lock(m_mutex);
    return m_busy_seconds;
  }
  /// Jobs finished so far.
  int jobs_done() {
    const std::lock_guard lock(m_mutex);
    return m_jobs_done;
  }

 private:
  std::mutex m_mutex;
  std::condition_variable m_changed;
  std::deque<TileJob> m_jobs;
  std::vector<std::pair<TileJob, double>> m_finished;
  bool m_closed = false;
  double m_busy_seconds = 0;
  int m_jobs_done = 0;
};

}  // namespace raylab::dist
