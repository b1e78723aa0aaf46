// The SPD generators balls, gears, mount and tetra: at their default size each must describe the
// same scene as the NFF file the original SPD 3.14 program writes (../shared/spd-reference),
// read here with load_nff; at other sizes their primitive counts must follow the originals'
// formulas; sizes out of range are refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "../test_paths.h"
#include "../test_util.h"
#include "raylab/core/error.h"
#include "raylab/io/nff_loader.h"
#include "raylab/scene/spd.h"

namespace raylab {
namespace {

namespace fs = std::filesystem;

const std::string kReferenceDir = raylab::test::source_dir() + "/../shared/spd-reference/";

// The reference prints with %g (6 significant digits), so values agree to about 5e-6 relative;
// coordinates that are zero in one and rounding noise (1e-17) in the other need the absolute term.
constexpr double kRelTol = 1e-5;
constexpr double kAbsTol = 1e-6;

bool close(float a, float b) {
  return std::fabs(double(a) - double(b)) <= kRelTol * std::max(std::fabs(double(a)), std::fabs(double(b))) + kAbsTol;
}
bool close(Vec3 a, Vec3 b) { return close(a.x, b.x) && close(a.y, b.y) && close(a.z, b.z); }

std::string str(Vec3 v) { return std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z); }

// Largest coordinate difference seen, absolute and as a fraction of the tolerance, recorded in
// the test's properties (--gtest_output=xml shows them).
struct Deviation {
  double max = 0.0, max_share_of_tolerance = 0.0;
  void see(float a, float b) {
    const double d = std::fabs(double(a) - double(b));
    max = std::max(max, d);
    const double tolerance = kRelTol * std::max(std::fabs(double(a)), std::fabs(double(b))) + kAbsTol;
    max_share_of_tolerance = std::max(max_share_of_tolerance, d / tolerance);
  }
  void see(Vec3 a, Vec3 b) {
    see(a.x, b.x);
    see(a.y, b.y);
    see(a.z, b.z);
  }
  void record() const {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", max);
    ::testing::Test::RecordProperty("max_coordinate_deviation", text);
    std::snprintf(text, sizeof text, "%.3g", max_share_of_tolerance);
    ::testing::Test::RecordProperty("max_share_of_tolerance", text);
  }
};

// Expects `generated` and `reference` to be the same scene up to the reference's printing
// precision: same primitives in the same order with the same objects, same materials, lights,
// camera and settings.
void expect_same_scene(const Scene& generated, const Scene& reference) {
  const Geometry& g = generated.geometry;
  const Geometry& r = reference.geometry;
  Deviation deviation;

  ASSERT_EQ(g.triangles.size(), r.triangles.size());
  std::size_t bad = 0;
  for (std::size_t i = 0; i < g.triangles.size(); ++i) {
    const Triangle& a = g.triangles[i];
    const Triangle& b = r.triangles[i];
    deviation.see(a.p0, b.p0);
    deviation.see(a.p1, b.p1);
    deviation.see(a.p2, b.p2);
    if (!(close(a.p0, b.p0) && close(a.p1, b.p1) && close(a.p2, b.p2)) && bad++ < 5) {
      ADD_FAILURE() << "triangle " << i << ": " << str(a.p0) << " / " << str(a.p1) << " / " << str(a.p2)
                    << " vs reference " << str(b.p0) << " / " << str(b.p1) << " / " << str(b.p2);
    }
  }
  EXPECT_EQ(bad, 0u) << "triangles differing from the reference";
  EXPECT_EQ(g.triangle_objects, r.triangle_objects);
  EXPECT_EQ(g.triangle_normals.size(), r.triangle_normals.size());

  ASSERT_EQ(g.spheres.size(), r.spheres.size());
  bad = 0;
  for (std::size_t i = 0; i < g.spheres.size(); ++i) {
    const Sphere& a = g.spheres[i];
    const Sphere& b = r.spheres[i];
    deviation.see(a.center, b.center);
    deviation.see(a.radius, b.radius);
    if (!(close(a.center, b.center) && close(a.radius, b.radius)) && bad++ < 5) {
      ADD_FAILURE() << "sphere " << i << ": " << str(a.center) << " r " << a.radius << " vs reference " << str(b.center)
                    << " r " << b.radius;
    }
  }
  EXPECT_EQ(bad, 0u) << "spheres differing from the reference";
  EXPECT_EQ(g.sphere_objects, r.sphere_objects);
  EXPECT_EQ(g.cylinders.size(), r.cylinders.size());
  EXPECT_EQ(g.disks.size(), r.disks.size());
  EXPECT_EQ(g.quads.size(), r.quads.size());
  deviation.record();

  test::expect_each(generated.objects, reference.objects, "object", [](const SceneObject& a, const SceneObject& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.material, b.material);
  });
  test::expect_each(generated.materials, reference.materials, "material", [](const Material& a, const Material& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_TRUE(close(a.color, b.color)) << str(a.color) << " vs " << str(b.color);
    EXPECT_TRUE(close(a.kd, b.kd)) << a.kd << " vs " << b.kd;
    EXPECT_TRUE(close(a.ks, b.ks)) << a.ks << " vs " << b.ks;
    EXPECT_TRUE(close(a.shininess, b.shininess)) << a.shininess << " vs " << b.shininess;
    EXPECT_TRUE(close(a.reflectivity, b.reflectivity)) << a.reflectivity << " vs " << b.reflectivity;
    EXPECT_TRUE(close(a.transmittance, b.transmittance)) << a.transmittance << " vs " << b.transmittance;
    EXPECT_TRUE(close(a.ior, b.ior)) << a.ior << " vs " << b.ior;
    EXPECT_EQ(a.fresnel, b.fresnel);
  });
  test::expect_each(generated.lights, reference.lights, "light", [](const Light& a, const Light& b) {
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_TRUE(close(a.position, b.position)) << str(a.position) << " vs " << str(b.position);
    EXPECT_TRUE(close(a.intensity, b.intensity)) << str(a.intensity) << " vs " << str(b.intensity);
    EXPECT_EQ(a.falloff, b.falloff);
  });

