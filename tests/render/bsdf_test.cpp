// The scattering models against references: chi-square tests of each model's sampling against
// its own density (as pbrt-v4 and Mitsuba 3 test theirs), sample weights against eval and pdf,
// reciprocity, Fresnel against published figures, energy conservation, and the exact
// directions of delta lobes.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "raylab/core/rng.h"
#include "raylab/render/bsdf.h"
#include "raylab/render/optics.h"
#include "sphere_chi2.h"

namespace raylab {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr float kDeg = std::numbers::pi_v<float> / 180.f;

// A direction at polar angle `theta_deg` from +z (negative z beyond 90 degrees), at an azimuth
// that lines up with no axis or cell boundary.
Vec3 direction(float theta_deg, float phi = 0.7f) {
  const float t = theta_deg * kDeg;
  return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

Sample2 next2(Pcg32& rng) {
  const float x = rng.next_float();
  return {x, rng.next_float()};
}

// A conductor whose Fresnel reflectance is 1 to float precision (a perfect mirror): n = 0 and
// a large extinction coefficient.
const ConductorIor kPerfectMirror{{0.f, 0.f, 0.f}, {1e4f, 1e4f, 1e4f}};

ConductorIor gold() { return *metal_ior("gold"); }

// --- Sampling against density ---------------------------------------------------------------

using test::Chi2Result;
using test::gamma_q;
using test::integrate_on_sphere;
using test::pearson;
using test::spherical;

const test::SphereGrid kGrid{32, 64};
constexpr int kChi2Samples = 500'000;

// The sampled directions of `bsdf` at `wo`; delta samples and failures are what pdf() does not
// describe.
std::vector<double> observed_counts(const Bsdf& bsdf, Vec3 wo, Pcg32& rng) {
  return test::observed_counts(kGrid, kChi2Samples, [&]() -> std::optional<Vec3> {
    const float u_lobe = rng.next_float();
    const auto s = bsdf.sample(wo, u_lobe, next2(rng));
    if (!s || s->delta) return std::nullopt;
    return s->wi;
  });
}

std::vector<double> expected_counts(const Bsdf& bsdf, Vec3 wo) {
  return test::expected_counts(kGrid, kChi2Samples, [&](Vec3 wi) { return bsdf.pdf(wo, wi); });
}

struct Chi2Case {
  std::string name;
  Bsdf bsdf;
  Vec3 wo;
};

std::string case_name(const char* model, float alpha, float theta) {
  char name[64];
  std::snprintf(name, sizeof name, "%s alpha %.1f wo %.0f", model, static_cast<double>(alpha),
                static_cast<double>(theta));
  return name;
}

std::vector<Chi2Case> diffuse_cases() { return {{"diffuse wo 30", Bsdf::diffuse(Color{0.5f}), direction(30.f)}}; }

std::vector<Chi2Case> conductor_cases() {
  std::vector<Chi2Case> cases;
  for (float alpha : {0.1f, 0.3f, 0.8f}) {
    for (float theta : {0.f, 30.f, 60.f, 80.f}) {
      cases.push_back({case_name("conductor", alpha, theta), Bsdf::conductor(gold(), alpha), direction(theta)});
    }
  }
  return cases;
}

// From outside (wo above) and from inside (wo below), at 30 degrees from the normal; then
// grazing from outside, and from inside at 60 degrees, past the critical angle of 41.8
// degrees, where most facets reflect totally.
std::vector<Chi2Case> dielectric_cases() {
  std::vector<Chi2Case> cases;
  for (const auto& [alpha, theta] :
       {std::pair{0.2f, 30.f}, {0.2f, 150.f}, {0.2f, 70.f}, {0.5f, 30.f}, {0.5f, 150.f}, {0.5f, 120.f}}) {
    cases.push_back({case_name("dielectric 1.5", alpha, theta), Bsdf::dielectric(1.5f, alpha), direction(theta)});
  }
  return cases;
}

std::vector<Chi2Case> plastic_cases() {
  std::vector<Chi2Case> cases;
  for (const auto& [alpha, theta] : {std::pair{0.1f, 45.f}, {0.5f, 0.f}, {0.5f, 75.f}}) {
    cases.push_back(
        {case_name("plastic", alpha, theta), Bsdf::plastic({0.6f, 0.3f, 0.1f}, 1.5f, alpha), direction(theta)});
  }
  // A smooth coat: only the diffuse lobe has a density; the delta share lands in the last cell.
  cases.push_back({"plastic smooth wo 45", Bsdf::plastic({0.6f, 0.3f, 0.1f}, 1.5f, 0.f), direction(45.f)});
  return cases;
}

// Significance 0.01 for the whole suite, split over its tests by Sidak's correction.
double per_test_significance() {
  const double tests = static_cast<double>(diffuse_cases().size() + conductor_cases().size() +
                                           dielectric_cases().size() + plastic_cases().size());
  return 1. - std::pow(1. - 0.01, 1. / tests);
}

void expect_samples_follow_pdf(const std::vector<Chi2Case>& cases, std::uint64_t seed) {
  const double significance = per_test_significance();
  Pcg32 rng(seed);
  for (const Chi2Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Chi2Result r = pearson(observed_counts(c.bsdf, c.wo, rng), expected_counts(c.bsdf, c.wo));
    ASSERT_TRUE(r.failure.empty()) << r.failure;
    std::printf("  chi2 %-44s statistic %9.1f dof %4d p %.4f\n", c.name.c_str(), r.statistic, r.dof, r.p_value);
    EXPECT_GT(r.p_value, significance) << "chi2 " << r.statistic << " with " << r.dof << " degrees of freedom";
  }
}

TEST(Chi2PValue, MatchesClosedFormsOfTheChiSquareDistribution) {
  // Two degrees of freedom: Q = exp(-x / 2); one: Q = erfc(sqrt(x / 2)).
  for (double x : {0.1, 1., 4., 20., 60.}) {
    EXPECT_NEAR(gamma_q(1., 0.5 * x), std::exp(-0.5 * x), 1e-12 * std::max(1., std::exp(-0.5 * x))) << x;
    EXPECT_NEAR(gamma_q(0.5, 0.5 * x), std::erfc(std::sqrt(0.5 * x)), 1e-12) << x;
  }
  // Many degrees of freedom: the median of chi-square(k) is about k (1 - 2 / (9k))^3.
  const double k = 2000.;
  EXPECT_NEAR(gamma_q(0.5 * k, 0.5 * k * std::pow(1. - 2. / (9. * k), 3.)), 0.5, 1e-3);
}

// The test can fail: samples of a conductor of alpha 0.3 against the density of alpha 0.33.
TEST(BsdfChi2, RejectsADensityThatIsSlightlyWrong) {
  Pcg32 rng(5);
  const Vec3 wo = direction(30.f);
  const Chi2Result r = pearson(observed_counts(Bsdf::conductor(gold(), 0.3f), wo, rng),
                               expected_counts(Bsdf::conductor(gold(), 0.33f), wo));
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  EXPECT_LT(r.p_value, 1e-6);
}

TEST(BsdfChi2, DiffuseSamplesFollowPdf) { expect_samples_follow_pdf(diffuse_cases(), 1); }
TEST(BsdfChi2, RoughConductorSamplesFollowPdf) { expect_samples_follow_pdf(conductor_cases(), 2); }
TEST(BsdfChi2, RoughDielectricSamplesFollowPdfOverTheSphere) { expect_samples_follow_pdf(dielectric_cases(), 3); }
TEST(BsdfChi2, PlasticSamplesFollowPdf) { expect_samples_follow_pdf(plastic_cases(), 4); }

// --- Weights, densities and reciprocity -----------------------------------------------------

std::vector<Bsdf> rough_models() {
  return {Bsdf::diffuse({0.8f, 0.5f, 0.2f}),
          Bsdf::conductor(gold(), 0.05f),
          Bsdf::conductor(gold(), 0.4f, {0.9f, 0.8f, 0.7f}),
          Bsdf::conductor(*metal_ior("aluminium"), 1.f),
          Bsdf::dielectric(1.5f, 0.1f),
          Bsdf::dielectric(1.33f, 0.6f, {0.9f, 1.f, 0.8f}),
          Bsdf::dielectric(1.f / 1.5f, 0.3f),
          Bsdf::plastic({0.7f, 0.4f, 0.2f}, 1.5f, 0.f),
          Bsdf::plastic({0.7f, 0.4f, 0.2f}, 1.5f, 0.2f),
          Bsdf::plastic({0.2f, 0.9f, 0.4f}, 1.8f, 0.7f)};
}

// A direction uniform on the sphere, kept away from the horizon where cosines lose their
// digits.
Vec3 random_direction(Pcg32& rng) {
  for (;;) {
    const float z = 1.f - 2.f * rng.next_float();
    if (std::fabs(z) < 0.02f) continue;
    const float r = std::sqrt(std::max(0.f, 1.f - z * z));
    const float phi = 2.f * std::numbers::pi_v<float> * rng.next_float();
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
}

void expect_color_rel(Color got, Color want, float rel, float abs = 1e-6f) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], rel * std::fabs(want[k]) + abs) << "channel " << k;
}

