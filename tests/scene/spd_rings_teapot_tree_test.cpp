// The SPD generators 'rings', 'teapot' and 'tree' against the NFF files the original SPD 3.14
// programs write (../shared/spd-reference): at the default size each must build the same Scene as
// loading that file, primitive by primitive, up to the 6 significant digits the file keeps. Other
// sizes must give the primitive counts the original programs document, and sizes out of range
// are refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "../test_paths.h"
#include "raylab/core/error.h"
#include "raylab/io/nff_loader.h"
#include "raylab/scene/spd.h"

namespace raylab {
namespace {

const std::string kReferenceDir = raylab::test::source_dir() + "/../shared/spd-reference/";

// The reference prints %g (6 significant digits), so values agree to 5e-6 relative; the absolute
// part covers values that are rounding noise of zero there (2.22045e-16 for 0).
bool close(float a, float b) { return std::fabs(a - b) <= 1e-5f * std::max(std::fabs(a), std::fabs(b)) + 1e-5f; }
bool close(Vec3 a, Vec3 b) { return close(a.x, b.x) && close(a.y, b.y) && close(a.z, b.z); }

std::string str(Vec3 v) {
  std::ostringstream s;
  s.precision(9);
  s << '(' << v.x << ", " << v.y << ", " << v.z << ')';
  return s.str();
}

// Tallies mismatches of one array, so that a wrong scene reports the first difference and how
// many there are instead of thousands of failures.
class Mismatches {
 public:
  explicit Mismatches(std::string what) : m_what(std::move(what)) {}
  ~Mismatches() { EXPECT_EQ(m_count, 0u) << m_what << ": " << m_count << " differ, first " << m_first; }
  void check(bool ok, std::size_t index, const std::string& generated, const std::string& reference) {
    if (ok) return;
    if (m_count++ == 0) {
      m_first = "#" + std::to_string(index) + ": generated " + generated + ", reference " + reference;
    }
  }

