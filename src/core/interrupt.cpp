#include "raylab/core/interrupt.h"

#include <unistd.h>

#include <atomic>
#include <csignal>

namespace raylab {
namespace {

// Lock-free atomics are what a signal handler may touch besides volatile sig_atomic_t.
std::atomic<int> g_signal{0};
std::atomic<void (*)()> g_at_exit_now{nullptr};
std::atomic<bool> g_exit_at_first{false};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<bool>::is_always_lock_free);

extern "C" void on_interrupt(int signal) {
  int expected = 0;
  const bool first = g_signal.compare_exchange_strong(expected, signal);
  if (first && !g_exit_at_first.load()) return;  // only the flag: the render stops between tiles
  if (void (*last_words)() = g_at_exit_now.load()) last_words();
  ::_exit(interrupt_exit_status(signal));
}

}  // namespace

void install_interrupt_handlers(void (*at_exit_now)(), bool exit_at_first) {
  g_at_exit_now.store(at_exit_now);
  g_exit_at_first.store(exit_at_first);
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a write or read under way goes on rather than failing with EINTR
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() { return g_signal.load(); }

int interrupt_exit_status(int signal) { return 128 + signal; }

void reset_interrupt_handlers() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  g_signal.store(0);
  g_at_exit_now.store(nullptr);
  g_exit_at_first.store(false);
}

}  // namespace raylab
