// Both BVHs ("bvh", the 4-wide one, and "bvh2", the binary one) must answer every query exactly as
// brute force does (up to float ties), on scenes built to stress them (test_scenes.h): overlap,
// slivers, sizes over eight orders of magnitude, dense soups, every shape kind, and closed meshes
// with axis-aligned (zero-thickness box) faces. The binary tree's structure is checked in
// bvh_tree_test.cpp, the 4-wide collapse in bvh4_test.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "raylab/accel/brute_force.h"
#include "raylab/accel/bvh.h"
#include "raylab/accel/bvh4.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

constexpr float kRelTol = 1e-5f;

bool near(float a, float b) { return std::fabs(a - b) <= kRelTol * std::max(std::fabs(a), std::fabs(b)); }

bool same_hit(const Hit& a, const Hit& b) { return a.t == b.t && a.prim_id == b.prim_id && a.u == b.u && a.v == b.v; }

// Compares every query of `bvh` with `brute` on `rays`; reports the first few failures in detail.
void compare(const Geometry& g, const Accelerator& bvh, const Accelerator& brute, const std::vector<Ray>& rays,
             Sampler& s) {
  int failures = 0, hits = 0;
  auto fail = [&](const std::string& what, const Ray& r) {
    if (++failures <= 5) {
      ADD_FAILURE() << what << " for ray o=(" << r.origin.x << ", " << r.origin.y << ", " << r.origin.z << ") d=("
                    << r.direction.x << ", " << r.direction.y << ", " << r.direction.z << ") tmin=" << r.tmin;
    }
  };
  TraversalStats bvh_stats;
  int counted = 0;
  for (const Ray& ray : rays) {
    Ray rb = ray, rv = ray;
    Hit hb, hv;
    const bool fb = brute.intersect(rb, hb);
    const bool fv = bvh.intersect(rv, hv);
    if (fb != fv) {
      fail(fb ? "BVH missed a hit" : "BVH found a phantom hit", ray);
      continue;
    }
    if (fb) {
      ++hits;
      if (rb.tmax != hb.t || rv.tmax != hv.t) fail("tmax not shrunk to the hit", ray);
      if (!near(hb.t, hv.t)) fail("t differs: " + std::to_string(hb.t) + " vs " + std::to_string(hv.t), ray);
      if (hb.prim_id != hv.prim_id) {
        // Allowed only for a tie: the BVH's primitive, tested alone, must hit at the same t.
        Ray alone = ray;
        Hit h;
        if (!g.intersect(hv.prim_id, WatertightRay(alone), alone, h) || !near(h.t, hb.t)) {
          fail("different primitive without a tie", ray);
        }
      }
    } else if (rv.tmax != ray.tmax || hv.valid()) {
      fail("a miss changed the ray or the hit", ray);
    }

    // Counted versions: the same answer, bit for bit, plus plausible counts.
    Ray rc = ray;
    Hit hc;
    TraversalStats st;
    const bool fc = bvh.intersect_counted(rc, hc, st);
    if (fc != fv || !same_hit(hc, hv)) fail("intersect_counted differs from intersect", ray);
    if (st.nodes_visited < 1 || st.prim_tests > g.size() || st.hits != (fc ? 1u : 0u)) fail("implausible counts", ray);
    bvh_stats += st;
    if (++counted % 8 == 0) {  // brute force is slow; a sample of rays checks its counts
      TraversalStats sb;
      Ray rbc = ray;
      Hit hbc;
      brute.intersect_counted(rbc, hbc, sb);
      if (sb.prim_tests != g.size() || sb.hits != (fb ? 1u : 0u) || !same_hit(hbc, hb)) {
        fail("brute intersect_counted", ray);
      }
    }

    // Any-hit with a random tmax: occluded iff the closest hit lies before tmax.
    Ray ro = ray;
    ro.tmax = fb ? hb.t * s.uni(0.5f, 1.5f) : (s.rng.next_float() < 0.5f ? kInf : s.uni(0.f, 1e5f));
    if (fb && std::fabs(ro.tmax - hb.t) <= kRelTol * hb.t) continue;  // too close to call
    const bool expected = fb && hb.t < ro.tmax;
    if (bvh.occluded(ro) != expected) fail(expected ? "BVH occluded missed" : "BVH occluded phantom", ro);
    if (brute.occluded(ro) != expected) fail("brute occluded disagrees with brute intersect", ro);
    TraversalStats so;
    if (bvh.occluded_counted(ro, so) != expected || so.hits != (expected ? 1u : 0u)) fail("occluded_counted", ro);
  }
  EXPECT_EQ(failures, 0) << "of " << rays.size() << " rays";
  EXPECT_GT(hits, int(rays.size()) / 10) << "too few hits for a meaningful comparison";
  // The BVH must do much less work than testing everything (brute force: size() tests a ray).
  EXPECT_LT(bvh_stats.prim_tests * 4, std::uint64_t(g.size()) * rays.size());
}

