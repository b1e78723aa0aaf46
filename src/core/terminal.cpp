#include "raylab/core/terminal.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>

namespace raylab {
namespace {

constexpr int kDefaultColumns = 80;  // what a terminal without a size, or a file, gets
constexpr int kFewestColumns = 20;

}  // namespace

int columns_from_environment(const char* columns) {
  int n = 0;
  if (columns != nullptr) {
    const char* end = columns + std::strlen(columns);
    const auto [ptr, ec] = std::from_chars(columns, end, n);
    if (ec != std::errc() || ptr != end || n <= 0) n = 0;
  }
  return n > 0 ? std::max(n, kFewestColumns) : kDefaultColumns;
}

int terminal_columns(int fd) {
  winsize size{};
  if (::isatty(fd) && ::ioctl(fd, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) {
    return std::max(static_cast<int>(size.ws_col), kFewestColumns);
  }
  return columns_from_environment(std::getenv("COLUMNS"));
}

}  // namespace raylab
