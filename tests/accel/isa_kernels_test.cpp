// The kernels of every instruction set this machine can run (raylab/core/isa.h): each agrees
// with brute force, and every set answers bit for bit as the baseline set does, single rays and
// packets, on the same structure built under each.

#include <gtest/gtest.h>

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/bvh.h"
#include "raylab/accel/factory.h"
#include "raylab/accel/irregular_grid.h"
#include "raylab/accel/octree.h"
#include "raylab/accel/two_level_grid.h"
#include "raylab/accel/uniform_grid.h"
#include "raylab/accel/wide_bvh.h"
#include "raylab/core/isa.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

// The structures with kernels per instruction set.
const std::vector<std::string> kStructures = {"bvh",  "bvh2",  "bvh4",   "bvh8",     "bvh16",
                                              "grid", "grid2", "octree", "irregular"};

// Every query's answer for `rays`: closest hits (with the shrunk tmax), any-hit verdicts, then
// the same as packets.
struct Answers {
  std::vector<Hit> hits;
  std::vector<float> tmax;
  std::vector<std::uint8_t> occluded;
  std::vector<Hit> packet_hits;
  std::vector<std::uint8_t> packet_occluded;
};

Answers answers(const Accelerator& accel, const std::vector<Ray>& rays) {
  Answers a;
  for (Ray r : rays) {
    Hit h;
    accel.intersect(r, h);
    a.hits.push_back(h);
    a.tmax.push_back(r.tmax);
    a.occluded.push_back(accel.occluded(r) ? 1 : 0);
  }
  std::vector<Ray> packet = rays;
  a.packet_hits.resize(rays.size());
  accel.intersect(std::span<Ray>(packet), std::span<Hit>(a.packet_hits));
  a.packet_occluded.resize(rays.size());
  accel.occluded(std::span<const Ray>(rays), std::span<std::uint8_t>(a.packet_occluded));
  return a;
}

// The set a structure runs (every structure of kStructures has kernels per set).
template <class... Structures>
std::optional<Isa> kernel_isa_among(const Accelerator& accel) {
  std::optional<Isa> isa;
  ((isa = isa ? isa : [&]() -> std::optional<Isa> {
     if (auto* s = dynamic_cast<const Structures*>(&accel)) return s->kernel_isa();
     return std::nullopt;
   }()),
   ...);
  return isa;
}

std::optional<Isa> kernel_isa_of(const Accelerator& accel) {
  return kernel_isa_among<WideBvh<4>, WideBvh<8>, WideBvh<16>, Bvh, UniformGrid, TwoLevelGrid, Octree, IrregularGrid>(
      accel);
}

class IsaKernels : public ::testing::TestWithParam<std::string> {};

TEST_P(IsaKernels, EverySetAgreesWithBruteForceAndWithBaselineBitForBit) {
  for (Geometry (*scene)(Sampler&) : {every_shape_kind, closed_meshes, spheres_and_triangles}) {
    Sampler s(31);
    const Geometry g = scene(s);
    const BruteForce brute(g);
    const std::vector<Ray> rays = random_rays(g, s, 1500);
    // The lowest set this build has: baseline, unless the library was built for a higher
    // level without dispatch (RAYLAB_ARCH=x86-64-v3 and RAYLAB_ISA_DISPATCH=OFF).
    std::unique_ptr<Accelerator> baseline;
    {
      const ScopedIsa isa(usable_isas().front());
      baseline = make_accelerator(GetParam(), g);
    }
    const Answers expected = answers(*baseline, rays);
    for (Isa isa : usable_isas()) {
      SCOPED_TRACE(isa_name(isa));
      std::unique_ptr<Accelerator> accel;
      {
        const ScopedIsa scoped(isa);
        accel = make_accelerator(GetParam(), g);
      }
      EXPECT_EQ(kernel_isa_of(*accel), isa);
      Sampler cs(5);
      compare(g, *accel, brute, rays, cs);
      const Answers got = answers(*accel, rays);
      for (std::size_t i = 0; i < rays.size(); ++i) {
        ASSERT_TRUE(same_hit(got.hits[i], expected.hits[i])) << describe(rays[i]);
        ASSERT_EQ(got.tmax[i], expected.tmax[i]) << describe(rays[i]);
        ASSERT_EQ(got.occluded[i], expected.occluded[i]) << describe(rays[i]);
        ASSERT_TRUE(same_hit(got.packet_hits[i], expected.packet_hits[i])) << describe(rays[i]);
        ASSERT_EQ(got.packet_occluded[i], expected.packet_occluded[i]) << describe(rays[i]);
      }
    }
  }
}