TEST(BsdfWeight, WeightIsEvalCosOverPdfAndPdfMatchesSample) {
  Pcg32 rng(11);
  for (const Bsdf& bsdf : rough_models()) {
    SCOPED_TRACE(static_cast<int>(bsdf.model()));
    int checked = 0;
    for (int n = 0; n < 20000; ++n) {
      const Vec3 wo = random_direction(rng);
      const float u_lobe = rng.next_float();
      const auto s = bsdf.sample(wo, u_lobe, next2(rng));
      if (!s || s->delta || std::fabs(s->wi.z) < 0.02f) continue;
      ASSERT_GT(s->pdf, 0.f);
      EXPECT_NEAR(bsdf.pdf(wo, s->wi), s->pdf, 1e-3f * s->pdf);
      expect_color_rel(s->weight, bsdf.eval(wo, s->wi) * (std::fabs(s->wi.z) / bsdf.pdf(wo, s->wi)), 1e-3f);
      EXPECT_EQ(s->transmitted, s->wi.z * wo.z < 0.f);
      ++checked;
    }
    EXPECT_GT(checked, 5000);
  }
}

TEST(BsdfReciprocity, ReflectionIsSymmetric) {
  Pcg32 rng(12);
  for (const Bsdf& bsdf : rough_models()) {
    SCOPED_TRACE(static_cast<int>(bsdf.model()));
    for (int n = 0; n < 20000; ++n) {
      const Vec3 wo = random_direction(rng);
      Vec3 wi = random_direction(rng);
      if (wi.z * wo.z < 0.f) wi.z = -wi.z;  // the same side: a reflection
      expect_color_rel(bsdf.eval(wo, wi), bsdf.eval(wi, wo), 1e-3f);
    }
  }
}

