// EnvironmentLight against references: its samples against its own density by a chi-square test
// over the sphere, irradiance against the analytic answer, and the lat-long convention of
// scene/environment.h read back from single bright texels.

#include "raylab/render/environment_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

#include "../sampling/chi_square.h"
#include "raylab/core/rng.h"

namespace raylab {
namespace {

constexpr double kPi = std::numbers::pi;

// A width x height image whose texel (i, j) is texel(i, j).
std::shared_ptr<const EnvironmentImage> make_image(int width, int height, const std::function<Color(int, int)>& texel) {
  auto image = std::make_shared<EnvironmentImage>();
  image->width = width;
  image->height = height;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) image->texels.push_back(texel(i, j));
  }
  return image;
}

Environment image_environment(std::shared_ptr<const EnvironmentImage> image, float rotate_degrees = 0.f,
                              float scale = 1.f) {
  Environment env;
  env.image = std::move(image);
  env.rotate_degrees = rotate_degrees;
  env.scale = scale;
  return env;
}

// 64 x 32 texels of 5.625 degrees: a gradient across the whole sphere and a sun of 3 x 2 texels
// about 50 degrees from the zenith, 800 times brighter.
std::shared_ptr<const EnvironmentImage> sun_and_gradient() {
  return make_image(64, 32, [](int i, int j) {
    if (i >= 40 && i <= 42 && j >= 8 && j <= 9) return Color{900.f, 800.f, 700.f};
    return Color{0.1f + 0.9f * i / 64.f, 0.2f + 0.5f * j / 32.f, 0.3f};
  });
}

// Upper hemisphere `sky`, lower hemisphere `ground`.
std::shared_ptr<const EnvironmentImage> two_tone(Color sky, Color ground) {
  return make_image(16, 8, [=](int, int j) { return j < 4 ? sky : ground; });
}

Environment constant_environment(Color c, float scale = 1.f) {
  Environment env;
  env.color = c;
  env.scale = scale;
  return env;
}

// World-space spherical angles of a direction: theta from +y, phi = atan2(z, x).
double theta_of(Vec3 d) { return std::atan2(std::hypot(d.x, d.z), d.y); }
double phi_of(Vec3 d) { return std::atan2(d.z, d.x); }
Vec3 direction(double theta, double phi) {
  return {static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
          static_cast<float>(std::sin(theta) * std::sin(phi))};
}

// Histogram of `samples` draws of `drawn` over a 16 x 32 grid of (theta, phi) cells against the
// counts the pdf of `claimed` predicts, integrated over each cell with 8 x 8 midpoints in
// (theta, phi) (dOmega = sin(theta) dtheta dphi). The cells' edges fall on texel edges of a
// 64 x 32 image turned by a multiple of 5.625 degrees, where the pdf is constant in each
// sub-cell and the midpoint rule is exact. Also returns the integral of the pdf over the sphere.
struct SphereHistogram {
  test::ChiSquare chi;
  double pdf_integral = 0.0;
};

