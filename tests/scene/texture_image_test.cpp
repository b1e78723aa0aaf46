// TextureImage: bilinear lookups against values computed by hand, repeat addressing, the v flip,
// and diffuse_color multiplying the material colour by the texture.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "raylab/scene/material.h"
#include "raylab/scene/texture_image.h"

namespace raylab {
namespace {

const Color kRed{1.f, 0.f, 0.f};
const Color kGreen{0.f, 1.f, 0.f};
const Color kBlue{0.f, 0.f, 1.f};
const Color kWhite{1.f, 1.f, 1.f};

// 2 x 2, top row red | green, bottom row blue | white (rows as the file stores them).
TextureImage quad_image() { return TextureImage(2, 2, {kRed, kGreen, kBlue, kWhite}); }

void expect_color(Color got, Color want, float tolerance = 0.f) {
  EXPECT_NEAR(got.x, want.x, tolerance);
  EXPECT_NEAR(got.y, want.y, tolerance);
  EXPECT_NEAR(got.z, want.z, tolerance);
}

TEST(TextureImage, TexelCentresReturnTheTexelExactly) {
  const TextureImage image = quad_image();
  // v counts up from the bottom of the image: the top row is at v = 0.75.
  expect_color(image.sample(0.25f, 0.75f), kRed);
  expect_color(image.sample(0.75f, 0.75f), kGreen);
  expect_color(image.sample(0.25f, 0.25f), kBlue);
  expect_color(image.sample(0.75f, 0.25f), kWhite);
}

TEST(TextureImage, BilinearBetweenTexelCentres) {
  const TextureImage image = quad_image();
  // Halfway between red and green.
  expect_color(image.sample(0.5f, 0.75f), {0.5f, 0.5f, 0.f});
  // Halfway between red (top) and blue (bottom).
  expect_color(image.sample(0.25f, 0.5f), {0.5f, 0.f, 0.5f});
  // The centre: a quarter of each.
  expect_color(image.sample(0.5f, 0.5f), {0.5f, 0.5f, 0.5f});
  // A quarter of the way from red to green: x = 0.375 * 2 - 0.5 = 0.25.
  expect_color(image.sample(0.375f, 0.75f), {0.75f, 0.25f, 0.f});
}

TEST(TextureImage, RampAgainstHandComputedWeights) {
  // 4 x 1 grey ramp 0, 1, 2, 3. At u = 0.3: x = 0.3 * 4 - 0.5 = 0.7, so 0 * 0.3 + 1 * 0.7.
  const TextureImage ramp(4, 1, {Color(0.f), Color(1.f), Color(2.f), Color(3.f)});
  EXPECT_NEAR(ramp.sample(0.3f, 0.5f).x, 0.7f, 1e-6f);
  // u = 0.8: x = 2.7, so 2 * 0.3 + 3 * 0.7 = 2.7.
  EXPECT_NEAR(ramp.sample(0.8f, 0.5f).x, 2.7f, 1e-6f);
  // Past the last texel centre the lookup wraps to the first: u = 0.95 gives x = 3.3,
  // 3 * 0.7 + 0 * 0.3.
  EXPECT_NEAR(ramp.sample(0.95f, 0.5f).x, 2.1f, 1e-5f);
  // And before the first centre it blends with the last: u = 0.05, x = -0.3: 3 * 0.3 + 0 * 0.7.
  EXPECT_NEAR(ramp.sample(0.05f, 0.5f).x, 0.9f, 1e-5f);
  // A single row: v does not matter.
  EXPECT_NEAR(ramp.sample(0.3f, 0.1f).x, 0.7f, 1e-6f);
}

TEST(TextureImage, RepeatAddressing) {
  const TextureImage image = quad_image();
  expect_color(image.sample(1.25f, 0.75f), kRed);
  expect_color(image.sample(-0.75f, 0.75f), kRed);
  expect_color(image.sample(0.25f, 2.25f), kBlue);
  expect_color(image.sample(0.25f, -0.25f), kRed);  // -0.25 wraps to 0.75
  // u = 0 is on the seam between the right column and the left one.
  expect_color(image.sample(0.f, 0.75f), {0.5f, 0.5f, 0.f});
  expect_color(image.sample(1.f, 0.75f), {0.5f, 0.5f, 0.f});
  // Large coordinates keep their fraction.
  expect_color(image.sample(1000.25f, 0.75f), kRed);
}

TEST(TextureImage, NonFiniteCoordinatesReadTheTopLeftTexel) {
  const TextureImage image = quad_image();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  expect_color(image.sample(nan, 0.25f), kRed);
  expect_color(image.sample(0.75f, inf), kRed);
}

TEST(TextureImage, SizeMustMatchTexels) {
  EXPECT_THROW(TextureImage(2, 2, {kRed, kGreen, kBlue}), std::invalid_argument);
  EXPECT_THROW(TextureImage(0, 0, {}), std::invalid_argument);
  EXPECT_THROW(TextureImage(-1, -1, {kRed}), std::invalid_argument);
  const TextureImage image = quad_image();
  EXPECT_EQ(image.width(), 2);
  EXPECT_EQ(image.height(), 2);
  expect_color(image.texel(1, 0), kGreen);
  expect_color(image.texel(0, 1), kBlue);
}

TEST(TextureImage, DiffuseColorMultipliesTheMaterialColour) {
  Material m;
  m.color = {0.5f, 0.25f, 2.f};
  m.texture = Texture::from_image(std::make_shared<const TextureImage>(quad_image()));
  expect_color(diffuse_color(m, 0.75f, 0.25f), {0.5f, 0.25f, 2.f});  // white texel
  expect_color(diffuse_color(m, 0.25f, 0.75f), {0.5f, 0.f, 0.f});    // red texel
  expect_color(diffuse_color(m, 0.5f, 0.75f), {0.25f, 0.125f, 0.f});
  // An image texture without an image leaves the colour alone.
  m.texture.image.reset();
  expect_color(diffuse_color(m, 0.25f, 0.75f), m.color);
}

TEST(TextureImage, CheckerStillWorksThroughTheConstructor) {
  Material m;
  m.color = kWhite;
  m.texture = {Texture::Kind::kChecker, kBlue, 0.5f};
  expect_color(diffuse_color(m, 0.25f, 0.25f), kWhite);
  expect_color(diffuse_color(m, 0.75f, 0.25f), kBlue);
}

}  // namespace
}  // namespace raylab