  const CameraSpec& ca = generated.camera;
  const CameraSpec& cb = reference.camera;
  EXPECT_TRUE(close(ca.from, cb.from)) << str(ca.from) << " vs " << str(cb.from);
  EXPECT_TRUE(close(ca.at, cb.at)) << str(ca.at) << " vs " << str(cb.at);
  EXPECT_TRUE(close(ca.up, cb.up)) << str(ca.up) << " vs " << str(cb.up);
  EXPECT_TRUE(close(ca.vfov_degrees, cb.vfov_degrees));
  EXPECT_EQ(ca.fov_span, cb.fov_span);
  EXPECT_TRUE(close(ca.hither, cb.hither)) << ca.hither << " vs " << cb.hither;

  EXPECT_EQ(generated.settings.width, reference.settings.width);
  EXPECT_EQ(generated.settings.height, reference.settings.height);
  EXPECT_TRUE(close(generated.settings.background, reference.settings.background));
  EXPECT_EQ(generated.settings.max_depth, reference.settings.max_depth);
}

class SpdBallsGearsMountTetra : public ::testing::TestWithParam<const char*> {};

TEST_P(SpdBallsGearsMountTetra, DefaultSizeMatchesOriginalProgramOutput) {
  const std::string name = GetParam();
  const std::string path = kReferenceDir + name + ".nff";
  if (!fs::exists(path)) GTEST_SKIP() << "no SPD reference at " << path;
  Scene reference;
  load_nff(path, reference);
  const Scene generated = make_spd_scene("spd:" + name);
  // A reference that failed to load would make the comparison vacuous.
  ASSERT_GT(reference.geometry.size(), 0u);
  expect_same_scene(generated, reference);
}

INSTANTIATE_TEST_SUITE_P(Spd, SpdBallsGearsMountTetra, ::testing::Values("balls", "gears", "mount", "tetra"),
                         [](const auto& info) { return std::string(info.param); });

const SpdGenerator& generator(std::string_view name) {
  for (const SpdGenerator& g : spd_generators()) {
    if (g.name == name) return g;
  }
  throw std::logic_error("no SPD generator " + std::string(name));
}

std::uint64_t power(std::uint64_t base, int exponent) {
  std::uint64_t p = 1;
  while (exponent-- > 0) p *= base;
  return p;
}

// Expected primitive counts of each scene at size s, from the SPD programs' own formulas. Each
// polygon of n corners becomes n - 2 triangles.
struct Counts {
  std::uint64_t triangles = 0, spheres = 0;
};

// balls: spheres 1 + 9 + ... + 9^s = (9^(s+1) - 1) / 8; the square floor is 2 triangles.
Counts balls_counts(int s) { return {2, (power(9, s + 1) - 1) / 8}; }
// gears: s^3 gears, each two 144-gons (142 triangles each) and 144 quadrilateral walls; floor 2.
Counts gears_counts(int s) { return {2 + power(s, 3) * (2 * 142 + 144 * 2), 0}; }
// mount: 2 * 4^s triangles and 4 spheres.
Counts mount_counts(int s) { return {2 * power(4, s), 4}; }
// tetra: 4^(s-1) tetrahedra of 4 triangles: 4^s triangles.
Counts tetra_counts(int s) { return {power(4, s), 0}; }