// Radiance-scaled refraction is not symmetric; Veach's generalised reciprocity
// f(wo, wi) / n(wo)^2 = f(wi, wo) / n(wi)^2 holds instead. Where the facet is at the critical
// angle seen from inside (grazing from outside), 1 - F goes as the square root of the distance
// to that angle and float rounding of the facet's cosine shows as up to 20% of f; f is below
// 1e-4 there, hence the absolute tolerance.
TEST(BsdfReciprocity, TransmissionObeysGeneralisedReciprocity) {
  Pcg32 rng(13);
  for (float eta : {1.5f, 1.33f, 2.4f}) {
    for (float alpha : {0.1f, 0.5f}) {
      const Bsdf bsdf = Bsdf::dielectric(eta, alpha);
      int nonzero = 0;
      for (int n = 0; n < 20000; ++n) {
        const Vec3 wo = random_direction(rng);
        Vec3 wi = random_direction(rng);
        if (wi.z * wo.z > 0.f) wi.z = -wi.z;
        const float n_o = wo.z > 0.f ? 1.f : eta;
        const float n_i = wi.z > 0.f ? 1.f : eta;
        const Color forward = bsdf.eval(wo, wi) / (n_o * n_o);
        expect_color_rel(forward, bsdf.eval(wi, wo) / (n_i * n_i), 1e-3f, 1e-4f);
        nonzero += forward.x > 0.f;
      }
      EXPECT_GT(nonzero, 1000) << eta << " " << alpha;
    }
  }
}

// --- Fresnel ----------------------------------------------------------------------------------

