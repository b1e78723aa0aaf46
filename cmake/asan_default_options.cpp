// The AddressSanitizer settings every raylab program starts with, compiled into each executable
// (raylab_options in the top-level CMakeLists.txt) and empty in a build without the sanitizer.
// ASAN_OPTIONS in the environment still overrides them.
//
// intercept_tls_get_addr=0: up to GCC 13 and LLVM 16 the runtime's __tls_get_addr hook takes a
// dynamic TLS block that happens to start 16 bytes past a page boundary for one with glibc 2.19's
// header, reads the two words before it as that block's bounds, and LeakSanitizer's exit-time scan
// then faults on them ("Tracer caught signal 11"; google/sanitizers issue 1322). Glibc since 2.25
// has no such header, and ASan's malloc puts the first block of a size class exactly there, so
// whether a process that loads a module with TLS (Embree and TBB, through raylab's Embree module)
// dies at exit depends on which sizes it allocated first. Without the hook, LeakSanitizer skips the
// modules' dynamic TLS blocks; the executable's and libraries' static TLS is still scanned.

#include "raylab/core/address_sanitizer.h"

#if defined(RAYLAB_ADDRESS_SANITIZER)
/// Read by the AddressSanitizer runtime at start-up, before ASAN_OPTIONS.
extern "C" const char* __asan_default_options() { return "intercept_tls_get_addr=0"; }
#endif
