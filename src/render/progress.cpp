#include "raylab/render/progress.h"
#include "raylab/core/stopwatch.h"

#include <cmath>

namespace raylab {

ProgressBar::ProgressBar(std::string label, std::FILE* out, bool interactive)
    : m_label(std::move(label)), m_out(out), m_interactive(interactive), m_start(std::chrono::steady_clock::now()) {}

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
  constexpr int kWidth = 30;
  const double fraction = total > 0 ? static_cast<double>(done) / total : 1.0;
  const int filled = static_cast<int>(fraction * kWidth);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '-');
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : NAN;
  std::fprintf(m_out, "\r%s [%s] %3d%%  elapsed %s  ETA %s\x1b[K", m_label.c_str(), bar.c_str(),
               static_cast<int>(fraction * 100.0), format_duration(elapsed).c_str(), format_duration(eta).c_str());
  std::fflush(m_out);
}

void ProgressBar::finish(const std::string& summary) {
  std::lock_guard lock(m_mutex);
  const double elapsed = seconds_since(m_start);
  if (m_interactive && m_drawn) std::fprintf(m_out, "\r\x1b[K");
  std::fprintf(m_out, "%s: %s in %s\n", m_label.c_str(), summary.c_str(), format_duration(elapsed).c_str());
  std::fflush(m_out);
}

}  // namespace raylab
