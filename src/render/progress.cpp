#include "raylab/render/progress.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdlib>

#include "raylab/core/stopwatch.h"
#include "raylab/core/terminal.h"

namespace raylab {
namespace {

// The descriptor a bar's line is open on (drawn, not yet ended), or -1: what end_line_now, in a
// signal handler, may touch (a lock-free atomic).
std::atomic<int> g_open_line_fd{-1};
static_assert(std::atomic<int>::is_always_lock_free);

constexpr int kMaxBarWidth = 30;
constexpr int kMinBarWidth = 5;

}  // namespace

ProgressBar::ProgressBar(std::string label, std::FILE* out, bool interactive, int columns)
    : m_label(std::move(label)),
      m_out(out),
      m_interactive(interactive),
      m_columns(columns > 0 ? columns : raylab::terminal_columns(out != nullptr ? ::fileno(out) : -1)),
      m_start(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  // A bar left drawn (an exception past the render) still ends its line.
  std::lock_guard lock(m_mutex);
  if (m_interactive && m_drawn) {
    std::fprintf(m_out, "\n");
    g_open_line_fd.store(-1);
  }
}

std::string ProgressBar::format_duration(double seconds) {
  char buf[32];
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) return "?";
  if (seconds < 60.0) {
    std::snprintf(buf, sizeof buf, "%.1fs", seconds);
  } else if (seconds < 3600.0) {
    const int s = static_cast<int>(seconds);
    std::snprintf(buf, sizeof buf, "%dm%02ds", s / 60, s % 60);
  } else {
    const int m = static_cast<int>(seconds / 60.0);
    std::snprintf(buf, sizeof buf, "%dh%02dm", m / 60, m % 60);
  }
  return buf;
}

double ProgressBar::eta_seconds(int done, int total, double elapsed) {
  if (done <= 0 || total <= 0) return NAN;
  if (done >= total) return 0.0;
  return elapsed * static_cast<double>(total - done) / done;
}

std::string ProgressBar::format_line(const std::string& label, int done, int total, double elapsed, int columns) {
  const double fraction = total > 0 ? static_cast<double>(done) / total : 1.0;
  char percent[16];
  std::snprintf(percent, sizeof percent, "%3d%%", static_cast<int>(fraction * 100.0));
  const std::string eta = "ETA " + format_duration(eta_seconds(done, total, elapsed));
  const std::string times = "  elapsed " + format_duration(elapsed) + "  " + eta;
  const int room = columns - 1;
  // The parts by priority: percent and ETA first, then the bar, the elapsed time, the label.
  std::string head = label.empty() ? "" : label + " ";
  std::string tail = std::string(percent) + times;
  auto bar_room = [&] { return room - static_cast<int>(head.size() + tail.size()) - 3; };  // "[" "] "
  if (bar_room() < kMinBarWidth) tail = std::string(percent) + "  " + eta;
  if (bar_room() < kMinBarWidth) head.clear();
  std::string line = head;
  if (const int width = std::min(kMaxBarWidth, bar_room()); width >= kMinBarWidth) {
    const int filled = static_cast<int>(fraction * width);
    line += "[" + std::string(static_cast<std::size_t>(filled), '#') +
            std::string(static_cast<std::size_t>(width - filled), '-') + "] ";
  }
  line += tail;
  if (static_cast<int>(line.size()) > room) line.resize(static_cast<std::size_t>(std::max(0, room)));
  return line;
}

void ProgressBar::end_line_now() noexcept {
  const int fd = g_open_line_fd.exchange(-1);
  if (fd >= 0) {
    const ssize_t written = ::write(fd, "\n", 1);
    (void)written;  // nothing to do about a failed write on the way out
  }
}

void ProgressBar::update(int done, int total) {
  if (!m_interactive) return;
  const auto now = std::chrono::steady_clock::now();
  std::unique_lock lock(m_mutex, std::try_to_lock);
  if (!lock.owns_lock()) return;  // another thread is drawing; it will show progress soon enough
  if (m_drawn && now - m_last_draw < std::chrono::milliseconds(250) && done < total) return;
  m_last_draw = now;
  m_drawn = true;
  draw(done, total, std::chrono::duration<double>(now - m_start).count());
}

void ProgressBar::draw(int done, int total, double elapsed) {
  const std::string line = format_line(m_label, done, total, elapsed, m_columns);
  std::fprintf(m_out, "\r%s\x1b[K", line.c_str());
  std::fflush(m_out);
  g_open_line_fd.store(::fileno(m_out));
}

void ProgressBar::erase_locked() {
  if (m_interactive && m_drawn) {
    g_open_line_fd.store(-1);
    std::fprintf(m_out, "\r\x1b[K");
    std::fflush(m_out);
    m_drawn = false;
  }
}

void ProgressBar::clear() {
  std::lock_guard lock(m_mutex);
  erase_locked();
}

void ProgressBar::finish(const std::string& summary) {
  std::lock_guard lock(m_mutex);
  const double elapsed = seconds_since(m_start);
  erase_locked();
  std::fprintf(m_out, "%s: %s in %s\n", m_label.c_str(), summary.c_str(), format_duration(elapsed).c_str());
  std::fflush(m_out);
}

}  // namespace raylab
