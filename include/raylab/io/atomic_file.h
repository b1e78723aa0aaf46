#pragma once
/// \file
/// Writing files so that a reader never sees half of one.

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

/// Writes `bytes` to `path` atomically: to a temporary file in the same folder, flushed to disk,
/// then renamed over `path`. On failure the temporary is removed, any previous `path` is left
/// untouched, and InputError says why (missing folder, no permission, disk full).
void write_file_atomically(const std::string& path, std::span<const unsigned char> bytes);

/// As write_file_atomically(path, bytes) for the bytes of `pieces` one after the other, written
/// where they lie (an image's rows straight from its film) rather than first copied together.
void write_pieces_atomically(const std::string& path, std::span<const std::span<const unsigned char>> pieces);

/// Writes `text` to `path` atomically, as write_file_atomically does with bytes.
void write_text_atomically(const std::string& path, std::string_view text);

/// Removes the temporary files of the atomic writes under way, if any. Async-signal-safe (only
/// unlink), for a signal handler about to end the process: the targets stay as they were, and no
/// stray temporary is left beside them.
void remove_pending_temporary_files() noexcept;

/// Fails early, before any work, with UsageError (the command line's exit 2) naming the
/// problem when `path` cannot be written: its folder is missing, a part of the path is a file, the
/// path is a folder, or the folder refuses a new file (tried: access() says yes to root even in
/// /proc). Leaves nothing behind.
void check_writable(const std::string& path);

/// Fails with UsageError when `path` is one of `inputs` (the files a scene was read from:
/// Scene::source_files), by any name: writing there would destroy an input of the work.
void check_not_an_input(const std::string& path, const std::vector<std::string>& inputs);

}  // namespace raylab