SphereHistogram sphere_histogram(const EnvironmentLight& drawn, const EnvironmentLight& claimed, int samples,
                                 std::uint64_t seed) {
  constexpr int kTheta = 16, kPhi = 32, kSub = 8;
  std::vector<double> observed(kTheta * kPhi, 0.0), expected(kTheta * kPhi, 0.0);
  Pcg32 rng(seed);
  int count = 0;
  for (int s = 0; s < samples; ++s) {
    const std::optional<EnvironmentLight::Sample> x = drawn.sample({rng.next_float(), rng.next_float()});
    if (!x) continue;
    ++count;
    const int t = std::min(static_cast<int>(theta_of(x->wi) / kPi * kTheta), kTheta - 1);
    const int p = std::min(static_cast<int>((phi_of(x->wi) + kPi) / (2.0 * kPi) * kPhi), kPhi - 1);
    observed[static_cast<std::size_t>(t * kPhi + p)] += 1.0;
  }
  EXPECT_GE(count, samples - 10) << "too many empty samples";
  SphereHistogram result;
  const double dt = kPi / (kTheta * kSub), dp = 2.0 * kPi / (kPhi * kSub);
  for (int t = 0; t < kTheta; ++t) {
    for (int p = 0; p < kPhi; ++p) {
      double cell = 0.0;
      for (int a = 0; a < kSub; ++a) {
        for (int b = 0; b < kSub; ++b) {
          const double theta = (t * kSub + a + 0.5) * dt, phi = -kPi + (p * kSub + b + 0.5) * dp;
          cell += claimed.pdf(direction(theta, phi)) * std::sin(theta) * dt * dp;
        }
      }
      expected[static_cast<std::size_t>(t * kPhi + p)] = cell * count;
      result.pdf_integral += cell;
    }
  }
  result.chi = test::chi_square_test(observed, expected);
  return result;
}

SphereHistogram sphere_histogram(const EnvironmentLight& light, int samples, std::uint64_t seed) {
  return sphere_histogram(light, light, samples, seed);
}

TEST(EnvironmentLight, ConstantIsUniformOverTheSphere) {
  const EnvironmentLight light(constant_environment({0.5f, 1.f, 2.f}, 3.f));
  EXPECT_FALSE(light.has_image());
  EXPECT_FLOAT_EQ(light.pdf({0.3f, -0.2f, 0.9f}), static_cast<float>(1.0 / (4.0 * kPi)));
  EXPECT_EQ(light.radiance({0.f, -1.f, 0.f}), (Color{1.5f, 3.f, 6.f}));
  const SphereHistogram h = sphere_histogram(light, 200000, 41);
  EXPECT_TRUE(h.chi.pass()) << h.chi.describe();
  EXPECT_NEAR(h.pdf_integral, 1.0, 1e-4);
}

TEST(EnvironmentLight, SamplesFollowThePdfOfASunAndAGradient) {
  const EnvironmentLight light(image_environment(sun_and_gradient()));
  const SphereHistogram h = sphere_histogram(light, 1000000, 43);
  EXPECT_TRUE(h.chi.pass()) << h.chi.describe();
  EXPECT_NEAR(h.pdf_integral, 1.0, 1e-4);
}

TEST(EnvironmentLight, SamplesFollowThePdfWhenRotated) {
  // 33.75 degrees = 6 texels: not a quarter turn, so the rotation goes through sin and cos.
  const EnvironmentLight light(image_environment(sun_and_gradient(), 33.75f));
  const SphereHistogram h = sphere_histogram(light, 1000000, 47);
  EXPECT_TRUE(h.chi.pass()) << h.chi.describe();
  EXPECT_NEAR(h.pdf_integral, 1.0, 1e-4);
}

TEST(EnvironmentLight, ChiSquareRejectsAPdfThatIsNotTheSamplers) {
  // The histogram test must be able to fail: samples drawn from the sun image, densities from
  // the same image turned by one texel.
  const EnvironmentLight drawn(image_environment(sun_and_gradient()));
  const EnvironmentLight claimed(image_environment(sun_and_gradient(), 5.625f));
  EXPECT_FALSE(sphere_histogram(drawn, claimed, 100000, 53).chi.pass());
}