// Glass of n = 1.5 at 45 degrees (Hecht, Optics, 5th ed., fig. 4.49): Rs = 0.0920, Rp = 0.0085.
TEST(Fresnel, GlassAt45DegreesMatchesPublishedSAndP) {
  const FresnelTerms r = fresnel_dielectric_sp(std::cos(45.f * kDeg), 1.f, 1.5f);
  EXPECT_NEAR(r.s, 0.0920f, 5e-5f);
  EXPECT_NEAR(r.p, 0.0085f, 5e-5f);
  EXPECT_FLOAT_EQ(fresnel_dielectric(std::cos(45.f * kDeg), 1.f, 1.5f), 0.5f * (r.s + r.p));
}

TEST(Fresnel, NormalIncidenceIsSquaredIndexRatio) {
  for (float n : {1.33f, 1.5f, 2.4f}) {
    const float r0 = (n - 1.f) * (n - 1.f) / ((n + 1.f) * (n + 1.f));
    EXPECT_NEAR(fresnel_dielectric(1.f, 1.f, n), r0, 1e-6f) << n;
    EXPECT_NEAR(fresnel_dielectric(1.f, n, 1.f), r0, 1e-6f) << n;
  }
  EXPECT_NEAR(fresnel_dielectric(1.f, 1.f, 1.5f), 0.04f, 1e-6f);
}

TEST(Fresnel, BrewsterAngleReflectsNoParallelLight) {
  const float brewster = std::atan(1.5f);
  const FresnelTerms r = fresnel_dielectric_sp(std::cos(brewster), 1.f, 1.5f);
  EXPECT_NEAR(r.p, 0.f, 1e-7f);
  EXPECT_GT(r.s, 0.1f);
}

TEST(Fresnel, TotalInternalReflectionBeyondCriticalAngle) {
  const float critical = std::asin(1.f / 1.5f) / kDeg;  // 41.81 degrees
  for (float deg : {critical + 0.1f, 50.f, 70.f, 89.f}) {
    const FresnelTerms r = fresnel_dielectric_sp(std::cos(deg * kDeg), 1.5f, 1.f);
    EXPECT_EQ(r.s, 1.f) << deg;
    EXPECT_EQ(r.p, 1.f) << deg;
  }
  EXPECT_LT(fresnel_dielectric(std::cos((critical - 0.5f) * kDeg), 1.5f, 1.f), 1.f);
}

TEST(Fresnel, ConductorAtNormalIncidenceMatchesClosedForm) {
  for (const char* name : {"gold", "silver", "copper", "aluminium"}) {
    const ConductorIor ior = *metal_ior(name);
    const Color r = fresnel_conductor(1.f, ior);
    for (int c = 0; c < 3; ++c) {
      const float n = ior.eta[c];
      const float k = ior.k[c];
      EXPECT_NEAR(r[c], ((n - 1.f) * (n - 1.f) + k * k) / ((n + 1.f) * (n + 1.f) + k * k), 1e-6f) << name << c;
    }
  }
}

TEST(Fresnel, ConductorWithoutAbsorptionIsADielectric) {
  for (float n : {1.33f, 1.5f, 2.4f}) {
    for (float deg = 0.f; deg < 90.f; deg += 5.f) {
      const float cos_i = std::cos(deg * kDeg);
      const Color r = fresnel_conductor(cos_i, {Color{n}, Color{0.f}});
      EXPECT_NEAR(r.x, fresnel_dielectric(cos_i, 1.f, n), 1e-6f) << n << " " << deg;
    }
  }
  // And a perfect mirror reflects everything at every angle.
  for (float deg = 0.f; deg <= 90.f; deg += 10.f) {
    EXPECT_NEAR(fresnel_conductor(std::cos(deg * kDeg), kPerfectMirror).x, 1.f, 1e-6f) << deg;
  }
}

TEST(Fresnel, DiffuseReflectanceMatchesQuadrature) {
  for (float eta : {1.05f, 1.33f, 1.5f, 2.4f, 1.f / 1.5f, 1.f / 1.33f}) {
    // 2 * integral of F(mu) mu dmu over [0, 1], by the midpoint rule in double.
    constexpr int kSteps = 200000;
    double sum = 0.;
    for (int i = 0; i < kSteps; ++i) {
      const double mu = (i + 0.5) / kSteps;
      sum += 2. * mu * fresnel_dielectric(static_cast<float>(mu), 1.f, eta) / kSteps;
    }
    EXPECT_NEAR(fresnel_diffuse_reflectance(eta), sum, 2e-5) << eta;
  }
  EXPECT_EQ(fresnel_diffuse_reflectance(1.f), 0.f);
}

