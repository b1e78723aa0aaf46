// Reconstruction filters: each integrates to 1 over the plane (numeric 2D integration over its
// support), vanishes at and beyond its radius, has the sign its definition gives, and the
// factory accepts exactly the documented names and radii.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>

#include "../test_util.h"
#include "raylab/core/error.h"
#include "raylab/sampling/filter.h"

namespace raylab {
namespace {

constexpr std::string_view kNames[] = {"box", "tent", "gaussian", "mitchell"};

/// Midpoint rule over [-r, r]^2 on a steps x steps grid. The cells' edges fall on the support's
/// edges, where the box jumps, so the rule is exact for the box and O(h^2) for the others.
double integral_2d(const Filter& f, int steps) {
  const double r = f.radius();
  const double h = 2.0 * r / steps;
  double sum = 0.0;
  for (int j = 0; j < steps; ++j) {
    const auto y = static_cast<float>(-r + (j + 0.5) * h);
    for (int i = 0; i < steps; ++i) sum += f.evaluate(static_cast<float>(-r + (i + 0.5) * h), y);
  }
  return sum * h * h;
}

/// The smallest value of the 1D profile on a fine grid over its support.
float min_1d(const Filter& f) {
  float lowest = std::numeric_limits<float>::max();
  for (int i = -1000; i <= 1000; ++i) lowest = std::min(lowest, f.evaluate_1d(f.radius() * i / 1000.f));
  return lowest;
}

TEST(Filter, NamesAndDefaultRadii) {
  const auto names = filter_names();
  ASSERT_EQ(names.size(), std::size(kNames));
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(names[i], kNames[i]);
  EXPECT_EQ(default_filter_radius("box"), 0.5f);
  EXPECT_EQ(default_filter_radius("tent"), 1.f);
  EXPECT_EQ(default_filter_radius("gaussian"), 1.5f);
  EXPECT_EQ(default_filter_radius("mitchell"), 2.f);
  EXPECT_EQ(make_filter("box").kind(), FilterKind::kBox);
  EXPECT_EQ(make_filter("tent").kind(), FilterKind::kTent);
  EXPECT_EQ(make_filter("gaussian").kind(), FilterKind::kGaussian);
  EXPECT_EQ(make_filter("mitchell").kind(), FilterKind::kMitchell);
  for (std::string_view name : kNames) {
    EXPECT_EQ(make_filter(name).radius(), default_filter_radius(name)) << name;
    EXPECT_EQ(make_filter(name, 0.f).radius(), default_filter_radius(name)) << name;
    EXPECT_EQ(make_filter(name, 1.25f).radius(), 1.25f) << name;
  }
}

TEST(Filter, IntegratesToOneAtDefaultAndOtherRadii) {
  for (std::string_view name : kNames) {
    for (float radius : {0.f, 0.75f, 3.f}) {
      const Filter f = make_filter(name, radius);
      EXPECT_NEAR(integral_2d(f, 600), 1.0, 1e-3) << name << " radius " << f.radius();
    }
  }
}

TEST(Filter, ZeroAtAndBeyondTheRadius) {
  for (std::string_view name : kNames) {
    for (float radius : {0.f, 0.75f, 2.5f}) {
      const Filter f = make_filter(name, radius);
      const float r = f.radius();
      for (float x : {r, -r, std::nextafter(r, 100.f), 1.5f * r, -3.f * r, 100.f}) {
        EXPECT_EQ(f.evaluate_1d(x), 0.f) << name << " at " << x;
        EXPECT_EQ(f.evaluate(x, 0.f), 0.f) << name;
        EXPECT_EQ(f.evaluate(0.f, x), 0.f) << name;
        EXPECT_EQ(f.evaluate(x, x), 0.f) << name;
      }
      EXPECT_EQ(f.evaluate_1d(std::numeric_limits<float>::quiet_NaN()), 0.f) << name;
      EXPECT_EQ(f.evaluate_1d(std::numeric_limits<float>::infinity()), 0.f) << name;
      // Inside, the profile is not zero at the centre, and it is symmetric.
      EXPECT_GT(f.evaluate_1d(0.f), 0.f) << name;
      for (float t : {0.1f, 0.4f, 0.7f, 0.95f}) EXPECT_EQ(f.evaluate_1d(t * r), f.evaluate_1d(-t * r)) << name;
    }
  }
}

TEST(Filter, ProfilesAreContinuousAtTheRadiusExceptTheBox) {
  // tent, gaussian and mitchell fall to zero at the radius; the box jumps.
  for (std::string_view name : {"tent", "gaussian", "mitchell"}) {
    const Filter f = make_filter(name);
    EXPECT_NEAR(f.evaluate_1d(0.999f * f.radius()), 0.f, 1e-3f) << name;
  }
  const Filter box = make_filter("box", 2.f);
  EXPECT_FLOAT_EQ(box.evaluate_1d(0.999f * 2.f), 0.25f);
}

TEST(Filter, KnownValues) {
  // box: 1 / (2r) per axis; tent: (r - |x|) / r^2; mitchell at 0: (6 - 2B) / 6 * (2 / r).
  EXPECT_FLOAT_EQ(make_filter("box").evaluate(0.1f, -0.3f), 1.f);
  EXPECT_FLOAT_EQ(make_filter("box", 1.f).evaluate(0.f, 0.f), 0.25f);
  EXPECT_FLOAT_EQ(make_filter("tent").evaluate_1d(0.25f), 0.75f);
  EXPECT_FLOAT_EQ(make_filter("tent", 2.f).evaluate_1d(0.5f), 1.5f / 4.f);
  EXPECT_FLOAT_EQ(make_filter("mitchell").evaluate_1d(0.f), 16.f / 18.f);
  EXPECT_FLOAT_EQ(make_filter("mitchell", 4.f).evaluate_1d(0.f), 8.f / 18.f);
  // gaussian: the shifted bell over its closed-form integral, at x = sigma = r / 3.
  const double r = 1.5;
  const double sigma = r / 3;
  const double area = sigma * std::sqrt(2 * std::numbers::pi) * std::erf(3 / std::sqrt(2.0)) - 2 * r * std::exp(-4.5);
  EXPECT_NEAR(make_filter("gaussian").evaluate_1d(0.5f), (std::exp(-0.5) - std::exp(-4.5)) / area, 1e-6);
}

TEST(Filter, SignsBoxTentGaussianNonNegativeMitchellHasANegativeLobe) {
  for (std::string_view name : {"box", "tent", "gaussian"}) {
    EXPECT_GE(min_1d(make_filter(name)), 0.f) << name;
    EXPECT_GE(min_1d(make_filter(name, 3.f)), 0.f) << name;
  }
  const Filter mitchell = make_filter("mitchell");
  EXPECT_LT(min_1d(mitchell), 0.f);
  // The lobe lies between 1 and 2 units of the cubic, i.e. at 0.75 of the radius.
  EXPECT_LT(mitchell.evaluate_1d(0.75f * mitchell.radius()), 0.f);
  EXPECT_LT(mitchell.evaluate(0.75f * mitchell.radius(), 0.f), 0.f);
}

TEST(Filter, MakeFilterRejectsUnknownNamesAndBadRadii) {
  for (auto call : {+[] { (void)make_filter("lanczos"); }, +[] { (void)default_filter_radius("lanczos"); }}) {
    const std::string message = test::thrown_message<UsageError>(call);
    test::expect_contains_all(message, {"lanczos"});
    test::expect_contains_all(message, kNames);
  }
  for (float radius :
       {-0.5f, -1e-6f, 8.01f, 100.f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    EXPECT_THROW((void)make_filter("tent", radius), UsageError) << radius;
  }
  EXPECT_NO_THROW((void)make_filter("tent", 8.f));
  EXPECT_THROW(Filter(FilterKind::kBox, 0.f), UsageError);
  EXPECT_THROW(Filter(FilterKind::kBox, -1.f), UsageError);
}

}  // namespace
}  // namespace raylab
