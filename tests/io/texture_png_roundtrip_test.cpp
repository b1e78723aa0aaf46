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

TEST(TexturePng, LinearDataMapsReadBackBitForBit) {
  // A data map (normal, bump, metallic-roughness) holds code / 255 itself: every code once.
  std::vector<Color> texels;
  for (int i = 0; i < 256; ++i) texels.push_back({i / 255.f, (255 - i) / 255.f, (i * 7 % 256) / 255.f});
  const TextureImage image(256, 1, texels);
  const auto png = encode_texture_png(image, TextureEncoding::kLinear);
  ASSERT_TRUE(png.has_value());
  const auto back = decode_texture(*png, "t.png", "", TextureEncoding::kLinear);
  for (int x = 0; x < 256; ++x) {
    const Color a = image.texel(x, 0), b = back->texel(x, 0);
    ASSERT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z) << "texel " << x;
  }
  // The same file read as colour decodes the codes as sRGB: code 128 is 0.2158, not 0.502.
  const auto as_colour = decode_texture(*png, "t.png");
  EXPECT_NEAR(as_colour->texel(128, 0).x, srgb_to_linear(128 / 255.f), 1e-6f);
  EXPECT_NE(as_colour->texel(128, 0).x, back->texel(128, 0).x);
}

TEST(TexturePng, LinearTexelsEightBitsCannotHoldGiveNoFile) {
  const TextureImage image(1, 1, {Color{0.5f, 0.5f, 1.f}});  // 0.5 is no code / 255
  EXPECT_FALSE(encode_texture_png(image, TextureEncoding::kLinear).has_value());
}

}  // namespace
}  // namespace raylab
