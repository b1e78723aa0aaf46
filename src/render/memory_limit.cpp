#include "raylab/render/memory_limit.h"

#include <fmt/core.h>
#include <unistd.h>

#include "raylab/core/byte_size.h"
#include "raylab/core/error.h"

namespace raylab {

std::size_t default_memory_limit() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::size_t(1) << 40;  // unknown: no practical limit
  return static_cast<std::size_t>(static_cast<double>(pages) * static_cast<double>(page) * 0.8);
}

void check_memory_limit(const RenderMemoryEstimate& e, std::uint64_t primitives, std::optional<std::size_t> given) {
  const std::size_t limit = given ? *given : default_memory_limit();
  if (e.total() <= limit) return;
  throw UsageError(fmt::format(
      "this render would need about {} (image {}, per-tile sums {}, acceleration structure {} for {} primitives; "
      "{} primary samples), more than the limit of {}{}; lower --width or --height, or raise --max-memory",
      human_bytes(e.total()), human_bytes(e.image), human_bytes(e.sums), human_bytes(e.accelerator), primitives,
      e.samples, human_bytes(limit), given ? " (--max-memory)" : " (80% of this machine's memory)"));
}

}  // namespace raylab
