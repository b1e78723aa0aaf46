// reuse_freed_memory: large blocks come from the heap and stay there once freed, so that the
// next one reuses their pages. Checked in a fresh process (a death test in its threadsafe style
// runs the test binary again), where glibc's own thresholds are still its defaults: a block of
// 24 MiB would get its own mapping there, unmapped again when freed.

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "raylab/core/address_sanitizer.h"
#include "raylab/core/heap_policy.h"

#if defined(__GLIBC__)
#include <malloc.h>

namespace raylab {
namespace {

// 0 when a freed 24 MiB block stays in the heap and the next one of that size lies in it; else
// which step failed.
int reuse_check() {
  reuse_freed_memory();
  constexpr std::size_t kBytes = std::size_t(24) << 20;
  const struct mallinfo2 before = mallinfo2();
  char* first = static_cast<char*>(std::malloc(kBytes));
  if (first == nullptr) return 1;
  std::memset(first, 1, kBytes);
  if (mallinfo2().hblkhd != before.hblkhd) return 2;  // a mapping of its own
  std::free(first);
  if (mallinfo2().arena < before.arena + kBytes) return 3;  // handed back to the system
  char* second = static_cast<char*>(std::malloc(kBytes));
  if (second == nullptr) return 4;
  const bool reused = second == first;  // the same heap space
  std::free(second);
  return reused ? 0 : 5;
}

TEST(HeapPolicy, FreedBlocksStayForTheNextAllocation) {
#if defined(RAYLAB_ADDRESS_SANITIZER)
  GTEST_SKIP() << "AddressSanitizer's allocator replaces glibc's: mallopt does not reach it";
#endif
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(std::_Exit(reuse_check()), ::testing::ExitedWithCode(0), "")
      << "exit code 2: the block was mapped on its own; 3: freed memory went back; 5: not reused";
}

}  // namespace
}  // namespace raylab
#endif
