// load_environment: a colour from "R,G,B", an image through read_image, and the messages of
// everything else.

#include "raylab/io/environment_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "../test_util.h"
#include "io_test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/image_io.h"

namespace raylab {
namespace {

using test::expect_contains_all;
using test::thrown_message;

TEST(LoadEnvironment, ReadsAConstantColour) {
  const Environment env = load_environment("0.5,0.5,0.5", 30.f);
  EXPECT_EQ(env.color, Color{0.5f});
  EXPECT_EQ(env.image, nullptr);
  EXPECT_EQ(env.rotate_degrees, 30.f);
  EXPECT_EQ(env.scale, 1.f);
  EXPECT_TRUE(env.present());
  EXPECT_EQ(load_environment(" 1 , 2,3 ", 0.f).color, (Color{1.f, 2.f, 3.f}));
  EXPECT_FALSE(load_environment("0,0,0", 0.f).present());
}

TEST(LoadEnvironment, RefusesANegativeColour) {
  const std::string m = thrown_message<UsageError>([] { load_environment("1,-0.5,1", 0.f); });
  expect_contains_all(m, {"--env", "'1,-0.5,1'", ">= 0"});
}

TEST(LoadEnvironment, RefusesWhatIsNeitherAColourNorAFile) {
  for (const char* spec : {"1,2", "1,2,3,4", "nan,1,1", "red", "", "no/such/sky.exr"}) {
    SCOPED_TRACE(spec);
    const std::string m = thrown_message<UsageError>([=] { load_environment(spec, 0.f); });
    expect_contains_all(m,
                        {"--env: '" + std::string(spec) + "'", "neither R,G,B", "readable image file", "no such file"});
  }
  // The option's name comes from the caller.
  expect_contains_all(thrown_message<UsageError>([] { load_environment("1,2", 0.f, "\"environment\""); }),
                      {"\"environment\": '1,2'"});
}

TEST(LoadEnvironment, RefusesANonFiniteRotation) {
  const std::string m =
      thrown_message<UsageError>([] { load_environment("1,1,1", std::numeric_limits<float>::quiet_NaN()); });
  expect_contains_all(m, {"--env", "rotation", "finite"});
}

TEST(LoadEnvironment, ReadsAnExrItWrote) {
  const test::TempDir dir("environment");
  Film film(4, 2);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; ++x) film.at(x, y) = {x * 10.f + y, 1000.f, 0.125f};
  }
  const std::string path = dir.file("sky.exr");
  write_image(film, path);
  const Environment env = load_environment(path, -45.f);
  ASSERT_NE(env.image, nullptr);
  EXPECT_EQ(env.image->width, 4);
  EXPECT_EQ(env.image->height, 2);
  EXPECT_EQ(env.image->path, path);
  EXPECT_TRUE(std::ranges::equal(env.image->texels, film.pixels()));  // row 0 stays the top row
  EXPECT_EQ(env.rotate_degrees, -45.f);
  EXPECT_TRUE(env.present());
}

TEST(LoadEnvironment, ReadsAPfm) {
  const test::TempDir dir("environment");
  Film film(3, 1);
  film.at(2, 0) = {7.f, 8.f, 9.f};
  const std::string path = dir.file("sky.pfm");
  write_image(film, path);
  EXPECT_TRUE(std::ranges::equal(load_environment(path, 0.f).image->texels, film.pixels()));
}

TEST(LoadEnvironment, RefusesNegativeAndNonFinitePixelsNamingTheFile) {
  const test::TempDir dir("environment");
  for (float bad : {-1.f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    SCOPED_TRACE(bad);
    Film film(3, 2);
    film.at(2, 1) = {0.5f, bad, 0.5f};
    const std::string path = dir.file("bad.exr");
    write_image(film, path);
    const std::string m = thrown_message<InputError>([&] { load_environment(path, 0.f); });
    expect_contains_all(m, {path + ": --env: pixel (2, 1)", "finite and >= 0"});
  }
}

TEST(LoadEnvironment, NamesTheFileItCannotDecode) {
  const test::TempDir dir("environment");
  const std::string path = test::write_text(dir.path() / "sky.exr", "not an exr");
  expect_contains_all(thrown_message<InputError>([&] { load_environment(path, 0.f); }), {path + ": --env: ", "EXR"});
}

TEST(LoadEnvironment, RefusesAFolderAndARadianceHdr) {
  const test::TempDir dir("environment");
  expect_contains_all(thrown_message<UsageError>([&] { load_environment(dir.path().string(), 0.f); }),
                      {"--env", "neither R,G,B", "it is a folder"});
  const std::string hdr = test::write_text(dir.path() / "sky.hdr", "#?RADIANCE\n");
  expect_contains_all(thrown_message<InputError>([&] { load_environment(hdr, 0.f); }),
                      {hdr + ": --env: ", ".hdr", ".exr"});
}

}  // namespace
}  // namespace raylab
