#pragma once
// The global `--isa` option and the RAYLAB_ISA variable, checked before any command runs.

#include <string>

namespace raylab::cli {

/// Makes `name` (from --isa; empty when not given) the active instruction set, or checks that
/// RAYLAB_ISA is valid when `name` is empty. Throws UsageError naming the option or the variable
/// when the set is unknown or this CPU cannot run it.
void choose_isa(const std::string& name);

}  // namespace raylab::cli
