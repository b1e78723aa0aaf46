// Every structure, with every wrap mode, must answer every query exactly as brute force does (up
// to float ties), on the stress scenes of test_scenes.h: overlap, slivers, sizes over eight
// orders of magnitude, dense soups, every shape kind, closed meshes with axis-aligned faces, rays
// through shared edges and vertices and rays lying in face planes. The scenes' objects (one per
// shape kind, one per cube) become wrapped meshes under --wrap box and --wrap sphere.

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/factory.h"
#include "raylab/accel/two_level.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

using Param = std::tuple<std::string, WrapMode>;

class AccelVsBrute : public ::testing::TestWithParam<Param> {
 protected:
  std::unique_ptr<Accelerator> make(const Geometry& g) const {
    SceneAccelOptions options;
    options.top = std::get<0>(GetParam());
    options.wrap = std::get<1>(GetParam());
    return make_scene_accelerator(g, {}, {}, options);
  }

  void run_scene(Geometry (*make_scene)(Sampler&), std::uint64_t seed, int ray_count = 6000) const {
    Sampler s(seed);
    const Geometry g = make_scene(s);
    const auto accel = make(g);
    const BruteForce brute(g);
    EXPECT_EQ(accel->info().name.rfind(std::get<0>(GetParam()), 0), 0u) << accel->info().name;
    const Box3 b = accel->bounds(), gb = g.bounds();
    EXPECT_TRUE(b.contains(gb.lo) && b.contains(gb.hi)) << "the structure's bounds must hold the scene";
    EXPECT_EQ(accel->info().primitive_count, g.size());
    compare(g, *accel, brute, random_rays(g, s, ray_count), s);
  }
};

TEST_P(AccelVsBrute, OverlappingSpheresAndTriangles) { run_scene(spheres_and_triangles, 1); }
TEST_P(AccelVsBrute, Slivers) { run_scene(slivers, 2); }
TEST_P(AccelVsBrute, SizesFrom1em4To1e4) { run_scene(sizes_over_eight_decades, 3); }
TEST_P(AccelVsBrute, DenseTriangleSoup) { run_scene(dense_soup, 4); }
TEST_P(AccelVsBrute, EveryShapeKind) { run_scene(every_shape_kind, 5); }
TEST_P(AccelVsBrute, ClosedMeshes) { run_scene(closed_meshes, 6); }

// Rays from inside the closed cubes exactly through shared triangle edges and vertices: no
// structure may lose them in its cells or boxes (the cube's faces have zero-thickness boxes).
TEST_P(AccelVsBrute, ClosedMeshRaysThroughEdgesAndVertices) {
  Sampler s(60);
  const Geometry g = closed_meshes(s);
  const auto accel = make(g);
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
      const bool fv = accel->intersect(rv, hv), fb = brute.intersect(rb, hb);
      if (!fv || !fb || std::fabs(hv.t - 1.f) > 1e-4f || std::fabs(hb.t - 1.f) > 1e-4f ||
          !accel->occluded(Ray{o, 0.f, target - o})) {
        if (++failures <= 5)
          ADD_FAILURE() << "leak through triangle " << i << " feature " << k << " accel " << fv << " brute " << fb;
      }
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST_P(AccelVsBrute, RaysInFacePlanes) {
  Sampler s(61);
  const Geometry cubes = closed_meshes(s);
  rays_in_face_planes(*make(cubes), cubes, -2.f, 2.f, 62);
  Geometry at_zero;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(at_zero, {2.f, 2.f, 2.f}, 2.f, 6, identity, 0);
  rays_in_face_planes(*make(at_zero), at_zero, 0.f, 4.f, 63);
}

TEST_P(AccelVsBrute, EmptyGeometry) {
  const Geometry g;
  const auto accel = make(g);
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

TEST_P(AccelVsBrute, OnePrimitive) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 3);
  const auto accel = make(g);
  Ray ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  Hit hit;
  ASSERT_TRUE(accel->intersect(ray, hit));
  EXPECT_FLOAT_EQ(hit.t, 4.f);
  EXPECT_EQ(hit.prim_id, 0u);
  EXPECT_TRUE(accel->occluded(Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}, 4.5f}));
  EXPECT_FALSE(accel->occluded(Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}, 3.5f}));
  EXPECT_FALSE(accel->occluded(Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, -1.f}}));
  EXPECT_FALSE(accel->occluded(Ray{{0.f, 0.f, 10.f}, 0.f, {0.f, 0.f, 1.f}}));  // behind the origin
  EXPECT_EQ(ray.tmax, hit.t);
  Ray inside{{0.f, 0.f, 0.f}, 5.f, {0.f, 0.f, 1.f}};  // tmin past the near side: the far side
  ASSERT_TRUE(accel->intersect(inside, hit));
  EXPECT_FLOAT_EQ(hit.t, 6.f);
  Ray past{{0.f, 0.f, 0.f}, 6.5f, {0.f, 0.f, 1.f}};  // tmin beyond the sphere
  Hit none;
  EXPECT_FALSE(accel->intersect(past, none));
}

std::string param_name(const ::testing::TestParamInfo<Param>& info) {
  return std::get<0>(info.param) + "_wrap_" + std::string(wrap_mode_name(std::get<1>(info.param)));
}

INSTANTIATE_TEST_SUITE_P(Accel, AccelVsBrute,
                         ::testing::Combine(::testing::Values("bvh", "bvh2", "grid", "grid2", "octree", "irregular"),
                                            ::testing::Values(WrapMode::kNone, WrapMode::kBox, WrapMode::kSphere)),
                         param_name);

// A structure built over some of the primitives (every third, of every shape kind) answers as
// brute force over the same ones, and never with a primitive outside them.
class AccelOverSubset : public ::testing::TestWithParam<std::string> {};

TEST_P(AccelOverSubset, AnswersAsBruteForceOverTheSameIds) {
  Sampler s(19);
  const Geometry g = every_shape_kind(s);
  const std::vector<std::uint32_t> ids = every_third_id(g);
  const auto accel = make_accelerator(GetParam(), g, ids);
  const BruteForce brute(g, ids);
  EXPECT_EQ(accel->info().primitive_count, ids.size());
  int failures = 0, hits = 0;
  for (const Ray& ray : random_rays(g, s, 2000)) {
    const auto [rb, hb, fb, rv, hv, fv] = both_hits(brute, *accel, ray);
    std::string wrong = closest_hit_disagreement(g, ray, fb, hb, fv, hv, rv);
    if (wrong.empty() && fv && !std::binary_search(ids.begin(), ids.end(), hv.prim_id))
      wrong = "a primitive not built over";
    if (wrong.empty() && accel->occluded(ray) != fb) wrong = "occluded disagrees";
    if (!wrong.empty() && ++failures <= 5) ADD_FAILURE() << wrong << " for " << describe(ray);
    hits += fb ? 1 : 0;
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(hits, 200);
}

INSTANTIATE_TEST_SUITE_P(Accel, AccelOverSubset,
                         ::testing::Values("bvh", "bvh2", "grid", "grid2", "octree", "irregular"));

}  // namespace
}  // namespace raylab
