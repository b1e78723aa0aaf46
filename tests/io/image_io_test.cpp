// Image files: float formats round-trip bit-exactly, PNG within its 8-bit quantisation, the sRGB
// curves invert each other, and the RMSE is the analytic one.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "io_test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

class ImageIo : public ::testing::Test {
 protected:
  std::string file(const std::string& name) const { return m_dir.file(name); }

 private:
  test::TempDir m_dir{"image-io"};
};

// An odd-sized film where every channel of every pixel is different, so that a flipped row
// order, swapped channels or a transposition all show; includes values above 1, tiny values,
// a denormal, zero and negatives (float formats must keep them all).
Film float_film() {
  Film f(5, 3);
  const float specials[] = {0.f, 1.f, 1e-30f, 1e-40f, 65504.f, 3.4e38f, -2.5f, 0.1f, 1.0000001f};
  int i = 0;
  for (int y = 0; y < f.height(); ++y) {
    for (int x = 0; x < f.width(); ++x, ++i) {
      const float base = specials[i % std::size(specials)];
      f.at(x, y) = {base, 0.001f * static_cast<float>(i) + 1.5f, -static_cast<float>(i) * 1e-7f};
    }
  }
  return f;
}

bool same_bits(const Film& a, const Film& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Color)) == 0;
}

TEST_F(ImageIo, PfmRoundTripIsBitExact) {
  const Film f = float_film();
  write_image(f, file("a.pfm"));
  EXPECT_TRUE(same_bits(read_image(file("a.pfm")), f));
}

TEST_F(ImageIo, ExrRoundTripIsBitExact) {
  const Film f = float_film();
  write_image(f, file("a.exr"));
  EXPECT_TRUE(same_bits(read_image(file("a.exr")), f));
}

// PFM is stored bottom row first (the format's convention); the header says size and endianness.
TEST_F(ImageIo, PfmLayoutIsBottomUpLittleEndian) {
  Film f(2, 2);
  f.at(0, 1) = {1.f, 2.f, 3.f};  // bottom-left: the first pixel in the file
  const std::vector<unsigned char> bytes = encode_image(f, ".pfm");
  const std::string header = "PF\n2 2\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 4 * 3 * 4);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + header.size()), header);
  float first[3];
  std::memcpy(first, bytes.data() + header.size(), sizeof first);
  EXPECT_EQ(first[0], 1.f);
  EXPECT_EQ(first[1], 2.f);
  EXPECT_EQ(first[2], 3.f);
}

// PNG stores round(255 * srgb(v)): reading back gives the same encoded value within half a step.
TEST_F(ImageIo, PngRoundTripWithinOneEightBitStep) {
  Film f(17, 9);
  int i = 0;
  for (int y = 0; y < f.height(); ++y) {
    for (int x = 0; x < f.width(); ++x, ++i) {
      const float t = static_cast<float>(i) / static_cast<float>(f.width() * f.height() - 1);
      f.at(x, y) = {t, t * t, 1.f - t};
    }
  }
  f.at(0, 0) = {2.f, -1.f, 0.5f};  // out of range: clamped to 1 and 0
  write_image(f, file("a.png"));
  const Film g = read_image(file("a.png"));
  ASSERT_EQ(g.width(), f.width());
  ASSERT_EQ(g.height(), f.height());
  for (int y = 0; y < f.height(); ++y) {
    for (int x = 0; x < f.width(); ++x) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(linear_to_srgb(g.at(x, y)[k]), linear_to_srgb(f.at(x, y)[k]), 0.5f / 255.f + 1e-5f)
            << x << "," << y << " channel " << k;
      }
    }
  }
  EXPECT_FLOAT_EQ(g.at(0, 0).x, 1.f);
  EXPECT_EQ(g.at(0, 0).y, 0.f);
}

TEST_F(ImageIo, ExtensionIsCaseInsensitive) {
  const Film f = float_film();
  write_image(f, file("upper.PFM"));
  EXPECT_TRUE(same_bits(read_image(file("upper.PFM")), f));
  EXPECT_NO_THROW(check_image_extension("x.Png"));
  EXPECT_NO_THROW(check_image_extension("dir.d/x.EXR"));
  EXPECT_THROW(check_image_extension("x.jpg"), UsageError);
  EXPECT_THROW(check_image_extension("dir.png/x"), UsageError);  // a dot in the folder is no extension
  EXPECT_THROW(write_image(f, file("x.tiff")), UsageError);
  EXPECT_FALSE(fs::exists(file("x.tiff")));
}

TEST_F(ImageIo, UnreadableFilesThrowInputError) {
  for (const char* name : {"missing.pfm", "missing.exr", "missing.png"}) {
    EXPECT_THROW(read_image(file(name)), InputError) << name;
  }
  std::ofstream(file("garbage.pfm"), std::ios::binary) << "P6\n1 1\n255\n";
  EXPECT_THROW(read_image(file("garbage.pfm")), InputError);
  std::ofstream(file("short.pfm"), std::ios::binary) << "PF\n4 4\n-1.0\n0123";
  EXPECT_THROW(read_image(file("short.pfm")), InputError);
  std::ofstream(file("garbage.exr"), std::ios::binary) << "not an exr";
  EXPECT_THROW(read_image(file("garbage.exr")), InputError);
  std::ofstream(file("garbage.png"), std::ios::binary) << "not a png";
  EXPECT_THROW(read_image(file("garbage.png")), InputError);
}

