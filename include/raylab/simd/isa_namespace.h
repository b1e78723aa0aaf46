#pragma once
/// \file
/// The namespace that keeps one instruction set's kernels apart from another's. raylab compiles
/// its kernel sources once per instruction set (raylab/core/isa.h); an inline function or a
/// template those sources share through a header would then be compiled several times under
/// one name, and the linker would keep one copy for all callers: a baseline caller could run
/// the AVX-512 copy and die of SIGILL. So every header whose inline code is a kernel's (the SIMD
/// types, the triangle and box tests, the walks) opens RAYLAB_ISA_BEGIN: an inline namespace
/// named after the instruction set of the translation unit's compile flags, invisible to
/// callers but part of every mangled name. Each set's copies are then distinct functions.

#include "raylab/core/isa.h"

#if defined(RAYLAB_SIMD_SCALAR)
#define RAYLAB_ISA_NS isa_scalar
#define RAYLAB_ISA_VALUE ::raylab::Isa::baseline
#elif defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512BW__) && defined(__AVX512DQ__)
#define RAYLAB_ISA_NS isa_avx512
#define RAYLAB_ISA_VALUE ::raylab::Isa::avx512
#elif defined(__AVX2__) && defined(__FMA__)
#define RAYLAB_ISA_NS isa_avx2
#define RAYLAB_ISA_VALUE ::raylab::Isa::avx2
#else
#define RAYLAB_ISA_NS isa_baseline
#define RAYLAB_ISA_VALUE ::raylab::Isa::baseline
#endif

/// Opens the instruction set's inline namespace (inside namespace raylab or one of its own).
#define RAYLAB_ISA_BEGIN inline namespace RAYLAB_ISA_NS {
/// Closes what RAYLAB_ISA_BEGIN opened.
#define RAYLAB_ISA_END }

namespace raylab {
RAYLAB_ISA_BEGIN

/// The kernel set this translation unit is compiled as, as a type: the template argument that
/// names a structure's kernels of this set (see src/accel/kernel_dispatch.h).
struct KernelIsa {
  static constexpr Isa value = RAYLAB_ISA_VALUE;  ///< the set, as a value
};

/// The kernel set of this translation unit's compile flags (in the library: its own set).
inline constexpr Isa kOwnKernelIsa = KernelIsa::value;

RAYLAB_ISA_END
}  // namespace raylab
