#include "isa_option.h"

#include <stdexcept>

#include "raylab/core/error.h"
#include "raylab/core/isa.h"

namespace raylab::cli {

void choose_isa(const std::string& name) {
  try {
    if (name.empty()) {
      static_cast<void>(active_isa());  // reads and checks RAYLAB_ISA
    } else {
      set_isa(usable_isa_named(name, "--isa " + name));
    }
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

}  // namespace raylab::cli
