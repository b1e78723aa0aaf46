// Frame ranges as users write them, and the file each frame goes to.

#include <gtest/gtest.h>

#include "raylab/dist/frame_range.h"

namespace raylab::dist {
namespace {

TEST(FrameRange, ParsesARangeOrOneFrame) {
  EXPECT_EQ(parse_frame_range("3:7"), (std::pair{3, 7}));
  EXPECT_EQ(parse_frame_range("12"), (std::pair{12, 12}));
  EXPECT_EQ(parse_frame_range("0:0"), (std::pair{0, 0}));
  for (const char* bad : {"", ":", "7:3", "-1", "1:", ":2", "a:b", "1:2:3", "1234567890"}) {
    EXPECT_FALSE(parse_frame_range(bad)) << bad;
  }
}

TEST(FrameRange, NumbersTheOutput) {
  EXPECT_EQ(frame_output("f.####.png", 7), "f.0007.png");
  EXPECT_EQ(frame_output("f.##.png", 123), "f.123.png");
  EXPECT_EQ(frame_output("out.png", 7), "out.0007.png");
  EXPECT_EQ(frame_output("dir.v2/out", 12345), "dir.v2/out.12345");
  EXPECT_EQ(frame_output("out", 1), "out.0001");
}

}  // namespace
}  // namespace raylab::dist
