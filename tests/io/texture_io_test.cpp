// load_texture / decode_texture: PNG (8 and 16 bit, RGB and grey) and JPEG decoded to linear RGB
// with rows in file order, and every refusal: missing file, not an image, a corrupt image, and a
// header claiming a size above the limit, refused before any decoding.

#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io_test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/image_io.h"
#include "raylab/io/texture_io.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

// A minimal PNG writer (stored, uncompressed deflate blocks), so that tests can write what
// stb_image_write cannot: 16-bit samples, and headers that lie about the image size.
class PngWriter {
 public:
  // `raw` holds the scanlines, each led by its filter byte.
  static Bytes encode(std::uint32_t width, std::uint32_t height, int bit_depth, int colour_type, const Bytes& raw) {
    Bytes out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    Bytes ihdr;
    put32(ihdr, width);
    put32(ihdr, height);
    ihdr.insert(ihdr.end(), {static_cast<unsigned char>(bit_depth), static_cast<unsigned char>(colour_type), 0, 0, 0});
    chunk(out, "IHDR", ihdr);
    chunk(out, "IDAT", zlib_stored(raw));
    chunk(out, "IEND", {});
    return out;
  }

 private:
  static void put32(Bytes& b, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<unsigned char>(v >> s));
  }
  static std::uint32_t crc32(const Bytes& data) {
    std::uint32_t c = 0xffffffffu;
    for (unsigned char byte : data) {
      c ^= byte;
      for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
  }
  static void chunk(Bytes& out, const char* type, const Bytes& data) {
    put32(out, static_cast<std::uint32_t>(data.size()));
    Bytes typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    out.insert(out.end(), typed.begin(), typed.end());
    put32(out, crc32(typed));
  }
  static Bytes zlib_stored(const Bytes& raw) {
    Bytes z = {0x78, 0x01};
    std::size_t pos = 0;
    do {
      const std::size_t n = std::min<std::size_t>(raw.size() - pos, 65535);
      const bool last = pos + n == raw.size();
      z.push_back(last ? 1 : 0);
      z.insert(z.end(), {static_cast<unsigned char>(n), static_cast<unsigned char>(n >> 8),
                         static_cast<unsigned char>(~n), static_cast<unsigned char>(~n >> 8)});
      z.insert(z.end(), raw.begin() + static_cast<std::ptrdiff_t>(pos),
               raw.begin() + static_cast<std::ptrdiff_t>(pos + n));
      pos += n;
    } while (pos < raw.size());
    std::uint32_t a = 1, b = 0;
    for (unsigned char byte : raw) {
      a = (a + byte) % 65521;
      b = (b + a) % 65521;
    }
    put32(z, (b << 16) | a);
    return z;
  }
};

