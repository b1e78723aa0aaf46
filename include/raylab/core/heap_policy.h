#pragma once
/// \file
/// How the process's heap hands back and reuses memory: a choice for programs, not the library.

namespace raylab {

/// Makes the C library keep memory a program frees for its next allocations instead of
/// returning it to the system: blocks up to 32 MiB come from the heap (not each from its own
/// mapping, unmapped when freed), and up to 64 MiB freed at the heap's top stays mapped. Each
/// page the system hands a process is faulted in on first touch, and on a virtual machine a
/// fault can cost 10 us (docs/performance.md, "Page faults on a virtual machine"): a block the
/// process frees and then allocates again (a scene's loading and building buffers, an encoded
/// image) would come back as fresh pages. Peak memory is unchanged; memory is returned when
/// the process ends. Call it
/// once, first thing in main, before any thread starts. Does nothing outside glibc.
void reuse_freed_memory();

}  // namespace raylab