 private:
  std::string m_what;
  std::size_t m_count = 0;
  std::string m_first;
};

void compare_geometry(const Geometry& gen, const Geometry& ref) {
  ASSERT_EQ(gen.spheres.size(), ref.spheres.size());
  ASSERT_EQ(gen.cylinders.size(), ref.cylinders.size());
  ASSERT_EQ(gen.triangles.size(), ref.triangles.size());
  ASSERT_EQ(gen.triangle_normals.size(), ref.triangle_normals.size());
  EXPECT_TRUE(gen.disks.empty() && gen.quads.empty());
  {
    Mismatches m("spheres");
    for (std::size_t i = 0; i < ref.spheres.size(); ++i) {
      const Sphere& a = gen.spheres[i];
      const Sphere& b = ref.spheres[i];
      m.check(close(a.center, b.center) && close(a.radius, b.radius), i,
              str(a.center) + " r " + std::to_string(a.radius), str(b.center) + " r " + std::to_string(b.radius));
    }
  }
  {
    Mismatches m("cylinders");
    for (std::size_t i = 0; i < ref.cylinders.size(); ++i) {
      const Cylinder& a = gen.cylinders[i];
      const Cylinder& b = ref.cylinders[i];
      m.check(close(a.base, b.base) && close(a.base_radius, b.base_radius) && close(a.apex, b.apex) &&
                  close(a.apex_radius, b.apex_radius),
              i, str(a.base) + "-" + str(a.apex), str(b.base) + "-" + str(b.apex));
    }
  }
  {
    Mismatches m("triangles");
    for (std::size_t i = 0; i < ref.triangles.size(); ++i) {
      const Triangle& a = gen.triangles[i];
      const Triangle& b = ref.triangles[i];
      m.check(close(a.p0, b.p0) && close(a.p1, b.p1) && close(a.p2, b.p2), i, str(a.p0) + str(a.p1) + str(a.p2),
              str(b.p0) + str(b.p1) + str(b.p2));
    }
  }
  {
    Mismatches m("triangle normals");
    for (std::size_t i = 0; i < ref.triangle_normals.size(); ++i) {
      const auto& a = gen.triangle_normals[i];
      const auto& b = ref.triangle_normals[i];
      m.check(close(a[0], b[0]) && close(a[1], b[1]) && close(a[2], b[2]), i, str(a[0]) + str(a[1]) + str(a[2]),
              str(b[0]) + str(b[1]) + str(b[2]));
    }
  }
  // Same objects in the same order means each primitive follows the same fill as in the file.
  EXPECT_EQ(gen.sphere_objects, ref.sphere_objects);
  EXPECT_EQ(gen.cylinder_objects, ref.cylinder_objects);
  EXPECT_EQ(gen.triangle_objects, ref.triangle_objects);
}

void compare_materials(const Scene& gen, const Scene& ref) {
  ASSERT_EQ(gen.objects.size(), ref.objects.size());
  for (std::size_t i = 0; i < ref.objects.size(); ++i) {
    EXPECT_EQ(gen.objects[i].material, ref.objects[i].material) << "object " << i;
  }
  ASSERT_EQ(gen.materials.size(), ref.materials.size());
  Mismatches m("materials");
  for (std::size_t i = 0; i < ref.materials.size(); ++i) {
    const Material& a = gen.materials[i];
    const Material& b = ref.materials[i];
    const bool ok = close(a.color, b.color) && close(a.kd, b.kd) && close(a.ks, b.ks) &&
                    close(a.shininess, b.shininess) && close(a.reflectivity, b.reflectivity) &&
                    close(a.transmittance, b.transmittance) && close(a.ior, b.ior) && a.fresnel == b.fresnel;
    m.check(ok, i, str(a.color) + " shine " + std::to_string(a.shininess),
            str(b.color) + " shine " + std::to_string(b.shininess));
  }
}

void compare_view(const Scene& gen, const Scene& ref) {
  EXPECT_TRUE(close(gen.camera.from, ref.camera.from)) << str(gen.camera.from) << " vs " << str(ref.camera.from);
  EXPECT_TRUE(close(gen.camera.at, ref.camera.at)) << str(gen.camera.at) << " vs " << str(ref.camera.at);
  EXPECT_TRUE(close(gen.camera.up, ref.camera.up)) << str(gen.camera.up) << " vs " << str(ref.camera.up);
  EXPECT_FLOAT_EQ(gen.camera.vfov_degrees, ref.camera.vfov_degrees);
  EXPECT_EQ(gen.camera.fov_span, ref.camera.fov_span);
  EXPECT_FLOAT_EQ(gen.camera.hither, ref.camera.hither);
  EXPECT_EQ(gen.settings.width, ref.settings.width);
  EXPECT_EQ(gen.settings.height, ref.settings.height);
  EXPECT_TRUE(close(gen.settings.background, ref.settings.background));
  ASSERT_EQ(gen.lights.size(), ref.lights.size());
  for (std::size_t i = 0; i < ref.lights.size(); ++i) {
    EXPECT_TRUE(close(gen.lights[i].position, ref.lights[i].position))
        << "light " << i << ": " << str(gen.lights[i].position) << " vs " << str(ref.lights[i].position);
    EXPECT_TRUE(close(gen.lights[i].intensity, ref.lights[i].intensity)) << "light " << i;
    EXPECT_EQ(gen.lights[i].kind, ref.lights[i].kind) << "light " << i;
  }
}

// spd:NAME at its default size against NAME.nff from the original program.
void compare_with_reference(const std::string& name) {
  const std::string path = kReferenceDir + name + ".nff";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no SPD reference at " << path;
  Scene ref;
  load_nff(path, ref);
  const Scene gen = make_spd_scene("spd:" + name);
  compare_view(gen, ref);
  compare_materials(gen, ref);
  compare_geometry(gen.geometry, ref.geometry);
}

TEST(SpdRingsTeapotTree, RingsMatchesOriginal) { compare_with_reference("rings"); }
TEST(SpdRingsTeapotTree, TeapotMatchesOriginal) { compare_with_reference("teapot"); }
TEST(SpdRingsTeapotTree, TreeMatchesOriginal) { compare_with_reference("tree"); }

// The original programs' documented counts; each scene also has one square (two triangles) or,
// for the teapot, n^2 checker squares.
struct Counts {
  std::uint64_t spheres, cylinders, triangles;
};

// rings: n(n+1)(2n+1)/6 objects of 30 cylinders and 30 spheres, and the back wall.
Counts rings_counts(std::uint64_t n) {
  const std::uint64_t each = 5 * n * (n + 1) * (2 * n + 1);
  return {each, each, 2};
}
// teapot: 32 patches of 2n^2 triangles less the 8n that collapse at the two poles, and n^2
// checker squares. At n = 1 the original writes 56 triangles, but four of them (the spout tip,
// whose four corner control points lie on one line) have no area and the builder drops them.
Counts teapot_counts(std::uint64_t n) {
  const std::uint64_t zero_area = n == 1 ? 4 : 0;
  return {0, 0, 64 * n * n - 8 * n - zero_area + 2 * n * n};
}
// tree: 2^(n+1) - 1 branches, each a cone and a sphere, and the field.
Counts tree_counts(std::uint64_t n) {
  const std::uint64_t branches = (std::uint64_t{2} << n) - 1;
  return {branches, branches, 2};
}

const SpdGenerator& generator(std::string_view name) {
  for (const SpdGenerator& g : spd_generators()) {
    if (g.name == name) return g;
  }
  throw std::logic_error("no generator " + std::string(name));
}

void expect_counts(const std::string& name, Counts (*counts)(std::uint64_t)) {
  for (int n = 1; n <= 3; ++n) {
    const Scene s = make_spd_scene("spd:" + name + "?size=" + std::to_string(n));
    const Counts c = counts(static_cast<std::uint64_t>(n));
    EXPECT_EQ(s.geometry.spheres.size(), c.spheres) << name << " size " << n;
    EXPECT_EQ(s.geometry.cylinders.size(), c.cylinders) << name << " size " << n;
    EXPECT_EQ(s.geometry.triangles.size(), c.triangles) << name << " size " << n;
  }
}

TEST(SpdRingsTeapotTree, RingsCountsFollowSizeFactor) { expect_counts("rings", rings_counts); }
TEST(SpdRingsTeapotTree, TeapotCountsFollowSizeFactor) { expect_counts("teapot", teapot_counts); }
TEST(SpdRingsTeapotTree, TreeCountsFollowSizeFactor) { expect_counts("tree", tree_counts); }

TEST(SpdRingsTeapotTree, DefaultsAreTheOriginals) {
  EXPECT_EQ(generator("rings").default_size, 7);
  EXPECT_EQ(generator("teapot").default_size, 6);
  EXPECT_EQ(generator("tree").default_size, 11);
}

// The largest accepted size must stay under 30M primitives, so that it fits in memory.
TEST(SpdRingsTeapotTree, MaxSizeStaysUnder30MPrimitives) {
  const auto total = [](Counts c) { return c.spheres + c.cylinders + c.triangles; };
  constexpr std::uint64_t kLimit = 30'000'000;
  EXPECT_LT(total(rings_counts(static_cast<std::uint64_t>(generator("rings").max_size))), kLimit);
  EXPECT_LT(total(teapot_counts(static_cast<std::uint64_t>(generator("teapot").max_size))), kLimit);
  EXPECT_LT(total(tree_counts(static_cast<std::uint64_t>(generator("tree").max_size))), kLimit);
  for (const char* name : {"rings", "teapot", "tree"}) {
    EXPECT_GT(generator(name).max_size, generator(name).default_size) << name;
  }
}

TEST(SpdRingsTeapotTree, OutOfRangeSizeIsRefused) {
  for (const char* name : {"rings", "teapot", "tree"}) {
    const std::string base = std::string("spd:") + name + "?size=";
    EXPECT_THROW(make_spd_scene(base + "0"), UsageError) << name;
    EXPECT_THROW(make_spd_scene(base + "-1"), UsageError) << name;
    EXPECT_THROW(make_spd_scene(base + std::to_string(generator(name).max_size + 1)), UsageError) << name;
  }
}

}  // namespace
}  // namespace raylab
