#include "raylab/io/read_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "raylab/core/error.h"

namespace raylab {
namespace {

// The innermost log of this thread (loaders run on the calling thread).
thread_local FileReadLog* t_log = nullptr;

}  // namespace

FileReadLog::FileReadLog() : m_outer(t_log) { t_log = this; }

FileReadLog::~FileReadLog() { t_log = m_outer; }

void note_file_read(const std::string& path) {
  for (FileReadLog* log = t_log; log != nullptr; log = log->m_outer) {
    if (std::find(log->m_files.begin(), log->m_files.end(), path) == log->m_files.end()) log->m_files.push_back(path);
  }
}

std::string read_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot open file: ") + std::strerror(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError(path, "cannot determine the file's size");
  in.seekg(0, std::ios::beg);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (size > 0 && !in.read(bytes.data(), size)) throw InputError(path, "cannot read the file");
  note_file_read(path);
  return bytes;
}

}  // namespace raylab
