#pragma once
/// \file
/// A terminal progress bar with elapsed time and ETA.

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace raylab {

/// Progress reporting on a stream (stderr). On a terminal: a bar redrawn in place at most four
/// times a second. Otherwise: nothing while running and one summary line from `finish`.
class ProgressBar {
 public:
  /// `label` precedes the bar; `interactive` selects the redrawn bar over the summary line.
  ProgressBar(std::string label, std::FILE* out, bool interactive);

  /// Reports `done` of `total` units; redraws if a quarter second has passed. Thread-safe.
  void update(int done, int total);

  /// Finishes the bar (or prints the summary line) with the total elapsed time.
  void finish(const std::string& summary);

  /// Formats seconds as "1.2s", "3m04s" or "1h02m".
  static std::string format_duration(double seconds);

 private:
  void draw(int done, int total, double elapsed);

  std::string m_label;
  std::FILE* m_out;
  bool m_interactive;
  std::mutex m_mutex;
  std::chrono::steady_clock::time_point m_start;
  std::chrono::steady_clock::time_point m_last_draw;
  bool m_drawn = false;
};

}  // namespace raylab