// The structure under test, by factory name: every test of these suites runs for each of them.
class BvhVsBrute : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<Accelerator> make(const Geometry& g, const BvhConfig& config = {}) const {
    AccelConfig accel;
    accel.bvh = config;
    return make_accelerator(GetParam(), g, accel);
  }

  void run_scene(Geometry (*make_scene)(Sampler&), std::uint64_t seed, int ray_count = 10000) const {
    Sampler s(seed);
    const Geometry g = make_scene(s);
    const auto accel = make(g);
    const BruteForce brute(g);
    EXPECT_EQ(accel->info().name, GetParam());
    const Box3 b = accel->bounds(), gb = g.bounds();
    EXPECT_EQ(b.lo, gb.lo);
    EXPECT_EQ(b.hi, gb.hi);
    EXPECT_EQ(accel->info().primitive_count, g.size());
    compare(g, *accel, brute, random_rays(g, s, ray_count), s);
  }
};
class BvhPacket : public BvhVsBrute {};
class BvhEdgeCases : public BvhVsBrute {};

TEST_P(BvhVsBrute, OverlappingSpheresAndTriangles) { run_scene(spheres_and_triangles, 1); }
TEST_P(BvhVsBrute, Slivers) { run_scene(slivers, 2); }
TEST_P(BvhVsBrute, SizesFrom1em4To1e4) { run_scene(sizes_over_eight_decades, 3); }
TEST_P(BvhVsBrute, DenseTriangleSoup) { run_scene(dense_soup, 4); }
TEST_P(BvhVsBrute, EveryShapeKind) { run_scene(every_shape_kind, 5); }
TEST_P(BvhVsBrute, ClosedMeshes) { run_scene(closed_meshes, 6); }

// Rays from inside the closed cubes exactly through shared triangle edges and vertices: the BVH
// must not lose them in its boxes (the cube's faces have zero-thickness boxes).
TEST_P(BvhVsBrute, ClosedMeshRaysThroughEdgesAndVertices) {
  Sampler s(60);
  const Geometry g = closed_meshes(s);
  const auto bvh = make(g);
  const BruteForce brute(g);
  // The two cubes' interiors, shrunk: in the second (rotated) cube, a ball around its centre.
  auto origin_for = [&](std::uint32_t object) {
    return object == 0 ? s.in_box(Vec3(-1.8f), Vec3(1.8f)) : Vec3{7.f, 1.f, -1.f} + s.unit() * s.uni(0.f, 1.4f);
  };
  int failures = 0;
  for (std::uint32_t i = 0; i < g.triangles.size(); i += 3) {
    const Triangle& tri = g.triangles[i];
    const Vec3 p[3] = {tri.p0, tri.p1, tri.p2};
    for (int k = 0; k < 6; ++k) {
      const Vec3 target = k < 3 ? lerp(p[k], p[(k + 1) % 3], s.rng.next_float()) : p[k - 3];
      const Vec3 o = origin_for(g.triangle_objects[i]);
      Ray rv{o, 0.f, target - o}, rb = rv;  // target at t = 1, the only crossing of the surface
      Hit hv, hb;
      const bool fv = bvh->intersect(rv, hv), fb = brute.intersect(rb, hb);
      if (!fv || !fb || std::fabs(hv.t - 1.f) > 1e-4f || std::fabs(hb.t - 1.f) > 1e-4f ||
          !bvh->occluded(Ray{o, 0.f, target - o})) {
        if (++failures <= 5)
          ADD_FAILURE() << "leak through triangle " << i << " feature " << k << " bvh " << fv << " brute " << fb;
      }
    }
  }
  EXPECT_EQ(failures, 0);
}

// Rays lying in the plane of an axis-aligned cube's faces (origin on the plane, direction
// component +0 or -0 across it): slab tests of those faces see 0 * inf or a substituted tiny
// direction, and must not cull them. Planes at +-2, and at 0 where origin * inv_dir is exactly 0.
// Compared with brute force rather than with a fixed answer.
void rays_in_face_planes(const Accelerator& bvh, const Geometry& g, float lo, float hi, std::uint64_t seed) {
  Sampler s(seed);
  const BruteForce brute(g);
  std::vector<Ray> rays;
  for (int i = 0; i < 3000; ++i) {
    const int axis = static_cast<int>(s.rng.next_u32() % 3);
    Ray r;
    r.origin = s.in_box(Vec3(lo - 1.f), Vec3(hi + 1.f));
    r.origin[axis] = s.rng.next_float() < 0.5f ? lo : hi;  // exactly on a face plane (and node planes)
    r.direction = s.unit();
    r.direction[axis] = s.rng.next_float() < 0.5f ? 0.f : -0.f;
    if (i % 4 == 0) r.direction[(axis + 1) % 3] = 0.f;  // along a face edge direction too
    rays.push_back(r);
  }
  compare(g, bvh, brute, rays, s);
}