TEST(EnvironmentLight, DensityIsProportionalToLuminance) {
  // Texels weighted by luminance times solid angle make the solid-angle density follow the
  // luminance, at the poles as at the horizon: at a texel's centre, pdf = luminance / (the
  // integral of luminance over the sphere), to the 0.04% by which a texel's solid angle differs
  // from 2 pi^2 sin(theta) du dv there.
  const std::shared_ptr<const EnvironmentImage> image = sun_and_gradient();
  const EnvironmentLight light(image_environment(image, 0.f, 3.f));
  double integral = 0.0;
  for (int j = 0; j < 32; ++j) {
    const double solid_angle = 2.0 * kPi / 64 * (std::cos(kPi * j / 32) - std::cos(kPi * (j + 1) / 32));
    for (int i = 0; i < 64; ++i)
      integral += luminance(image->texels[static_cast<std::size_t>(j * 64 + i)]) * solid_angle;
  }
  for (int j = 0; j < 32; ++j) {
    for (int i = 0; i < 64; ++i) {
      const Vec3 d = direction(kPi * (j + 0.5) / 32, 2.0 * kPi * ((i + 0.5) / 64 - 0.5));
      const double want = luminance(image->texels[static_cast<std::size_t>(j * 64 + i)]) / integral;
      ASSERT_NEAR(light.pdf(d), want, 1e-3 * want) << "texel " << i << ", " << j;
    }
  }
}

TEST(EnvironmentLight, SampleCarriesRadianceAndPdfOfItsDirection) {
  for (float rotate : {0.f, 90.f, 33.75f, -200.f}) {
    SCOPED_TRACE("rotate " + std::to_string(rotate));
    const EnvironmentLight light(image_environment(sun_and_gradient(), rotate, 2.5f));
    Pcg32 rng(59);
    for (int s = 0; s < 20000; ++s) {
      const auto x = light.sample({rng.next_float(), rng.next_float()});
      if (!x) continue;
      ASSERT_NEAR(length(x->wi), 1.f, 1e-6f);
      ASSERT_GT(x->pdf, 0.f);
      ASSERT_TRUE(std::isfinite(x->pdf));
      ASSERT_EQ(x->pdf, light.pdf(x->wi));
      ASSERT_EQ(x->radiance, light.radiance(x->wi));
    }
  }
}

// The Monte Carlo estimate of the irradiance at a surface facing +y, sum L cos / pdf / N, and
// its standard error; per channel.
struct Estimate {
  Color mean;
  Color sigma;
};

Estimate upward_irradiance(const EnvironmentLight& light, int samples, std::uint64_t seed) {
  Pcg32 rng(seed);
  double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
  for (int s = 0; s < samples; ++s) {
    const auto x = light.sample({rng.next_float(), rng.next_float()});
    if (!x || x->wi.y <= 0.f) continue;
    for (int c = 0; c < 3; ++c) {
      const double f = static_cast<double>(x->radiance[c]) * x->wi.y / x->pdf;
      sum[c] += f;
      sum2[c] += f * f;
    }
  }
  Estimate e;
  for (int c = 0; c < 3; ++c) {
    const double mean = sum[c] / samples;
    const double variance = std::max(0.0, sum2[c] / samples - mean * mean);
    e.mean[c] = static_cast<float>(mean);
    e.sigma[c] = static_cast<float>(std::sqrt(variance / samples));
  }
  return e;
}

void expect_within_3_sigma(const Estimate& e, Color want) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(e.sigma[c], 0.f) << "channel " << c;
    EXPECT_NEAR(e.mean[c], want[c], 3.f * e.sigma[c] + 1e-6f * want[c]) << "channel " << c;
  }
}

TEST(EnvironmentLight, IrradianceOfAConstantEnvironmentIsPiL) {
  const Color l{0.25f, 1.f, 4.f};
  const EnvironmentLight light(constant_environment(l));
  expect_within_3_sigma(upward_irradiance(light, 200000, 61), l * static_cast<float>(kPi));
}

TEST(EnvironmentLight, IrradianceOfATwoToneImageIsPiTimesTheSky) {
  // A ground brighter than the sky draws most samples below the horizon, where they add
  // nothing: the estimate must still come out as pi times the sky alone.
  const Color sky{1.f, 0.5f, 0.25f};
  for (float rotate : {0.f, 71.f}) {
    SCOPED_TRACE("rotate " + std::to_string(rotate));
    const EnvironmentLight light(image_environment(two_tone(sky, {3.f, 3.f, 3.f}), rotate, 2.f));
    expect_within_3_sigma(upward_irradiance(light, 200000, 67), sky * static_cast<float>(2.0 * kPi));
  }
}