// Normal-incidence reflectance of bulk metals as the handbooks give it (Bass et al., Handbook of
// Optics, vol. IV, and refractiveindex.info's Johnson & Christy and Rakic data): silver above
// 0.9 across the visible, gold and copper red over green over blue with gold's blue near 0.38,
// aluminium flat near 0.92.
TEST(MetalIor, NormalReflectanceMatchesPublishedValues) {
  const auto reflectance = [](const char* name) { return fresnel_conductor(1.f, *metal_ior(name)); };
  const Color silver = reflectance("silver");
  EXPECT_GT(silver.x, 0.96f);
  EXPECT_GT(silver.y, 0.95f);
  EXPECT_GT(silver.z, 0.90f);
  const Color gold = reflectance("gold");
  EXPECT_GT(gold.x, gold.y);
  EXPECT_GT(gold.y, gold.z);
  EXPECT_NEAR(gold.x, 0.94f, 0.02f);
  EXPECT_NEAR(gold.y, 0.85f, 0.04f);
  EXPECT_NEAR(gold.z, 0.38f, 0.04f);
  const Color copper = reflectance("copper");
  EXPECT_GT(copper.x, copper.y);
  EXPECT_GT(copper.y, copper.z);
  EXPECT_NEAR(copper.x, 0.94f, 0.02f);
  EXPECT_NEAR(copper.y, 0.63f, 0.05f);
  EXPECT_NEAR(copper.z, 0.55f, 0.05f);
  const Color aluminium = reflectance("aluminium");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(aluminium[c], 0.92f, 0.015f) << c;
}

TEST(MetalIor, KnowsBothSpellingsOfAluminiumAndRejectsUnknownNames) {
  ASSERT_TRUE(metal_ior("aluminum").has_value());
  EXPECT_EQ(metal_ior("aluminum")->eta, metal_ior("aluminium")->eta);
  EXPECT_EQ(metal_ior("aluminum")->k, metal_ior("aluminium")->k);
  EXPECT_FALSE(metal_ior("unobtainium").has_value());
  EXPECT_FALSE(metal_ior("").has_value());
}

// --- Energy ---------------------------------------------------------------------------------

struct Albedo {
  double mean = 0.;
  double std_error = 0.;
};

// Directional albedo: the mean sample weight (channel `c`), failures counting 0. With
// `importance` the transmitted weights are multiplied by eta_rel^2, undoing the radiance
// scale, so that the mean is the fraction of energy scattered.
Albedo directional_albedo(const Bsdf& bsdf, Vec3 wo, int n, Pcg32& rng, float eta = 1.f, int c = 0) {
  double sum = 0.;
  double sum2 = 0.;
  for (int i = 0; i < n; ++i) {
    const float u_lobe = rng.next_float();
    const auto s = bsdf.sample(wo, u_lobe, next2(rng));
    if (!s) continue;
    double w = s->weight[c];
    if (s->transmitted) {
      const double eta_rel = wo.z > 0.f ? eta : 1. / eta;
      w *= eta_rel * eta_rel;
    }
    sum += w;
    sum2 += w * w;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0., sum2 / n - mean * mean) / n)};
}

TEST(BsdfEnergy, DiffuseAlbedoIsRho) {
  Pcg32 rng(21);
  const Color rho{0.8f, 0.5f, 0.25f};
  const Bsdf bsdf = Bsdf::diffuse(rho);
  for (float theta : {0.f, 45.f, 85.f}) {
    for (int c = 0; c < 3; ++c) {
      const Albedo a = directional_albedo(bsdf, direction(theta), 100000, rng, 1.f, c);
      EXPECT_NEAR(a.mean, rho[c], 1e-5) << theta;  // every weight is rho: no noise at all
    }
  }
}

TEST(BsdfEnergy, SmoothDielectricConservesEnergyFromBothSides) {
  Pcg32 rng(22);
  for (float eta : {1.33f, 1.5f, 2.4f}) {
    const Bsdf bsdf = Bsdf::dielectric(eta, 0.f);
    for (float theta : {0.f, 30.f, 60.f, 89.f, 180.f, 160.f, 130.f, 100.f}) {
      const Albedo a = directional_albedo(bsdf, direction(theta), 20000, rng, eta);
      EXPECT_NEAR(a.mean, 1., 1e-6) << eta << " " << theta;
    }
  }
}