// Triangles some thousands of units from the world's origin and rays from among them aimed at
// their corners: a ray grazes the boxes whose corner or edge a vertex lies on, and the origin
// times the inverse direction is thousands of times the distance to them. A box test in fused
// form (plane * inverse - origin * inverse in one FMA, as Embree's; measured and not kept,
// docs/performance.md) subtracts that product last, so one rounding in it is a thousandfold
// error in the distance unless it is rounded to the safe side: it fails here. Every set must
// find the hits brute force finds.
TEST_P(IsaKernels, RaysGrazingCornersFarFromTheWorldOrigin) {
  Sampler s(47);
  const Vec3 centre{3000.f, -5000.f, 4000.f};
  Geometry g;
  for (int i = 0; i < 600; ++i)
    g.add(random_triangle(s, centre + s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.3f, 3.f)), 0);
  const BruteForce brute(g);
  std::vector<Ray> rays;
  for (int i = 0; i < 3000; ++i) {
    const Triangle& t = g.triangles[s.rng.next_u32() % g.triangles.size()];
    const Vec3 corner = i % 3 == 0 ? t.p0 : i % 3 == 1 ? t.p1 : t.p2;
    Ray r;
    r.origin = centre + s.in_box(Vec3(-15.f), Vec3(15.f));
    r.direction = corner - r.origin;
    rays.push_back(r);
  }
  for (Isa isa : usable_isas()) {
    SCOPED_TRACE(isa_name(isa));
    std::unique_ptr<Accelerator> accel;
    {
      const ScopedIsa scoped(isa);
      accel = make_accelerator(GetParam(), g);
    }
    Sampler cs(9);
    compare(g, *accel, brute, rays, cs);
  }
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) { return info.param; }
INSTANTIATE_TEST_SUITE_P(Accel, IsaKernels, ::testing::ValuesIn(kStructures), param_name);

TEST(Isa, NamesRoundTrip) {
  for (Isa isa : {Isa::baseline, Isa::avx2, Isa::avx512}) EXPECT_EQ(parse_isa(isa_name(isa)), isa);
  EXPECT_FALSE(parse_isa("sse4").has_value());
  EXPECT_FALSE(parse_isa("").has_value());
  EXPECT_FALSE(parse_isa("AVX2").has_value());
}

TEST(Isa, UsableSetsAreBuiltAndTheWidestIsTheDefault) {
  const std::vector<Isa> built = built_isas(), usable = usable_isas();
  ASSERT_FALSE(usable.empty());
  for (Isa isa : usable) {
    EXPECT_NE(std::find(built.begin(), built.end(), isa), built.end()) << isa_name(isa);
    EXPECT_EQ(isa_unusable_reason(isa), "") << isa_name(isa);
  }
  // The widest usable set is the default (RAYLAB_ISA is not set in the test environment).
  EXPECT_EQ(active_isa(), usable.back());
}

TEST(Isa, ScopedIsaRestoresAndUnusableSetsAreRefused) {
  const Isa before = active_isa();
  for (Isa isa : usable_isas()) {
    const ScopedIsa scoped(isa);
    EXPECT_EQ(active_isa(), isa);
  }
  EXPECT_EQ(active_isa(), before);
  for (Isa isa : {Isa::baseline, Isa::avx2, Isa::avx512}) {
    const std::string reason = isa_unusable_reason(isa);
    if (reason.empty()) continue;
    try {
      set_isa(isa);
      FAIL() << "set_isa accepted " << isa_name(isa);
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
    EXPECT_EQ(active_isa(), before);
  }
}

TEST(Isa, DefaultBvhWidthFollowsTheSet) {
  Geometry g;
  g.add(Sphere{}, 0);
  for (Isa isa : usable_isas()) {
    const ScopedIsa scoped(isa);
    const auto bvh = make_accelerator("bvh", g);
    EXPECT_EQ(bvh->info().name, "bvh");
    if (native_box_width(isa) == 16) {
      EXPECT_NE(dynamic_cast<const WideBvh<16>*>(bvh.get()), nullptr);
    } else {
      EXPECT_NE(dynamic_cast<const WideBvh<8>*>(bvh.get()), nullptr);
    }
  }
}

}  // namespace
}  // namespace raylab
