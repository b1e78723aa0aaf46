#pragma once
/// \file
/// The memory a render may take: a render whose estimate (estimate_render_memory) is over the
/// limit is refused before anything is allocated, rather than left to the kernel's OOM killer.

#include <cstddef>
#include <cstdint>
#include <optional>

#include "raylab/render/renderer.h"

namespace raylab {

/// The limit when none is given: 80% of this machine's physical memory (2^40 bytes when the
/// machine does not say).
std::size_t default_memory_limit();

/// Throws UsageError when `estimate` is over `limit` (default_memory_limit() when empty), naming
/// the estimate's parts, the `primitives` of the scene and the limit. The message speaks of
/// --width, --height and --max-memory (the limit given), as the command line that sets them.
void check_memory_limit(const RenderMemoryEstimate& estimate, std::uint64_t primitives,
                        std::optional<std::size_t> limit);

}  // namespace raylab
