// Image textures written beside a converted scene file: a PNG that reads back to the very same
// texels, or none when 8 bits cannot hold them.

#include <gtest/gtest.h>

#include <vector>

#include "raylab/core/srgb.h"
#include "raylab/io/texture_io.h"

namespace raylab {
namespace {

TEST(TexturePng, EightBitTexelsReadBackBitForBit) {
  // Every 8-bit code once, in each channel at a different place: 256 x 1 texels.
  std::vector<Color> texels;
  for (int i = 0; i < 256; ++i) {
    texels.push_back(
        {srgb_to_linear(i / 255.f), srgb_to_linear((255 - i) / 255.f), srgb_to_linear((i * 7 % 256) / 255.f)});
  }
  const TextureImage image(256, 1, texels);
  const auto png = encode_texture_png(image);
  ASSERT_TRUE(png.has_value());
  const auto back = decode_texture(*png, "t.png");
  ASSERT_EQ(back->width(), 256);
  ASSERT_EQ(back->height(), 1);
  for (int x = 0; x < 256; ++x) {
    const Color a = image.texel(x, 0), b = back->texel(x, 0);
    ASSERT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z) << "texel " << x;
  }
}

TEST(TexturePng, TexelsEightBitsCannotHoldGiveNoFile) {
  const TextureImage image(1, 1, {Color{0.123456f, 0.5f, 0.5f}});
  EXPECT_FALSE(encode_texture_png(image).has_value());
}

}  // namespace
}  // namespace raylab