TEST(BsdfEnergy, PerfectSmoothMirrorReflectsEverything) {
  const Bsdf bsdf = Bsdf::conductor(kPerfectMirror, 0.f);
  for (float theta : {0.f, 30.f, 60.f, 89.f}) {
    const auto s = bsdf.sample(direction(theta), 0.5f, {0.3f, 0.6f});
    ASSERT_TRUE(s.has_value());
    expect_color_rel(s->weight, Color{1.f}, 1e-6f);
  }
}

// No model scatters more than arrives: conductors as perfect mirrors, glass with the radiance
// scale undone, diffuse and plastic with a white base.
TEST(BsdfEnergy, NoModelCreatesEnergy) {
  Pcg32 rng(23);
  for (float alpha : {0.f, 0.05f, 0.2f, 0.5f, 1.f}) {
    const std::array<std::pair<Bsdf, float>, 5> models{{{Bsdf::conductor(kPerfectMirror, alpha), 1.f},
                                                        {Bsdf::dielectric(1.5f, alpha), 1.5f},
                                                        {Bsdf::dielectric(1.f / 1.5f, alpha), 1.f / 1.5f},
                                                        {Bsdf::plastic(Color{1.f}, 1.5f, alpha), 1.f},
                                                        {Bsdf::diffuse(Color{1.f}), 1.f}}};
    for (const auto& [bsdf, eta] : models) {
      for (float theta : {0.f, 30.f, 60.f, 85.f, 180.f, 150.f, 120.f, 95.f}) {
        const Albedo a = directional_albedo(bsdf, direction(theta), 20000, rng, eta);
        EXPECT_LE(a.mean, 1. + 4. * a.std_error + 1e-6)
            << "model " << static_cast<int>(bsdf.model()) << " alpha " << alpha << " theta " << theta;
      }
    }
  }
}

// Smooth plastic with a white base conserves energy exactly: what the coat does not reflect,
// F(wo), reaches the viewer through the base, since (1 - Fdr_ext) / eta^2 = 1 - Fdr_int. With a
// grey base rho the albedo is F + (1 - F) rho (1 - Fdr_int) / (1 - rho Fdr_int).
TEST(BsdfEnergy, SmoothPlasticAlbedoMatchesClosedForm) {
  Pcg32 rng(24);
  const float eta = 1.5f;
  const float fdr_int = fresnel_diffuse_reflectance(1.f / eta);
  for (float rho : {1.f, 0.5f}) {
    const Bsdf bsdf = Bsdf::plastic(Color{rho}, eta, 0.f);
    for (float theta : {0.f, 45.f, 80.f}) {
      const float f = fresnel_dielectric(std::cos(theta * kDeg), 1.f, eta);
      const double want = f + (1.f - f) * rho * (1.f - fdr_int) / (1.f - rho * fdr_int);
      const Albedo a = directional_albedo(bsdf, direction(theta), 200000, rng);
      EXPECT_NEAR(a.mean, want, 4. * a.std_error + 1e-4) << rho << " " << theta;
    }
  }
}

// Integral of f cos over the upper hemisphere by quadrature of eval alone: an albedo that shares
// no code with sample().
double albedo_by_quadrature(const Bsdf& bsdf, Vec3 wo) {
  const auto integrand = [&](double t, double p) {
    const Vec3 wi = spherical(t, p);
    return static_cast<double>(bsdf.eval(wo, wi).x) * std::cos(t);
  };
  double sum = 0.;
  constexpr int kTheta = 48;
  constexpr int kPhi = 192;  // fine in azimuth: near the horizon a low-roughness lobe is narrow there
  for (int i = 0; i < kTheta; ++i) {
    for (int j = 0; j < kPhi; ++j) {
      sum += integrate_on_sphere(integrand, 0.5 * kPi * i / kTheta, 0.5 * kPi * (i + 1) / kTheta, 2. * kPi * j / kPhi,
                                 2. * kPi * (j + 1) / kPhi, 1);
    }
  }
  return sum;
}

