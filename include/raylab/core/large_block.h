#pragma once
/// \file
/// Memory for the few large arrays of a render (the image, the BVH builder's references, the
/// wide BVH's nodes and triangle blocks) in transparent huge pages where the system has them.
///
/// Each 4 KiB page a process touches for the first time costs a page fault; on a virtual machine
/// one costs 10-15 us (docs/performance.md, "Page faults on a virtual machine"), so the 3 MB
/// image of a 512 x 512 render took 770 of them. A 2 MiB huge page is one fault. Embree asks
/// for huge pages for its BVH memory the same way (madvise(MADV_HUGEPAGE) on Linux).

#include <cstddef>

namespace raylab {

/// A transparent huge page on x86-64: large blocks are aligned to it and made of whole ones.
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

/// Blocks of at least this many bytes are large. Half a huge page: one fault and 2 MiB zeroed
/// cost less than 256 faults of 4 KiB, and the few large arrays of a render can spare the rest.
inline constexpr std::size_t kLargeBlockBytes = kHugePageBytes / 2;

/// True when a block of `bytes` is large: the one rule by which every user of large blocks
/// (DefaultInitAllocator, the Python module's answer arrays) decides.
constexpr bool is_large_block(std::size_t bytes) { return bytes >= kLargeBlockBytes; }

/// A block of `bytes` (at least kLargeBlockBytes) of uninitialised memory, aligned to kHugePageBytes
/// and advised to the kernel as huge pages (MADV_HUGEPAGE: used where the kernel's transparent
/// huge pages are on, ignored elsewhere). Throws std::bad_alloc when there is no memory. Under
/// AddressSanitizer the block comes from operator new instead, so that the sanitizer still
/// watches it.
void* allocate_large_block(std::size_t bytes);

/// Frees a block that allocate_large_block(bytes) gave.
void free_large_block(void* block, std::size_t bytes) noexcept;

}  // namespace raylab
