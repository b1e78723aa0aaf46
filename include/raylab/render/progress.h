#pragma once
/// \file
/// A terminal progress bar with elapsed time and ETA.

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace raylab {

/// Progress reporting on a stream (stderr). On a terminal: a bar redrawn in place (carriage
/// return, then clear to the end of the line) at most four times a second, never wider than the
/// terminal so that it cannot wrap. Otherwise: nothing while running and one summary line from
/// `finish`.
class ProgressBar {
 public:
  /// `label` precedes the bar; `interactive` selects the redrawn bar over the summary line.
  /// `columns`: the terminal's width; 0 asks raylab::terminal_columns (core/terminal.h) of `out`.
  ProgressBar(std::string label, std::FILE* out, bool interactive, int columns = 0);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Reports `done` of `total` units; redraws if a quarter second has passed. Thread-safe.
  void update(int done, int total);

  /// Finishes the bar (or prints the summary line) with the total elapsed time.
  void finish(const std::string& summary);

  /// Erases the bar, if one is drawn, and prints nothing: for a caller that reports in its own words.
  void clear();

  /// Formats seconds as "1.2s", "3m04s" or "1h02m".
  static std::string format_duration(double seconds);

  /// Seconds left when `done` of `total` units took `elapsed` seconds, assuming the units left
  /// cost what the done ones did on average; NaN before the first unit (nothing to go by).
  static double eta_seconds(int done, int total, double elapsed);

  /// The bar's line for `done` of `total` after `elapsed` seconds, at most `columns` - 1
  /// characters (the last column would make some terminals wrap): the bar shrinks, then the
  /// elapsed time and the label go, as the width requires.
  static std::string format_line(const std::string& label, int done, int total, double elapsed, int columns);

  /// Ends a bar's line that is drawn now with a newline, so that whatever the terminal shows next
  /// starts on a line of its own. Async-signal-safe (one write), for a signal handler about to
  /// end the process mid-render.
  static void end_line_now() noexcept;

 private:
  void draw(int done, int total, double elapsed);
  void erase_locked();

  std::string m_label;
  std::FILE* m_out;
  bool m_interactive;
  int m_columns;
  std::mutex m_mutex;
  std::chrono::steady_clock::time_point m_start;
  std::chrono::steady_clock::time_point m_last_draw;
  bool m_drawn = false;
};

}  // namespace raylab
