#pragma once
/// \file
/// SIGINT and SIGTERM for long renders. The first signal only sets a flag, which the render polls
/// between tiles so that it can finish the tiles under way and save what it has; a second signal
/// ends the process at once (exit status 128 + the signal), after a last-words function that may
/// only do async-signal-safe things (such as removing a half-written temporary file).

namespace raylab {

/// Installs the handlers for SIGINT and SIGTERM. `at_exit_now` (may be null) runs in the handler
/// just before a signal ends the process. With `exit_at_first`, already the first signal ends the
/// process that way (for work that cannot stop part-way and save).
void install_interrupt_handlers(void (*at_exit_now)(), bool exit_at_first = false);

/// The signal that asked to stop (SIGINT or SIGTERM), or 0 while none has. Safe from any thread.
int interrupt_signal();

/// The exit status for a run stopped by `signal`: 128 + signal (130 for SIGINT, 143 for SIGTERM).
int interrupt_exit_status(int signal);

/// Restores the default handlers and clears the flag (for tests that install them more than once).
void reset_interrupt_handlers();

}  // namespace raylab