// Albedo of a perfect-mirror GGX conductor at normal incidence, from a 1-D integral that shares
// no code with the model: the visible normals are then distributed as D(m) cos(m), whose
// cumulative distribution in t = tan^2(m) is c = t / (alpha^2 + t); a facet at m reflects to
// 2m with weight G2 = 1 / (1 + Lambda(2m)), and facets steeper than 45 degrees (c above
// 1 / (1 + alpha^2)) reflect below the horizon. At alpha = 1 the integral is 1 - ln 2.
double normal_incidence_albedo(double alpha) {
  const double a2 = alpha * alpha;
  const double c_max = 1. / (1. + a2);
  constexpr int kSteps = 100000;
  double sum = 0.;
  for (int i = 0; i < kSteps; ++i) {
    const double c = c_max * (i + 0.5) / kSteps;
    const double t = a2 * c / (1. - c);
    const double tan2_out = 4. * t / ((1. - t) * (1. - t));  // tan^2(2m)
    sum += 1. / (1. + 0.5 * (std::sqrt(1. + a2 * tan2_out) - 1.));
  }
  return sum * c_max / kSteps;
}

// Single-scattering GGX loses the light that would scatter again between facets, and at any
// roughness the light that the facets steeper than 45 degrees send below the horizon: at normal
// incidence at least alpha^2 / (1 + alpha^2), 1% at alpha = 0.1, whatever the masking. Measured
// albedo of a perfect-mirror conductor (Fresnel 1), by quadrature of eval (converged to 1e-4;
// 200,000 samples each agree with every entry to within their noise):
//
//   alpha   wo 0    wo 30   wo 60   wo 80
//   0.1     0.9883  0.9861  0.9692  0.8955
//   0.2     0.9477  0.9391  0.8952  0.8623
//   0.3     0.8774  0.8639  0.8217  0.8482
//   0.5     0.6878  0.6831  0.6983  0.8053
//   0.7     0.5037  0.5176  0.5899  0.7509
//   1.0     0.3069  0.3352  0.4507  0.6682
TEST(BsdfEnergy, RoughConductorLossMatchesSingleScatteringGgx) {
  Pcg32 rng(25);
  const std::array<float, 4> angles{0.f, 30.f, 60.f, 80.f};
  std::printf("  GGX conductor albedo (Fresnel 1), sampled | by quadrature of eval\n  alpha");
  for (float theta : angles) std::printf("   wo %2.0f deg      ", static_cast<double>(theta));
  std::printf("\n");
  for (float alpha : {0.1f, 0.2f, 0.3f, 0.5f, 0.7f, 1.f}) {
    const Bsdf bsdf = Bsdf::conductor(kPerfectMirror, alpha);
    std::printf("  %.1f  ", static_cast<double>(alpha));
    for (float theta : angles) {
      SCOPED_TRACE(std::to_string(alpha) + " " + std::to_string(theta));
      const Vec3 wo = direction(theta);
      const Albedo a = directional_albedo(bsdf, wo, 200000, rng);
      const double quadrature = albedo_by_quadrature(bsdf, wo);
      std::printf("  %.4f | %.4f", a.mean, quadrature);
      EXPECT_NEAR(a.mean, quadrature, 4. * a.std_error + 1e-3);
      EXPECT_LE(a.mean, 1. + 1e-6);
      if (theta == 0.f) {
        EXPECT_NEAR(a.mean, normal_incidence_albedo(alpha), 4. * a.std_error + 1e-4);
      }
      if (alpha == 0.1f && theta <= 30.f) {
        EXPECT_GT(a.mean, 0.98);  // under 2% lost
      }
    }
    std::printf("\n");
  }
  EXPECT_NEAR(normal_incidence_albedo(1.), 1. - std::log(2.), 1e-6);
  const double a2 = 0.01;  // alpha = 0.1: just above the loss to steep facets
  EXPECT_LT(normal_incidence_albedo(0.1), 1. - a2 / (1. + a2));
  EXPECT_GT(normal_incidence_albedo(0.1), 1. - a2 / (1. + a2) - 3e-3);
}

// --- Delta lobes ------------------------------------------------------------------------------

