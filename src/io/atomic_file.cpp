#include "raylab/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
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

}  // namespace

void check_writable(const std::string& path) {
  const std::string folder = parent_folder(path);
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    throw InputError(path, "cannot write: folder '" + folder + "' does not exist");
  }
  if (::access(folder.c_str(), W_OK) != 0) {
    throw InputError(path, "cannot write: folder '" + folder + "' is not writable (" + std::strerror(errno) + ")");
  }
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "cannot write: it is a folder");
}

void write_file_atomically(const std::string& path, std::span<const unsigned char> bytes) {
  check_writable(path);
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
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write failed");
    }
    written += static_cast<std::size_t>(n);
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
