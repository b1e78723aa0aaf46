#pragma once
/// \file
/// How many worker threads a request for N gets. TBB never runs more threads than the cores
/// this process may use (its market caps the workers, and an arena asking for more prints a raw
/// "TBB Warning" on stderr), so asking for more only costs that warning: every parallel part of
/// the library asks for usable_threads(N) instead, and a front end may say once what happened.

#include <string>

namespace raylab {

/// The cores this process may run on (its affinity mask, as TBB counts them); at least 1.
int available_cores();

/// The threads a request for `requested` gets: all available cores for 0 (or less), else
/// `requested` capped at available_cores().
int usable_threads(int requested);

/// A one-line note for the user when `requested` threads is more than this machine's cores
/// ("--threads 64 is more than this machine's 2 cores; using 2"), else empty. `option` names the
/// setting as the user gave it ("--threads").
std::string thread_count_notice(int requested, const std::string& option = "--threads");

}  // namespace raylab