TEST(EnvironmentLight, PowerIsPiR2TimesTheRadianceIntegral) {
  const EnvironmentLight constant(constant_environment({1.f, 2.f, 3.f}, 2.f));
  const Color want = Color{1.f, 2.f, 3.f} * static_cast<float>(2.0 * 4.0 * kPi * kPi * 9.0);
  const Color got = constant.power_estimate(3.f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5f * want[c]);
  // Half the sphere at each radiance: 2 pi L1 + 2 pi L2.
  const EnvironmentLight image(image_environment(two_tone({1.f, 1.f, 1.f}, {3.f, 0.f, 1.f})));
  const Color want_image = Color{4.f, 1.f, 2.f} * static_cast<float>(2.0 * kPi * kPi * 4.0);
  const Color got_image = image.power_estimate(2.f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got_image[c], want_image[c], 1e-5f * want_image[c]);
}

// An 8 x 4 image, black but for texel (i, j).
EnvironmentLight single_texel(int i, int j, float rotate_degrees = 0.f) {
  return EnvironmentLight(image_environment(make_image(8, 4,
                                                       [=](int x, int y) {
                                                         return x == i && y == j ? Color{5.f, 6.f, 7.f} : Color{0.f};
                                                       }),
                                            rotate_degrees));
}

// Expects light `light` to be bright in direction `bright` and black in each of `dark`.
void expect_bright_only(const EnvironmentLight& light, Vec3 bright, std::initializer_list<Vec3> dark) {
  EXPECT_EQ(light.radiance(bright), (Color{5.f, 6.f, 7.f}));
  EXPECT_GT(light.pdf(bright), 0.f);
  for (Vec3 d : dark) {
    EXPECT_EQ(light.radiance(d), Color{0.f}) << d.x << ", " << d.y << ", " << d.z;
    EXPECT_EQ(light.pdf(d), 0.f);
  }
}

TEST(EnvironmentLight, LatLongConventionOfTheHeader) {
  // Texel (4, 1) spans u in [0.5, 0.625), v in [0.25, 0.5): just above the horizon, from +x
  // toward +z. Its neighbours: toward -z (column 3), below the horizon (row 2).
  constexpr float e = 0.05f;
  expect_bright_only(single_texel(4, 1), {1.f, e, e}, {{1.f, e, -e}, {1.f, -e, e}, {-1.f, e, e}});
  // u = 0.75 along +z: column 6 starts there and turns on toward -x.
  expect_bright_only(single_texel(6, 1), {-e, e, 1.f}, {{e, e, 1.f}, {-e, e, -1.f}});
  // u = 0.25 along -z: column 2 starts there and turns on toward +x.
  expect_bright_only(single_texel(2, 1), {e, e, -1.f}, {{-e, e, -1.f}, {e, e, 1.f}});
  // The side edges along -x: column 0 from -x toward -z, column 7 from -x toward +z.
  expect_bright_only(single_texel(0, 1), {-1.f, e, -e}, {{-1.f, e, e}});
  expect_bright_only(single_texel(7, 1), {-1.f, e, e}, {{-1.f, e, -e}});
  // Row 0 is the top: the zenith; row 3 the nadir.
  expect_bright_only(single_texel(4, 0), {0.1f, 1.f, 0.02f}, {{0.1f, -1.f, 0.02f}});
  expect_bright_only(single_texel(4, 3), {0.1f, -1.f, 0.02f}, {{0.1f, 1.f, 0.02f}});
}

