// UninitializedVector: a std::vector in every respect except that growing it without a value
// leaves the new elements default-initialised; over-aligned element types stay aligned, and
// values given explicitly are written as usual.

#include "raylab/core/uninitialized_vector.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace raylab {
namespace {

struct alignas(64) CacheLine {
  std::uint32_t v[16];
};

TEST(UninitializedVector, KeepsOverAlignedTypesAligned) {
  UninitializedVector<CacheLine> lines;
  for (int n : {1, 3, 1000, 70000}) {  // small blocks and blocks large enough to be mapped
    lines.resize(static_cast<std::size_t>(n));
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(lines.data()) % 64, 0u) << n << " elements";
  }
}

TEST(UninitializedVector, WritesWhatItIsGivenAndKeepsItThroughGrowth) {
  UninitializedVector<std::uint32_t> v;
  for (std::uint32_t i = 0; i < 100000; ++i) v.push_back(i * 7u);
  for (std::uint32_t i = 0; i < v.size(); i += 997) ASSERT_EQ(v[i], i * 7u);
  v.resize(200000);  // the new tail is unwritten; the prefix is kept
  EXPECT_EQ(v[99999], 99999u * 7u);
  UninitializedVector<int> filled(1000, 5);
  EXPECT_EQ(filled[999], 5);
  filled.assign(3, -2);
  EXPECT_EQ(filled, (UninitializedVector<int>{-2, -2, -2}));
  UninitializedVector<int> zeros;
  zeros.resize(4, 0);
  EXPECT_EQ(zeros, (UninitializedVector<int>{0, 0, 0, 0}));
}

}  // namespace
}  // namespace raylab
