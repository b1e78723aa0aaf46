#pragma once
// The instruction-set extensions the load-time CPU check knows (cpu_check.cpp). Plain data and
// out-of-line functions only: the check is compiled for baseline x86-64, and an inline function
// shared with the rest of the library (compiled with -march=${RAYLAB_ARCH}) could be linked to
// the other TU's copy, which may use the very instructions being checked for. Internal to
// src/core.

#include <cstdint>

namespace raylab::cpu {

/// Extensions that GCC and clang emit from plain C++ (vectorised loops, bit tricks) at some
/// -march level: the x86-64-v2, v3 and v4 levels and what -march=native adds on current
/// CPUs. Crypto extensions other than AES and PCLMUL are left out: nothing in raylab asks for them.
enum Feature : int {
  kSse3,
  kSsse3,
  kSse41,
  kSse42,
  kPopcnt,
  kAvx,
  kAvx2,
  kFma,
  kBmi,
  kBmi2,
  kF16c,
  kMovbe,
  kLzcnt,
  kAvx512f,
  kAvx512vl,
  kAvx512bw,
  kAvx512dq,
  kAvx512cd,
  kAvx512vnni,
  kAvx512vbmi,
  kAvx512vbmi2,
  kAvx512bitalg,
  kAvx512vpopcntdq,
  kAvx512ifma,
  kAvx512bf16,
  kGfni,
  kVpclmulqdq,
  kAes,
  kPclmul,
  kFeatureCount
};

/// Bit f is set when the library was compiled to use feature f: its -march, read from the
/// compiler's predefined macros (cpu_build_features.cpp).
extern const std::uint64_t kBuildFeatures;
/// The -march the library was compiled with (RAYLAB_ARCH, e.g. "x86-64-v3" or "native").
extern const char kBuildArch[];

/// The name of `f` as __builtin_cpu_supports and /proc/cpuinfo-style listings spell it.
const char* feature_name(Feature f);
/// Whether this CPU, and the operating system for the AVX register states, supports `f`.
bool cpu_supports(Feature f);
/// Whether RAYLAB_CPU_CHECK_PRETEND_MISSING lists `f`: the tests' way to play a CPU without it
/// (for the load-time check and for the choice of kernels, raylab/core/isa.h).
bool pretended_missing(Feature f);

}  // namespace raylab::cpu