TEST(BsdfDelta, SmoothConductorIsAnExactMirrorWeightedByFresnel) {
  const Bsdf bsdf = Bsdf::conductor(gold(), 0.f, {0.9f, 0.8f, 1.f});
  EXPECT_TRUE(bsdf.is_delta());
  for (float theta : {0.f, 20.f, 55.f, 87.f}) {
    const Vec3 wo = direction(theta, 1.9f);
    const auto s = bsdf.sample(wo, 0.3f, {0.2f, 0.7f});
    ASSERT_TRUE(s.has_value());
    EXPECT_TRUE(s->delta);
    EXPECT_FALSE(s->transmitted);
    EXPECT_EQ(s->wi, (Vec3{-wo.x, -wo.y, wo.z}));
    expect_color_rel(s->weight, Color{0.9f, 0.8f, 1.f} * fresnel_conductor(wo.z, gold()), 1e-6f);
  }
  EXPECT_FALSE(bsdf.sample(direction(120.f), 0.3f, {0.2f, 0.7f}).has_value());  // from below
}

TEST(BsdfDelta, SmoothDielectricReflectsOrRefractsBySnellsLaw) {
  const float eta = 1.5f;
  const Bsdf bsdf = Bsdf::dielectric(eta, 0.f, {0.5f, 1.f, 1.f});
  EXPECT_TRUE(bsdf.is_delta());
  for (float theta : {0.f, 25.f, 60.f, 85.f, 180.f, 160.f, 140.f}) {
    SCOPED_TRACE(theta);
    const Vec3 wo = direction(theta, 2.3f);
    const bool outside = wo.z > 0.f;
    const float eta_i = outside ? 1.f : eta;
    const float eta_t = outside ? eta : 1.f;
    const float r = fresnel_dielectric(std::fabs(wo.z), eta_i, eta_t);
    const auto reflected = bsdf.sample(wo, 0.5f * r, {0.5f, 0.5f});
    ASSERT_TRUE(reflected.has_value());
    EXPECT_TRUE(reflected->delta);
    EXPECT_FALSE(reflected->transmitted);
    EXPECT_EQ(reflected->wi, (Vec3{-wo.x, -wo.y, wo.z}));
    EXPECT_NEAR(reflected->pdf, r, 1e-7f);
    const auto refracted = bsdf.sample(wo, 0.5f * (1.f + r), {0.5f, 0.5f});
    ASSERT_TRUE(refracted.has_value());
    EXPECT_TRUE(refracted->transmitted);
    // Snell: the tangential part shrinks by eta_i / eta_t, the direction stays in the plane of
    // incidence on the far side, and is a unit vector.
    const float ratio = eta_i / eta_t;
    EXPECT_NEAR(refracted->wi.x, -wo.x * ratio, 1e-6f);
    EXPECT_NEAR(refracted->wi.y, -wo.y * ratio, 1e-6f);
    EXPECT_LT(refracted->wi.z * wo.z, 0.f);
    EXPECT_NEAR(length(refracted->wi), 1.f, 1e-6f);
    EXPECT_NEAR(refracted->pdf, 1.f - r, 1e-6f);
    const float eta_rel = eta_t / eta_i;
    expect_color_rel(refracted->weight, Color{0.5f, 1.f, 1.f} / (eta_rel * eta_rel), 1e-6f);
  }
  // From inside past the critical angle every sample reflects.
  for (float u : {0.f, 0.5f, 0.999f}) {
    const auto s = bsdf.sample(direction(130.f), u, {0.5f, 0.5f});
    ASSERT_TRUE(s.has_value());
    EXPECT_FALSE(s->transmitted);
  }
}

TEST(BsdfDelta, DeltaModelsHaveNoDensity) {
  Pcg32 rng(31);
  for (const Bsdf& bsdf : {Bsdf::conductor(gold(), 0.f), Bsdf::dielectric(1.5f, 0.f), Bsdf::dielectric(1.f, 0.4f)}) {
    EXPECT_TRUE(bsdf.is_delta());
    for (int n = 0; n < 100; ++n) {
      const Vec3 wo = random_direction(rng);
      const Vec3 wi = random_direction(rng);
      EXPECT_EQ(bsdf.eval(wo, wi), Color{0.f});
      EXPECT_EQ(bsdf.pdf(wo, wi), 0.f);
    }
  }
  EXPECT_FALSE(Bsdf::plastic(Color{0.5f}, 1.5f, 0.f).is_delta());  // the base is diffuse
  EXPECT_FALSE(Bsdf::conductor(gold(), 0.01f).is_delta());
}

}  // namespace
}  // namespace raylab
