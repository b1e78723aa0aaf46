#include "raylab/core/heap_policy.h"

#include <cstdlib>  // defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace raylab {

void reuse_freed_memory() {
#if defined(__GLIBC__)
  // 32 MiB is glibc's own ceiling for the threshold it raises by itself after a mapped block is
  // freed; fixing it also fixes the trim threshold, hence the second call.
  constexpr int kMiB = 1 << 20;
  mallopt(M_MMAP_THRESHOLD, 32 * kMiB);
  mallopt(M_TRIM_THRESHOLD, 64 * kMiB);
#endif
}

}  // namespace raylab
