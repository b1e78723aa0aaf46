#include "raylab/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <vector>

#include "raylab/core/error.h"

namespace raylab {
namespace {

// The temporaries of the writes under way, for remove_pending_temporary_files: a few slots, each a
// name in a fixed buffer (no allocation, nothing a signal handler could find half-changed: a slot
// is marked in use only once its name is complete, and freed before the name is reused).
constexpr int kPendingSlots = 8;
struct PendingSlot {
  std::atomic<bool> in_use{false};
  std::atomic<bool> armed{false};
  char name[4096] = {};
};
PendingSlot g_pending[kPendingSlots];

// Registers temporary `name` while a write is under way; unregisters on destruction. When every
// slot is taken the write goes on unregistered (only a signal at that moment would leave it behind).
class PendingTemporary {
 public:
  explicit PendingTemporary(const std::string& name) {
    if (name.size() >= sizeof(PendingSlot::name)) return;
    for (PendingSlot& slot : g_pending) {
      bool expected = false;
      if (!slot.in_use.compare_exchange_strong(expected, true)) continue;
      std::memcpy(slot.name, name.c_str(), name.size() + 1);
      slot.armed.store(true);
      m_slot = &slot;
      return;
    }
  }
  ~PendingTemporary() {
    if (m_slot == nullptr) return;
    m_slot->armed.store(false);
    m_slot->in_use.store(false);
  }
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;

 private:
  PendingSlot* m_slot = nullptr;
};

std::string parent_folder(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// Why `path` cannot be written, or empty. `probe`: also create (and remove) a file in its folder.
std::string unwritable_reason(const std::string& path, bool probe) {
  namespace fs = std::filesystem;
  const std::string folder = parent_folder(path);
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    // The nearest part of the path that exists says what is wrong: a file where a folder
    // should be, else a folder that is missing.
    for (fs::path p = fs::path(folder); !p.empty() && p != p.parent_path(); p = p.parent_path()) {
      if (fs::is_directory(p, ec)) break;
      if (fs::exists(p, ec)) return "'" + p.string() + "' is a file, not a folder";
    }
    return "folder '" + folder + "' does not exist";
  }
  if (fs::is_directory(path, ec)) return "it is a folder";
  if (::access(folder.c_str(), W_OK) != 0)
    return "folder '" + folder + "' is not writable (" + std::strerror(errno) + ")";
  if (!probe) return "";
  // access() says yes to root everywhere, /proc included: only creating a file tells. The probe
  // is registered like a write's temporary, so that a signal cannot leave it behind.
  std::string temp = (fs::path(folder) / ".raylab-probe-XXXXXX").string();
  std::vector<char> name(temp.begin(), temp.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) return "folder '" + folder + "' is not writable (" + std::strerror(errno) + ")";
  const PendingTemporary pending(name.data());
  ::close(fd);
  ::unlink(name.data());
  return "";
}

}  // namespace

void check_writable(const std::string& path) {
  if (const std::string reason = unwritable_reason(path, true); !reason.empty()) {
    throw UsageError("cannot write '" + path + "': " + reason);
  }
}

void check_not_an_input(const std::string& path, const std::vector<std::string>& inputs) {
  std::error_code ec;
  for (const std::string& input : inputs) {
    // The same file by any name (a relative path, a link): an output that exists and is one.
    if (std::filesystem::equivalent(path, input, ec)) {
      throw UsageError("cannot write '" + path + "': it is one of the scene's own input files ('" + input +
                       "'); choose another output");
    }
  }
}

void write_file_atomically(const std::string& path, std::span<const unsigned char> bytes) {
  write_pieces_atomically(path, std::span<const std::span<const unsigned char>>(&bytes, 1));
}

void write_pieces_atomically(const std::string& path, std::span<const std::span<const unsigned char>> pieces) {
  // Found at write time, after the work: an input error (the file system changed, or no check
  // was made before); the probe is left out, as the temporary below is one.
  if (const std::string reason = unwritable_reason(path, false); !reason.empty()) {
    throw InputError(path, "cannot write: " + reason);
  }
  // mkstemp in the target's folder: the rename below then stays on one file system (atomic).
  // The name is cut so that the temporary's name (11 characters longer) stays within NAME_MAX
  // (255) whenever the target's does.
  const std::filesystem::path target(path);
  std::string temp = (target.parent_path() / target.filename().string().substr(0, 200)).string() + ".XXXXXX.tmp";
  std::vector<char> name(temp.begin(), temp.end());
  name.push_back('\0');
  const int fd = ::mkstemps(name.data(), 4);
  if (fd < 0) throw InputError(path, std::string("cannot create temporary file: ") + std::strerror(errno));
  temp.assign(name.data());
  const PendingTemporary pending(temp);
  auto fail = [&](const char* what) {
    const int err = errno;
    ::close(fd);
    ::unlink(temp.c_str());
    throw InputError(path, std::string(what) + ": " + std::strerror(err));
  };
  // Gathered writes, up to IOV_MAX pieces a call; a short write resumes inside its piece.
  std::vector<iovec> left;
  left.reserve(pieces.size());
  for (const std::span<const unsigned char> piece : pieces) {
    if (!piece.empty()) left.push_back({const_cast<unsigned char*>(piece.data()), piece.size()});
  }
  for (std::size_t next = 0; next < left.size();) {
    const int count = static_cast<int>(std::min<std::size_t>(left.size() - next, IOV_MAX));
    ssize_t n = ::writev(fd, left.data() + next, count);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write failed");
    }
    for (; next < left.size() && static_cast<std::size_t>(n) >= left[next].iov_len; ++next) {
      n -= static_cast<ssize_t>(left[next].iov_len);
    }
    if (n > 0) {  // part of piece `next` went out
      left[next].iov_base = static_cast<unsigned char*>(left[next].iov_base) + n;
      left[next].iov_len -= static_cast<std::size_t>(n);
    }
  }
  if (::fchmod(fd, 0644) != 0) fail("cannot set permissions");
  if (::fsync(fd) != 0) fail("cannot flush to disk");
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    throw InputError(path, std::string("close failed: ") + std::strerror(err));
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    throw InputError(path, std::string("cannot rename temporary file into place: ") + std::strerror(err));
  }
}

void write_text_atomically(const std::string& path, std::string_view text) {
  write_file_atomically(path, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
}

void remove_pending_temporary_files() noexcept {
  for (PendingSlot& slot : g_pending) {
    if (slot.armed.load()) ::unlink(slot.name);  // gone already once renamed into place: harmless
  }
}

}  // namespace raylab
