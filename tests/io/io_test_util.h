#pragma once
// Shared by the io tests that read and write real files: a fresh folder per test, and writing
// a file's exact bytes.

#include <atomic>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <string_view>
#include <system_error>

#include <unistd.h>

namespace raylab::test {

/// A fresh, empty folder `raylab-<tag>-<pid>-<n>` in the system temp folder, removed with all it
/// holds when the object goes. The pid and a counter keep parallel test processes and
/// successive tests out of each other's files.
class TempDir {
 public:
  /// Creates the folder, emptying what a crashed earlier run may have left under the same name.
  explicit TempDir(const std::string& tag)
      : m_path(std::filesystem::temp_directory_path() /
               ("raylab-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(next_number()))) {
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  /// Removes the folder; a failure to do so must not fail the test that used it.
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(m_path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// The folder.
  const std::filesystem::path& path() const { return m_path; }
  /// The path of file `name` in the folder, as a string.
  std::string file(const std::string& name) const { return (m_path / name).string(); }

 private:
  static int next_number() {
    static std::atomic<int> counter{0};
    return counter++;
  }

  std::filesystem::path m_path;
};

/// Writes `bytes` to file `path` as they are, replacing the file; returns `path` as a string.
inline std::string write_bytes(const std::filesystem::path& path, std::span<const unsigned char> bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return path.string();
}

/// Writes `text` to file `path` byte for byte (no newline translation); returns `path` as a
/// string.
inline std::string write_text(const std::filesystem::path& path, std::string_view text) {
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

}  // namespace raylab::test