TEST(Srgb, CurvesInvertEachOther) {
  for (int i = 0; i <= 1000; ++i) {
    const float v = static_cast<float>(i) / 1000.f;
    EXPECT_NEAR(srgb_to_linear(linear_to_srgb(v)), v, 1e-5f) << v;
    EXPECT_NEAR(linear_to_srgb(srgb_to_linear(v)), v, 1e-5f) << v;
  }
}

TEST(Srgb, KnownValuesAndClamping) {
  EXPECT_EQ(linear_to_srgb(0.f), 0.f);
  EXPECT_EQ(linear_to_srgb(1.f), 1.f);
  EXPECT_EQ(linear_to_srgb(7.f), 1.f);
  EXPECT_EQ(linear_to_srgb(-1.f), 0.f);
  EXPECT_EQ(linear_to_srgb(std::numeric_limits<float>::quiet_NaN()), 0.f);
  EXPECT_NEAR(linear_to_srgb(0.0031308f), 0.04045f, 1e-6f);  // where the two pieces meet
  EXPECT_NEAR(linear_to_srgb(0.18f), 0.46135613f, 1e-5f);    // middle grey
  EXPECT_NEAR(srgb_to_linear(0.5f), 0.21404114f, 1e-6f);
  // Monotone: the encoding never goes backwards.
  float prev = -1.f;
  for (int i = 0; i <= 4096; ++i) {
    const float e = linear_to_srgb(static_cast<float>(i) / 4096.f);
    EXPECT_GE(e, prev);
    prev = e;
  }
}

Film filled(int w, int h, Color c) {
  Film f(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) f.at(x, y) = c;
  }
  return f;
}

TEST(ImageRmse, IdenticalImagesGiveZero) {
  const Film f = float_film();
  EXPECT_EQ(image_rmse(f, f), 0.0);
  EXPECT_EQ(image_rmse(Film(0, 0), Film(0, 0)), 0.0);
}

TEST(ImageRmse, KnownDifferences) {
  // Black against white: every channel differs by 255 steps.
  EXPECT_NEAR(image_rmse(filled(4, 3, {0.f, 0.f, 0.f}), filled(4, 3, {1.f, 1.f, 1.f})), 255.0, 1e-9);
  // One white pixel of 16 in one channel: sqrt(255^2 / (3 * 16)).
  Film a = filled(4, 4, {0.f, 0.f, 0.f});
  Film b = a;
  b.at(2, 1).y = 1.f;
  EXPECT_NEAR(image_rmse(a, b), 255.0 / std::sqrt(48.0), 1e-9);
  // Measured on display values: linear 0.21404114 is sRGB 0.5, i.e. 127.5 steps from black.
  EXPECT_NEAR(image_rmse(filled(2, 2, {0.f, 0.f, 0.f}), filled(2, 2, Color(0.21404114f))), 127.5, 1e-3);
  // Values above 1 display as 1: no difference from white.
  EXPECT_EQ(image_rmse(filled(2, 2, Color(1.f)), filled(2, 2, Color(5.f))), 0.0);
}

TEST(ImageRmse, SizeMismatchThrowsInputError) {
  EXPECT_THROW(image_rmse(Film(4, 3), Film(3, 4)), InputError);
  EXPECT_THROW(image_rmse(Film(4, 3), Film(4, 2)), InputError);
}

// The difference image shows |a - b| of the display values times the scale, clamped to 1: a
// PNG of it holds exactly those values (black where the images agree).
TEST(DifferenceImage, ShowsTheScaledDisplayDifference) {
  Film a = filled(3, 2, {0.f, 0.f, 0.f});
  Film b = a;
  b.at(1, 0) = {0.21404114f, 0.f, 1.f};  // display values 0.5, 0 and 1
  const Film d = difference_image(a, b, 1.5f);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 3; ++x) {
      const Color want = x == 1 && y == 0 ? Color{0.75f, 0.f, 1.f} : Color{0.f, 0.f, 0.f};  // 1.5 clamps to 1
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(linear_to_srgb(d.at(x, y)[k]), want[k], 1e-5f) << x << y << k;
    }
  }
  EXPECT_EQ(image_rmse(difference_image(b, b, 8.f), a), 0.0);                            // agreeing images give black
  EXPECT_EQ(image_rmse(difference_image(a, b, 2.f), difference_image(b, a, 2.f)), 0.0);  // symmetric
  EXPECT_THROW(difference_image(Film(4, 3), Film(3, 4), 1.f), InputError);
}

}  // namespace
}  // namespace raylab
