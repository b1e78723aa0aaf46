#pragma once
/// \file
/// The CPU the library was built for. A release build uses -march=x86-64 and runs anywhere (its
/// wider kernels are chosen at run time, raylab/core/isa.h); a build for a higher level
/// (RAYLAB_ARCH=x86-64-v3, native) prints, on a CPU without what it uses, what is missing and
/// exits with status 1 when it is loaded, before any instruction the CPU lacks can raise SIGILL.
/// These functions let a program or a test ask the same questions.

#include <string>
#include <vector>

namespace raylab {

/// The instruction-set extensions the library was compiled to use (from its -march), named as
/// GCC's __builtin_cpu_supports names them ("avx2", "fma", "avx512f", ...).
std::vector<std::string> required_cpu_features();

/// Those of required_cpu_features() that this CPU (or its operating system) lacks: empty when
/// the library can run here, which it always is once the library has loaded.
std::vector<std::string> missing_cpu_features();

/// The -march the library was compiled with (the RAYLAB_ARCH setting: "x86-64-v3", "native", ...).
const char* build_cpu_arch();

}  // namespace raylab
