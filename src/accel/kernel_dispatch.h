#pragma once
// Calling the kernels of the instruction set an accelerator was built with (internal to
// src/accel). A structure's kernels are member templates with a last parameter `class K`, the
// KernelIsa tag of the set (raylab/simd/isa_namespace.h); the kernel sources are compiled once
// per set (src/CMakeLists.txt, RAYLAB_KERNEL_SOURCES), each instantiating them with its own tag,
// and with_kernels picks the instantiation at run time.

#include "raylab/core/isa.h"
#include "raylab/simd/isa_namespace.h"

namespace raylab {

// The tags of the sets compiled beside the library's own (declared here, defined in the kernel
// sources compiled for them).
#ifdef RAYLAB_KERNELS_AVX2
namespace isa_avx2 {
struct KernelIsa;
}
#endif
#ifdef RAYLAB_KERNELS_AVX512
namespace isa_avx512 {
struct KernelIsa;
}
#endif

/// Calls `f.template operator()<K>()` with K the tag of `isa`'s kernels: a set this build lacks
/// falls back to the library's own (active_isa never hands one out).
template <class F>
decltype(auto) with_kernels(Isa isa, F&& f) {
#ifdef RAYLAB_KERNELS_AVX512
  if (isa == Isa::avx512) return f.template operator()<isa_avx512::KernelIsa>();
#endif
#ifdef RAYLAB_KERNELS_AVX2
  if (isa == Isa::avx2) return f.template operator()<isa_avx2::KernelIsa>();
#endif
  static_cast<void>(isa);
  return f.template operator()<KernelIsa>();
}

}  // namespace raylab

// Structure's single-ray kernel `traverse` under the set tag Tag, in the four forms
// TraversalAccelerator calls, each preceded by `Keywords`: `template` instantiates them,
// `extern template` declares them compiled elsewhere.
#define RAYLAB_TRAVERSE_FORMS(Keywords, Structure, Tag)                                    \
  Keywords bool Structure::traverse<false, false, Tag>(Ray&, Hit&, TraversalStats*) const; \
  Keywords bool Structure::traverse<true, false, Tag>(Ray&, Hit&, TraversalStats*) const;  \
  Keywords bool Structure::traverse<false, true, Tag>(Ray&, Hit&, TraversalStats*) const;  \
  Keywords bool Structure::traverse<true, true, Tag>(Ray&, Hit&, TraversalStats*) const

// Instantiates Structure's kernel under the set tag Tag.
#define RAYLAB_INSTANTIATE_TRAVERSE_AS(Structure, Tag) RAYLAB_TRAVERSE_FORMS(template, Structure, Tag)

// In a kernel source: instantiates Structure's kernel for this translation unit's set.
#define RAYLAB_INSTANTIATE_TRAVERSE(Structure) RAYLAB_INSTANTIATE_TRAVERSE_AS(Structure, KernelIsa)

// Declares Structure's kernel for the set whose tag is Tag as compiled elsewhere (in that set's
// kernel source): without it, the source that instantiates the entry points would compile its
// own copy under the same name, with its own flags, and the linker could keep that one.
#define RAYLAB_EXTERN_TRAVERSE(Structure, Tag) RAYLAB_TRAVERSE_FORMS(extern template, Structure, Tag)

#ifdef RAYLAB_KERNELS_AVX2
#define RAYLAB_EXTERN_TRAVERSE_AVX2(Structure) RAYLAB_EXTERN_TRAVERSE(Structure, isa_avx2::KernelIsa);
#else
#define RAYLAB_EXTERN_TRAVERSE_AVX2(Structure)
#endif
#ifdef RAYLAB_KERNELS_AVX512
#define RAYLAB_EXTERN_TRAVERSE_AVX512(Structure) RAYLAB_EXTERN_TRAVERSE(Structure, isa_avx512::KernelIsa);
#else
#define RAYLAB_EXTERN_TRAVERSE_AVX512(Structure)
#endif

// In a structure's kernel source, compiled with the library's own flags: the four entry points
// of TraversalAccelerator<Structure>, which call the kernel of each built set.
#define RAYLAB_INSTANTIATE_ENTRY_POINTS(Structure) \
  RAYLAB_EXTERN_TRAVERSE_AVX2(Structure)           \
  RAYLAB_EXTERN_TRAVERSE_AVX512(Structure)         \
  template class TraversalAccelerator<Structure>
