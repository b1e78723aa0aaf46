#pragma once
/// \file
/// Reading a whole input file into memory, with a clear error when that is not possible.

#include <string>
#include <vector>

namespace raylab {

/// The bytes of file `path`. Throws InputError naming the file when it cannot be opened or read
/// (missing, a directory, no permission). Noted in the FileReadLog of this thread, if any.
std::string read_file(const std::string& path);

/// Notes that `path` was read, in the FileReadLog of this thread, if any: for a loader that
/// reads a file by other means than read_file (a library's own reader).
void note_file_read(const std::string& path);

/// The files read on this thread while it lives (read_file, note_file_read), each once, in the
/// order first read: how a loader learns every file a scene came from (the scene file, its
/// meshes, material libraries, textures, buffers), however deep the loaders nest. Logs nest: an
/// inner one's files are noted in the outer ones too.
class FileReadLog {
 public:
  FileReadLog();
  ~FileReadLog();
  FileReadLog(const FileReadLog&) = delete;
  FileReadLog& operator=(const FileReadLog&) = delete;

  /// The paths read so far, as they were given to read_file.
  const std::vector<std::string>& files() const { return m_files; }

 private:
  friend void note_file_read(const std::string& path);
  FileReadLog* m_outer;
  std::vector<std::string> m_files;
};

}  // namespace raylab
