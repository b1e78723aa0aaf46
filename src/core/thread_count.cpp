#include "raylab/core/thread_count.h"

#include <tbb/info.h>

#include <algorithm>

namespace raylab {

int available_cores() { return std::max(1, tbb::info::default_concurrency()); }

int usable_threads(int requested) {
  const int cores = available_cores();
  return requested <= 0 ? cores : std::min(requested, cores);
}

std::string thread_count_notice(int requested, const std::string& option) {
  const int cores = available_cores();
  if (requested <= cores) return "";
  return option + " " + std::to_string(requested) + " is more than this machine's " + std::to_string(cores) +
         (cores == 1 ? " core" : " cores") + "; using " + std::to_string(cores);
}

}  // namespace raylab
