#include "raylab/core/byte_size.h"

#include <gtest/gtest.h>

namespace raylab {
namespace {

TEST(ByteSize, ParsesBinaryUnits) {
  EXPECT_EQ(parse_byte_size("4096"), 4096u);
  EXPECT_EQ(parse_byte_size("512B"), 512u);
  EXPECT_EQ(parse_byte_size("1K"), 1024u);
  EXPECT_EQ(parse_byte_size("1k"), 1024u);
  EXPECT_EQ(parse_byte_size("512M"), 512u << 20);
  EXPECT_EQ(parse_byte_size("1.5GiB"), (3ull << 30) / 2);
  EXPECT_EQ(parse_byte_size("2T"), 2ull << 40);
}

TEST(ByteSize, RefusesWhatIsNotAPositiveSize) {
  for (const char* bad : {"", "M", "8X", "-1G", "0", "nan", "1e19", "8 G"}) {
    EXPECT_FALSE(parse_byte_size(bad).has_value()) << bad;
  }
}

TEST(ByteSize, HumanBytesKeepsThreeOrFourDigits) {
  EXPECT_EQ(human_bytes(0), "0 B");
  EXPECT_EQ(human_bytes(1023), "1023 B");
  EXPECT_EQ(human_bytes(1536), "1.5 KiB");
  EXPECT_EQ(human_bytes(5u << 20), "5.0 MiB");
  EXPECT_EQ(human_bytes(9ull << 29), "4.50 GiB");
}

TEST(ByteSize, HumanBytesReadsBackWithinItsRounding) {
  for (const std::size_t n : {std::size_t{1} << 20, std::size_t{3} << 30, std::size_t{777777}}) {
    std::string text = human_bytes(n);
    text.erase(text.find(' '), 1);
    const auto back = parse_byte_size(text);
    ASSERT_TRUE(back.has_value()) << text;
    EXPECT_NEAR(static_cast<double>(*back), static_cast<double>(n), 0.01 * static_cast<double>(n)) << text;
  }
}

}  // namespace
}  // namespace raylab