void expect_counts(const std::string& name, int size, Counts expected) {
  SCOPED_TRACE(name + " size " + std::to_string(size));
  const Scene scene = make_spd_scene("spd:" + name + "?size=" + std::to_string(size));
  EXPECT_EQ(scene.geometry.triangles.size(), expected.triangles);
  EXPECT_EQ(scene.geometry.spheres.size(), expected.spheres);
  EXPECT_TRUE(scene.geometry.cylinders.empty());
}

TEST(SpdBallsGearsMountTetraSizes, CountsFollowTheOriginalFormulas) {
  for (int size = 1; size <= 3; ++size) {
    expect_counts("balls", size, balls_counts(size));
    expect_counts("gears", size, gears_counts(size));
    expect_counts("mount", size, mount_counts(size));
    expect_counts("tetra", size, tetra_counts(size));
  }
  // The defaults the references were made with.
  EXPECT_EQ(generator("balls").default_size, 4);
  EXPECT_EQ(generator("gears").default_size, 4);
  EXPECT_EQ(generator("mount").default_size, 6);
  EXPECT_EQ(generator("tetra").default_size, 6);
}

TEST(SpdBallsGearsMountTetraSizes, LargestSizeStaysUnderThirtyMillionPrimitives) {
  constexpr std::uint64_t kLimit = 30'000'000;
  const auto total = [](Counts c) { return c.triangles + c.spheres; };
  EXPECT_LE(total(balls_counts(generator("balls").max_size)), kLimit);
  EXPECT_LE(total(gears_counts(generator("gears").max_size)), kLimit);
  EXPECT_LE(total(mount_counts(generator("mount").max_size)), kLimit);
  EXPECT_LE(total(tetra_counts(generator("tetra").max_size)), kLimit);
  // ...and is not needlessly small: one more step would pass the limit.
  EXPECT_GT(total(balls_counts(generator("balls").max_size + 1)), kLimit);
  EXPECT_GT(total(gears_counts(generator("gears").max_size + 1)), kLimit);
  EXPECT_GT(total(mount_counts(generator("mount").max_size + 1)), kLimit);
  EXPECT_GT(total(tetra_counts(generator("tetra").max_size + 1)), kLimit);
}

TEST(SpdBallsGearsMountTetraSizes, OutOfRangeSizesAreRefused) {
  for (const char* name : {"balls", "gears", "mount", "tetra"}) {
    SCOPED_TRACE(name);
    const std::string source = std::string("spd:") + name + "?size=";
    EXPECT_THROW(make_spd_scene(source + "0"), UsageError);
    EXPECT_THROW(make_spd_scene(source + std::to_string(generator(name).max_size + 1)), UsageError);
  }
}

// The mountain's heights come from seeds hashed from grid coordinates, not from a running random
// stream: two builds agree exactly, and cells sharing a grid point agree on its height, so the
// surface has no cracks. (At size 4, which has no reference file.)
TEST(SpdMountSurface, SurfaceIsDeterministicAndCrackFree) {
  const Scene a = make_spd_scene("spd:mount?size=4");
  const Scene b = make_spd_scene("spd:mount?size=4");
  ASSERT_EQ(a.geometry.triangles.size(), b.geometry.triangles.size());
  for (std::size_t i = 0; i < a.geometry.triangles.size(); ++i) {
    EXPECT_EQ(a.geometry.triangles[i].p0.z, b.geometry.triangles[i].p0.z);
  }
  // Height seen at each grid point by every triangle touching it.
  constexpr int kCells = 16;
  std::vector<std::vector<float>> height(kCells + 1, std::vector<float>(kCells + 1, NAN));
  std::size_t mismatches = 0;
  for (const Triangle& t : a.geometry.triangles) {
    for (const Vec3& p : {t.p0, t.p1, t.p2}) {
      const int i = static_cast<int>(std::lround((p.x + 1.f) / 2.f * kCells));
      const int j = static_cast<int>(std::lround((p.y + 1.f) / 2.f * kCells));
      ASSERT_TRUE(i >= 0 && i <= kCells && j >= 0 && j <= kCells);
      float& h = height[i][j];
      if (std::isnan(h)) {
        h = p.z;
      } else if (h != p.z) {
        ++mismatches;
      }
    }
  }
  EXPECT_EQ(mismatches, 0u);
  // The mountain is not flat: the displacement did something.
  float lowest = 0.f, highest = 0.f;
  for (const auto& row : height) {
    for (const float h : row) {
      lowest = std::min(lowest, h);
      highest = std::max(highest, h);
    }
  }
  EXPECT_GT(highest - lowest, 0.1f);
}

}  // namespace
}  // namespace raylab