TEST(EnvironmentLight, RotationTurnsCounterClockwiseAboutUp) {
  // With 90 degrees what lay along +x lies along -z, and what lay along +z lies along +x.
  expect_bright_only(single_texel(4, 1, 90.f), {0.05f, 0.05f, -1.f}, {{1.f, 0.05f, 0.05f}});
  expect_bright_only(single_texel(6, 1, 90.f), {1.f, 0.05f, 0.05f}, {{-0.05f, 0.05f, 1.f}});
  // A whole turn, and a negative one, are the same environment.
  expect_bright_only(single_texel(4, 1, 360.f), {1.f, 0.05f, 0.05f}, {});
  expect_bright_only(single_texel(4, 1, -270.f), {0.05f, 0.05f, -1.f}, {});
}

TEST(EnvironmentLight, ScaleMultipliesTheImage) {
  const EnvironmentLight light(image_environment(two_tone({1.f, 2.f, 3.f}, {0.f, 0.f, 0.f}), 0.f, 4.f));
  EXPECT_EQ(light.radiance({0.f, 1.f, 0.f}), (Color{4.f, 8.f, 12.f}));
}

TEST(EnvironmentLight, PolesAndBlackTexelsHaveDensityZero) {
  const EnvironmentLight light(image_environment(sun_and_gradient()));
  EXPECT_EQ(light.pdf({0.f, 1.f, 0.f}), 0.f);
  EXPECT_EQ(light.pdf({0.f, -3.f, 0.f}), 0.f);
  EXPECT_EQ(light.pdf({0.f, 0.f, 0.f}), 0.f);
  EXPECT_EQ(light.pdf({std::numeric_limits<float>::quiet_NaN(), 0.f, 1.f}), 0.f);
  EXPECT_TRUE(is_finite(light.radiance({0.f, 0.f, 0.f})));
  // u.y = 0 lands on the zenith itself: no sample rather than an infinite density.
  const auto pole = light.sample({0.5f, 0.f});
  if (pole) {
    EXPECT_TRUE(std::isfinite(pole->pdf));
  }
  // A black upper half is never drawn.
  const EnvironmentLight ground(image_environment(two_tone({0.f, 0.f, 0.f}, {1.f, 1.f, 1.f})));
  EXPECT_EQ(ground.pdf({0.3f, 0.5f, 0.1f}), 0.f);
  Pcg32 rng(71);
  for (int s = 0; s < 10000; ++s) {
    const auto x = ground.sample({rng.next_float(), rng.next_float()});
    if (x) {
      ASSERT_LE(x->wi.y, 0.f);
    }
  }
}

TEST(EnvironmentLight, RejectsDataTheLoaderWouldRefuse) {
  EXPECT_THROW(EnvironmentLight(constant_environment({-1.f, 0.f, 0.f})), std::invalid_argument);
  EXPECT_THROW(EnvironmentLight(constant_environment({1.f, 1.f, 1.f}, -1.f)), std::invalid_argument);
  Environment turned = constant_environment({1.f, 1.f, 1.f});
  turned.rotate_degrees = std::numeric_limits<float>::infinity();
  EXPECT_THROW(EnvironmentLight{turned}, std::invalid_argument);
  auto short_image = std::make_shared<EnvironmentImage>();
  short_image->width = 4;
  short_image->height = 2;
  short_image->texels.resize(7);
  EXPECT_THROW(EnvironmentLight(image_environment(short_image)), std::invalid_argument);
  EXPECT_THROW(EnvironmentLight(image_environment(make_image(
                   2, 2, [](int i, int) { return i ? Color{std::numeric_limits<float>::quiet_NaN()} : Color{1.f}; }))),
               std::invalid_argument);
}

TEST(Environment, PresentWhenItCanSendLight) {
  EXPECT_FALSE(Environment{}.present());
  EXPECT_TRUE(constant_environment({0.f, 0.f, 0.1f}).present());
  EXPECT_FALSE(constant_environment({1.f, 1.f, 1.f}, 0.f).present());
  EXPECT_TRUE(image_environment(two_tone(Color{0.f}, Color{0.f})).present());
}

}  // namespace
}  // namespace raylab
