#include "isa_option.h"

#include <stdexcept>

#include "raylab/core/error.h"
#include "raylab/core/isa.h"

namespace raylab::cli {

void choose_isa(const std::string& name) {
  if (name.empty()) {
    try {
      static_cast<void>(active_isa());  // reads and checks RAYLAB_ISA
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    return;
  }
  const std::optional<Isa> isa = parse_isa(name);
  if (!isa) throw UsageError("--isa " + name + ": not an instruction set (expected baseline, avx2 or avx512)");
  const std::string reason = isa_unusable_reason(*isa);
  if (!reason.empty()) throw UsageError("--isa " + name + ": " + reason);
  set_isa(*isa);
}

}  // namespace raylab::cli