void sink(void* context, void* data, int size) {
  auto* out = static_cast<Bytes*>(context);
  out->insert(out->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
}

Bytes stb_png(int w, int h, int comp, const Bytes& pixels) {
  Bytes out;
  EXPECT_NE(stbi_write_png_to_func(sink, &out, w, h, comp, pixels.data(), w * comp), 0);
  return out;
}

class TextureIo : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const Bytes& bytes) {
    return test::write_bytes(m_dir.path() / name, bytes);
  }
  // Loads `path`, which must fail with an InputError naming it and containing `fragment`.
  static void expect_refused(const std::string& path, const std::string& fragment) {
    try {
      load_texture(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }
  test::TempDir m_dir{"texio"};
};

void expect_color(Color got, Color want, float tolerance = 1e-6f) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

TEST_F(TextureIo, EightBitPngIsLinearisedWithRowsInFileOrder) {
  // 2 x 2: top row (0, 128, 255) | (255, 0, 64), bottom row (10, 20, 30) | (200, 100, 50).
  const Bytes pixels = {0, 128, 255, 255, 0, 64, 10, 20, 30, 200, 100, 50};
  const auto texture = load_texture(write("t.png", stb_png(2, 2, 3, pixels)));
  ASSERT_EQ(texture->width(), 2);
  ASSERT_EQ(texture->height(), 2);
  auto lin = [](int v) { return srgb_to_linear(static_cast<float>(v) / 255.f); };
  expect_color(texture->texel(0, 0), {0.f, lin(128), 1.f});
  EXPECT_NEAR(lin(128), 0.2158605f, 1e-5f);  // the sRGB curve, not a plain division
  expect_color(texture->texel(1, 0), {1.f, 0.f, lin(64)});
  expect_color(texture->texel(0, 1), {lin(10), lin(20), lin(30)});
  expect_color(texture->texel(1, 1), {lin(200), lin(100), lin(50)});
  // The top row is at the top of (u, v) space.
  expect_color(texture->sample(0.25f, 0.75f), texture->texel(0, 0));
}

TEST_F(TextureIo, GreyAndAlphaPngs) {
  const auto grey = load_texture(write("g.png", stb_png(2, 1, 1, {255, 128})));
  expect_color(grey->texel(0, 0), {1.f, 1.f, 1.f});
  const float half = srgb_to_linear(128.f / 255.f);
  expect_color(grey->texel(1, 0), {half, half, half});
  // Alpha is dropped, not multiplied in.
  const auto rgba = load_texture(write("a.png", stb_png(1, 1, 4, {255, 0, 0, 0})));
  expect_color(rgba->texel(0, 0), {1.f, 0.f, 0.f});
}

TEST_F(TextureIo, SixteenBitPngKeepsItsPrecision) {
  // One RGB texel of 16-bit samples 65535, 32768, 257 (big-endian), filter byte 0.
  const Bytes raw = {0, 0xff, 0xff, 0x80, 0x00, 0x01, 0x01};
  const auto texture = load_texture(write("s.png", PngWriter::encode(1, 1, 16, 2, raw)));
  expect_color(texture->texel(0, 0), {1.f, srgb_to_linear(32768.f / 65535.f), srgb_to_linear(257.f / 65535.f)});
  // 32768 and 32767 differ in 16 bits and would not in 8.
  EXPECT_NE(texture->texel(0, 0).y, srgb_to_linear(128.f / 255.f));
}

TEST_F(TextureIo, Jpeg) {
  Bytes pixels;
  for (int i = 0; i < 16 * 16; ++i) pixels.insert(pixels.end(), {200, 60, 30});
  Bytes jpeg;
  ASSERT_NE(stbi_write_jpg_to_func(sink, &jpeg, 16, 16, 3, pixels.data(), 100), 0);
  const auto texture = load_texture(write("t.jpg", jpeg));
  ASSERT_EQ(texture->width(), 16);
  // Lossy, but a flat colour survives within a few 8-bit steps.
  expect_color(texture->texel(7, 7),
               {srgb_to_linear(200.f / 255.f), srgb_to_linear(60.f / 255.f), srgb_to_linear(30.f / 255.f)}, 0.02f);
}

TEST_F(TextureIo, HugeHeaderIsRefusedBeforeDecoding) {
  // IHDR claims 100,000 x 100,000 texels; the pixel data is one scanline of nothing. Decoding
  // would fail differently (or try to allocate 30 GB): the size check must come first.
  const std::string path = write("huge.png", PngWriter::encode(100000, 100000, 8, 2, {0, 0, 0, 0}));
  expect_refused(path, "100000 x 100000");
  expect_refused(path, "too large");
}

TEST_F(TextureIo, HugeJpegHeaderIsRefusedBeforeDecoding) {
  Bytes pixels(8 * 8 * 3, 128);
  Bytes jpeg;
  ASSERT_NE(stbi_write_jpg_to_func(sink, &jpeg, 8, 8, 3, pixels.data(), 90), 0);
  // Make the frame header (SOF0: FF C0, length, precision, height, width) claim 65535 x 40000.
  std::size_t sof = 2;
  while (sof + 1 < jpeg.size() && !(jpeg[sof] == 0xff && jpeg[sof + 1] == 0xc0)) ++sof;
  ASSERT_LT(sof + 9, jpeg.size());
  jpeg[sof + 5] = 0x9c;  // height 40000 = 0x9c40
  jpeg[sof + 6] = 0x40;
  jpeg[sof + 7] = 0xff;  // width 65535
  jpeg[sof + 8] = 0xff;
  expect_refused(write("huge.jpg", jpeg), "65535 x 40000 texels is too large");
}

TEST_F(TextureIo, SideLimitIsRaylabsOwn) {
  // 20000 x 1 is well inside stb_image's limits and decodes fine, but passes raylab's 16384.
  Bytes raw(1 + 20000 * 3, 0);
  const std::string path = write("wide.png", PngWriter::encode(20000, 1, 8, 2, raw));
  expect_refused(path, "20000 x 1 texels is too large");
  // The same writer at the limit is accepted, which shows the refusal is the size alone.
  Bytes ok(1 + 16384 * 3, 0);
  const auto texture = load_texture(write("ok.png", PngWriter::encode(16384, 1, 8, 2, ok)));
  EXPECT_EQ(texture->width(), 16384);
}

TEST_F(TextureIo, NotAnImage) {
  const std::string text = "this is not an image\n";
  expect_refused(write("fake.png", Bytes(text.begin(), text.end())), "not a PNG or JPEG image");
  expect_refused(write("empty.png", {}), "not a PNG or JPEG image");
}

TEST_F(TextureIo, CorruptImage) {
  Bytes pixels(16 * 16 * 3);
  std::uint32_t state = 12345;  // noise, which does not compress
  for (unsigned char& p : pixels) p = static_cast<unsigned char>((state = state * 1664525u + 1013904223u) >> 24);
  Bytes png = stb_png(16, 16, 3, pixels);
  ASSERT_GT(png.size(), 200u);
  png.resize(png.size() / 2);  // the header stays, half the pixel data goes
  expect_refused(write("cut.png", png), "cannot decode image");
  // A signature and nothing else.
  expect_refused(write("sig.png", {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}), "not a valid PNG image");
}

TEST_F(TextureIo, MissingFile) { expect_refused(m_dir.file("missing.png"), "cannot open"); }

TEST_F(TextureIo, DecodeFromMemoryNamesTheElement) {
  const Bytes png = stb_png(1, 1, 3, {255, 255, 255});
  const auto texture = decode_texture(png, "scene.gltf", "images[2]");
  expect_color(texture->texel(0, 0), {1.f, 1.f, 1.f});
  try {
    decode_texture(Bytes{1, 2, 3}, "scene.gltf", "images[2]");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("scene.gltf: images[2]: not a PNG", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace raylab
