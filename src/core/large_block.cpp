#include "raylab/core/large_block.h"

#include <sys/mman.h>

#include <cstdint>
#include <new>

#include "raylab/core/address_sanitizer.h"

namespace raylab {

#if defined(RAYLAB_ADDRESS_SANITIZER)

void* allocate_large_block(std::size_t bytes) { return ::operator new (bytes, std::align_val_t{kHugePageBytes}); }

void free_large_block(void* block, std::size_t /*bytes*/) noexcept {
  ::operator delete (block, std::align_val_t{kHugePageBytes});
}

#else

namespace {

// `bytes` rounded up to whole huge pages.
std::size_t whole_pages(std::size_t bytes) { return (bytes + kHugePageBytes - 1) & ~(kHugePageBytes - 1); }

}  // namespace

void* allocate_large_block(std::size_t bytes) {
  if (bytes > SIZE_MAX - 2 * kHugePageBytes) throw std::bad_alloc();
  const std::size_t size = whole_pages(bytes);
  // One huge page more than asked for, so that an aligned block fits; the ends are given back.
  const std::size_t mapped = size + kHugePageBytes;
  void* const map = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (map == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(map);
  const std::uintptr_t aligned = (start + kHugePageBytes - 1) & ~std::uintptr_t{kHugePageBytes - 1};
  if (aligned > start) munmap(map, aligned - start);
  const std::size_t tail = start + mapped - (aligned + size);
  if (tail > 0) munmap(reinterpret_cast<void*>(aligned + size), tail);
  void* const block = reinterpret_cast<void*>(aligned);
  // Advice, not a requirement: where huge pages are off the block is ordinary memory.
  madvise(block, size, MADV_HUGEPAGE);
  return block;
}

void free_large_block(void* block, std::size_t bytes) noexcept { munmap(block, whole_pages(bytes)); }

#endif

}  // namespace raylab
