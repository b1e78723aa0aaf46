// Large blocks (the image, the builder's references, the wide BVH's arrays): aligned to a huge
// page, advised as huge pages, freed whole, and reached through the vectors that hold them.

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "raylab/core/address_sanitizer.h"
#include "raylab/core/large_block.h"
#include "raylab/core/uninitialized_vector.h"
#include "raylab/render/film.h"

namespace raylab {
namespace {

bool aligned_to_huge_page(const void* p) { return reinterpret_cast<std::uintptr_t>(p) % kHugePageBytes == 0; }

// The VmFlags line of /proc/self/smaps for the mapping that holds `address` ("" if none).
std::string vm_flags_of(const void* address) {
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
      inside = lo <= a && a < hi;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "";
}

TEST(LargeBlock, IsAlignedToAHugePageAndHoldsWhatIsWritten) {
  for (const std::size_t bytes : {kLargeBlockBytes, kHugePageBytes, 3 * kHugePageBytes + 12345}) {
    auto* block = static_cast<unsigned char*>(allocate_large_block(bytes));
    ASSERT_NE(block, nullptr);
    EXPECT_TRUE(aligned_to_huge_page(block)) << bytes;
    for (std::size_t i = 0; i < bytes; ++i) block[i] = static_cast<unsigned char>(i * 7);
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < bytes; ++i) wrong += block[i] != static_cast<unsigned char>(i * 7);
    EXPECT_EQ(wrong, 0u) << bytes;
    free_large_block(block, bytes);
  }
}

TEST(LargeBlock, IsAdvisedAsHugePagesAndUnmappedWhenFreed) {
#if defined(RAYLAB_ADDRESS_SANITIZER)
  GTEST_SKIP() << "under AddressSanitizer large blocks come from operator new, which it watches";
#endif
  const std::size_t bytes = 3 * kHugePageBytes;
  void* block = allocate_large_block(bytes);
  // "hg": madvise(MADV_HUGEPAGE) reached the block's mapping (whether the kernel then gives
  // huge pages depends on its settings and free memory, not on this code).
  const std::string flags = vm_flags_of(block);
  EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
  free_large_block(block, bytes);
  EXPECT_EQ(vm_flags_of(block), "") << "the block's pages are given back to the system";
}

TEST(LargeBlock, VectorsOfAMebibyteOrMoreUseThem) {
  UninitializedVector<float> small(kLargeBlockBytes / sizeof(float) - 1);
  UninitializedVector<float> large(kLargeBlockBytes / sizeof(float));
  EXPECT_TRUE(aligned_to_huge_page(large.data()));
#if !defined(RAYLAB_ADDRESS_SANITIZER)
  // One element short of a large block is an ordinary one: no huge-page advice on its memory.
  EXPECT_EQ(vm_flags_of(small.data()).find(" hg"), std::string::npos) << vm_flags_of(small.data());
  EXPECT_NE(vm_flags_of(large.data()).find(" hg"), std::string::npos) << vm_flags_of(large.data());
#endif
  // Growing from a small block to a large one and on keeps every element.
  UninitializedVector<std::uint32_t> grown;
  for (std::uint32_t i = 0; i < 3 * kHugePageBytes / sizeof(std::uint32_t); ++i) grown.push_back(i);
  EXPECT_TRUE(aligned_to_huge_page(grown.data()));
  std::uint32_t expected = 0;
  std::size_t wrong = 0;
  for (const std::uint32_t v : grown) wrong += v != expected++;
  EXPECT_EQ(wrong, 0u);
  grown.resize(10);
  grown.shrink_to_fit();  // back to a small block
  EXPECT_EQ(grown.size(), 10u);
  EXPECT_EQ(grown[9], 9u);
  // A copy (another allocation of the same size) holds the same elements.
  const UninitializedVector<float> copy = large;
  EXPECT_EQ(copy.size(), large.size());
  EXPECT_TRUE(aligned_to_huge_page(copy.data()));
}

TEST(LargeBlock, AFilmOfAMegapixelIsBlackInOne) {
  const Film film(1024, 1024);
  EXPECT_TRUE(aligned_to_huge_page(film.pixels().data()));
  std::size_t lit = 0;
  for (const Color& c : film.pixels()) lit += !(c == Color{0.f});
  EXPECT_EQ(lit, 0u) << "a new film is black, in huge pages or not";
}

}  // namespace
}  // namespace raylab
