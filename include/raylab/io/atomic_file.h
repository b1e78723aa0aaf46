#pragma once
/// \file
/// Writing files so that a reader never sees half of one.

#include <span>
#include <string>
#include <string_view>

namespace raylab {

/// Writes `bytes` to `path` atomically: to a temporary file in the same folder, flushed to disk,
/// then renamed over `path`. On failure the temporary is removed, any previous `path` is left
/// untouched, and InputError says why (missing folder, no permission, disk full).
void write_file_atomically(const std::string& path, std::span<const unsigned char> bytes);

/// Writes `text` to `path` atomically, as write_file_atomically does with bytes.
void write_text_atomically(const std::string& path, std::string_view text);

/// Removes the temporary files of the atomic writes under way, if any. Async-signal-safe (only
/// unlink), for a signal handler about to end the process: the targets stay as they were, and no
/// stray temporary is left beside them.
void remove_pending_temporary_files() noexcept;

/// Fails early, with the same InputError a write would give, when `path` cannot be written
/// (its folder is missing or not writable). Creates nothing.
void check_writable(const std::string& path);

}  // namespace raylab