TEST_P(BvhVsBrute, RaysInFacePlanes) {
  Sampler s(61);
  const Geometry cubes = closed_meshes(s);
  rays_in_face_planes(*make(cubes), cubes, -2.f, 2.f, 62);
  Geometry at_zero;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(at_zero, {2.f, 2.f, 2.f}, 2.f, 6, identity, 0);
  rays_in_face_planes(*make(at_zero), at_zero, 0.f, 4.f, 63);
}

// Build parameters other than the defaults must give the same answers (their trees are checked
// in bvh_tree_test.cpp).
TEST_P(BvhVsBrute, OtherBuildConfigs) {
  for (const BvhConfig config :
       {BvhConfig{2, 1, 1.f, 1.f, 4096}, BvhConfig{64, 32, 0.5f, 2.f, 4096}, BvhConfig{16, 4, 1.f, 1.f, 64}}) {
    Sampler s(7);
    const Geometry g = every_shape_kind(s);
    const BruteForce brute(g);
    compare(g, *make(g, config), brute, random_rays(g, s, 2000), s);
  }
}

TEST_P(BvhPacket, GroupQueriesEqualSingleRays) {
  Sampler s(8);
  const Geometry g = spheres_and_triangles(s);
  const auto bvh = make(g);
  std::vector<Ray> rays = random_rays(g, s, 512);
  std::vector<Ray> singles = rays;
  std::vector<Hit> hits(rays.size()), single_hits(rays.size());
  bvh->intersect(std::span<Ray>(rays), std::span<Hit>(hits));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    bvh->intersect(singles[i], single_hits[i]);
    EXPECT_TRUE(same_hit(hits[i], single_hits[i])) << "ray " << i;
    EXPECT_EQ(rays[i].tmax, singles[i].tmax) << "ray " << i;
  }
  std::vector<std::uint8_t> occ(rays.size(), 7);
  const std::vector<Ray> shadow = random_rays(g, s, 512);
  bvh->occluded(std::span<const Ray>(shadow), std::span<std::uint8_t>(occ));
  for (std::size_t i = 0; i < shadow.size(); ++i) EXPECT_EQ(occ[i], bvh->occluded(shadow[i]) ? 1 : 0) << "ray " << i;
}

TEST_P(BvhEdgeCases, EmptyGeometry) {
  const Geometry g;
  for (const auto& accel : {make(g), make_accelerator("brute", g)}) {
    Ray ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
    Hit hit;
    TraversalStats st;
    EXPECT_FALSE(accel->intersect(ray, hit));
    EXPECT_FALSE(accel->intersect_counted(ray, hit, st));
    EXPECT_FALSE(accel->occluded(ray));
    EXPECT_FALSE(accel->occluded_counted(ray, st));
    EXPECT_FALSE(hit.valid());
    EXPECT_EQ(ray.tmax, kInf);
    EXPECT_TRUE(accel->bounds().empty());
    EXPECT_EQ(accel->info().primitive_count, 0u);
  }
}

TEST_P(BvhEdgeCases, SinglePrimitive) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 3);
  const auto bvh = make(g);
  EXPECT_EQ(bvh->info().leaf_count, 1u);  // the binary tree's shape is checked in bvh_tree_test.cpp
  Ray ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  Hit hit;
  ASSERT_TRUE(bvh->intersect(ray, hit));
  EXPECT_FLOAT_EQ(hit.t, 4.f);
  EXPECT_EQ(hit.prim_id, 0u);
  EXPECT_TRUE(bvh->occluded(Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}, 4.5f}));
  EXPECT_FALSE(bvh->occluded(Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}, 3.5f}));
  EXPECT_FALSE(bvh->occluded(Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, -1.f}}));
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) { return info.param; }
INSTANTIATE_TEST_SUITE_P(Accel, BvhVsBrute, ::testing::Values("bvh", "bvh2"), param_name);
INSTANTIATE_TEST_SUITE_P(Accel, BvhPacket, ::testing::Values("bvh", "bvh2"), param_name);
INSTANTIATE_TEST_SUITE_P(Accel, BvhEdgeCases, ::testing::Values("bvh", "bvh2"), param_name);

TEST(AccelFactory, NamesAndUnknownName) {
  const auto names = accelerator_names();
  for (const char* name : {"bvh", "bvh2", "brute"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  Geometry g;
  g.add(Sphere{}, 0);
  EXPECT_EQ(make_accelerator("bvh", g)->info().name, "bvh");
  EXPECT_EQ(make_accelerator("bvh2", g)->info().name, "bvh2");
  EXPECT_EQ(make_accelerator("brute", g)->info().name, "brute");
  // "bvh" is the 4-wide tree, "bvh2" the binary one.
  EXPECT_NE(dynamic_cast<const Bvh4*>(make_accelerator("bvh", g).get()), nullptr);
  EXPECT_NE(dynamic_cast<const Bvh*>(make_accelerator("bvh2", g).get()), nullptr);
  try {
    make_accelerator("nope", g);
    FAIL() << "no exception for an unknown name";
  } catch (const UsageError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("nope"), std::string::npos) << msg;
    EXPECT_NE(msg.find("bvh"), std::string::npos) << msg;
    EXPECT_NE(msg.find("bvh2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("brute"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace raylab
