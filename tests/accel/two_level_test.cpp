// Instancing and wrappers: a two-level structure over instances must see exactly the world that
// copying every instance into the scene (bake_instances) gives, store the prototype once, shade
// instance hits as the copies shade, and pay one wrapper test for a ray that misses a wrapped mesh.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/two_level.h"
#include "raylab/core/error.h"
#include "raylab/scene/scene.h"
#include "raylab/scene/scene_merge.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

// A scene of a few world-space triangles plus two prototypes (a closed cube mesh and a triangle
// soup) placed 12 times under rotations, non-uniform scales, a mirror and translations.
Scene instanced_scene() {
  Sampler s(91);
  Scene scene;
  const std::uint32_t m = scene.add_material({});
  scene.add_object("floor", m);
  for (int i = 0; i < 20; ++i) scene.geometry.add(random_triangle(s, s.in_box(Vec3(-20.f), Vec3(20.f)), 2.f), 0);
  Geometry cube, soup;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(cube, {0.f, 0.f, 0.f}, 1.f, 4, identity, 0);
  for (int i = 0; i < 200; ++i) soup.add(random_triangle(s, s.in_box(Vec3(-2.f), Vec3(2.f)), 0.5f), 0);
  scene.prototypes = {cube, soup};
  for (int i = 0; i < 12; ++i) {
    const std::uint32_t first_object = scene.add_object("instance " + std::to_string(i), m);
    Transform t = Transform::translate(s.uni(-15.f, 15.f), s.uni(-15.f, 15.f), s.uni(-15.f, 15.f)) *
                  Transform::rotate(s.uni(0.f, 360.f), s.unit());
    if (i % 3 == 1) t = t * Transform::scale(s.uni(0.5f, 3.f), s.uni(0.5f, 3.f), s.uni(0.5f, 3.f));
    if (i % 4 == 2) t = t * Transform::scale(-1.0, 1.0, 1.0);  // a mirror
    scene.add_instance(static_cast<std::uint32_t>(i % 2), t, first_object);
  }
  return scene;
}

// Rays aimed at random points of random primitives of the baked copy, from around the scene.
std::vector<Ray> rays_at(const Geometry& baked, Sampler& s, int count) { return random_rays(baked, s, count); }

std::unique_ptr<Accelerator> make(const Scene& scene, const std::string& top, const std::string& bottom,
                                  WrapMode wrap) {
  SceneAccelOptions options;
  options.top = top;
  options.bottom = bottom;
  options.wrap = wrap;
  return make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, options);
}

TEST(TwoLevel, InstancesSeeTheWorldOfTheirBakedCopies) {
  const Scene scene = instanced_scene();
  Scene baked = scene;
  bake_instances(baked);
  ASSERT_EQ(baked.geometry.size(), scene.primitive_count());
  Sampler s(92);
  const std::vector<Ray> rays = rays_at(baked.geometry, s, 2500);
  const std::vector<Hit> expected = closest_hits(BruteForce(baked.geometry), rays);
  for (const char* top : {"bvh", "grid", "grid2", "octree", "irregular"}) {
    for (WrapMode wrap : {WrapMode::kNone, WrapMode::kBox, WrapMode::kSphere}) {
      const auto accel = make(scene, top, "bvh", wrap);
      int disagreements = 0, hits = 0;
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray& ray = rays[i];
        const Hit& hb = expected[i];
        const bool fb = hb.valid();
        const auto [a, ha, fa] = closest_hit(*accel, ray);
        hits += fb;
        // The instance is hit in its own space, so t may differ in the last bits, and a ray
        // grazing an edge may fall on the neighbouring triangle (same t) — or, rarely, just miss.
        const bool same = fa == fb && (!fa || (std::fabs(ha.t - hb.t) <= 1e-4f * hb.t &&
                                               (ha.prim_id == hb.prim_id || std::fabs(ha.t - hb.t) <= 1e-5f * hb.t)));
        disagreements += !same;
        const bool occluded = accel->occluded(ray);
        disagreements += occluded != fb;
      }
      EXPECT_GT(hits, 600);
      EXPECT_LE(disagreements, 4) << top << " wrap " << wrap_mode_name(wrap) << " of " << rays.size() << " rays";
    }
  }
}

// Every structure at either level and every wrapper agree exactly with brute force at both
// levels: the same arithmetic per primitive, so the same hits bit for bit, ties included.
TEST(TwoLevel, AnyStructureAtEitherLevelGivesTheSameHits) {
  const Scene scene = instanced_scene();
  Scene baked = scene;
  bake_instances(baked);
  Sampler s(93);
  const std::vector<Ray> rays = rays_at(baked.geometry, s, 1000);
  const std::vector<Hit> expected = closest_hits(*make(scene, "brute", "brute", WrapMode::kNone), rays);
  for (const char* top : {"bvh", "bvh2", "grid", "grid2", "octree", "irregular"}) {
    for (const char* bottom : {"bvh", "grid", "grid2", "octree", "irregular", "brute"}) {
      for (WrapMode wrap : {WrapMode::kNone, WrapMode::kBox, WrapMode::kSphere}) {
        const auto accel = make(scene, top, bottom, wrap);
        int failures = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
          const Ray& ray = rays[i];
          const Hit& hb = expected[i];
          const bool fb = hb.valid();
          const auto [a, ha, fa] = closest_hit(*accel, ray);
          failures += fa != fb || ha.t != hb.t || ha.prim_id != hb.prim_id || a.tmax != (fb ? hb.t : ray.tmax);
          failures += accel->occluded(ray) != fb;
        }
        EXPECT_EQ(failures, 0) << top << "/" << bottom << " wrap " << wrap_mode_name(wrap);
      }
    }
  }
}

TEST(TwoLevel, InstanceHitsShadeLikeTheirCopies) {
  const Scene scene = instanced_scene();
  Scene baked = scene;
  bake_instances(baked);
  const auto accel = make(scene, "bvh", "bvh", WrapMode::kBox);
  const BruteForce reference(baked.geometry);
  Sampler s(94);
  int compared = 0;
  for (const Ray& ray : rays_at(baked.geometry, s, 2000)) {
    Ray a = ray, b = ray;
    Hit ha, hb;
    if (!accel->intersect(a, ha) || !reference.intersect(b, hb) || ha.prim_id != hb.prim_id) continue;
    const SurfaceInteraction si = surface_at(scene, ray, ha), sb = surface_at(baked, ray, hb);
    const float scale = 1.f + length(sb.position);
    EXPECT_LT(length(si.position - sb.position), 1e-4f * scale);
    EXPECT_GT(dot(si.geometric_normal, sb.geometric_normal), 0.9999f);
    EXPECT_EQ(si.front_face, sb.front_face);
    EXPECT_EQ(si.object_id, sb.object_id);
    EXPECT_EQ(&scene.material_of(ha.prim_id), &scene.materials[scene.objects[sb.object_id].material]);
    ++compared;
  }
  EXPECT_GT(compared, 500);
}

TEST(TwoLevel, PrototypesAreStoredOnce) {
  Scene scene;
  scene.add_object("o", scene.add_material({}));
  Geometry mesh;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(mesh, {0.f, 0.f, 0.f}, 1.f, 20, identity, 0);  // 4800 triangles
  scene.prototypes = {mesh};
  for (int i = 0; i < 100; ++i) scene.add_instance(0, Transform::translate(3.0 * i, 0, 0), 0);
  const auto instanced = make(scene, "bvh", "bvh", WrapMode::kBox);
  Scene baked = scene;
  bake_instances(baked);
  const auto flat = make(baked, "bvh", "bvh", WrapMode::kNone);
  EXPECT_EQ(instanced->info().primitive_count, 480000u);
  // One prototype structure plus 100 small items, against 100 copies of everything.
  EXPECT_LT(instanced->info().memory_bytes * 20, flat->info().memory_bytes + baked.memory_bytes());
}

TEST(TwoLevel, AMissedWrapperCostsOneTest) {
  Geometry g;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(g, {0.f, 0.f, 0.f}, 1.f, 8, identity, 0);
  g.add(Sphere{{10.f, 0.f, 0.f}, 1.f}, 1);  // a single primitive: directly in the top level
  for (WrapMode wrap : {WrapMode::kBox, WrapMode::kSphere}) {
    SceneAccelOptions options;
    options.top = "brute";  // the top level tests every item: the mesh's wrapper and the sphere
    options.bottom = "brute";
    options.wrap = wrap;
    const auto accel = make_scene_accelerator(g, {}, {}, options);
    Ray ray{{0.f, 5.f, -10.f}, 0.f, {0.f, 0.f, 1.f}};  // passes above the cube and the sphere
    Hit hit;
    TraversalStats st;
    EXPECT_FALSE(accel->intersect_counted(ray, hit, st));
    EXPECT_EQ(st.volume_tests, 1u) << wrap_mode_name(wrap);
    EXPECT_EQ(st.prim_tests, 1u) << "only the sphere";
    Ray through{{0.f, 0.f, -10.f}, 0.f, {0.f, 0.f, 1.f}};
    TraversalStats st2;
    ASSERT_TRUE(accel->intersect_counted(through, hit, st2));
    EXPECT_FLOAT_EQ(hit.t, 9.f);
    EXPECT_EQ(st2.prim_tests, 1u + g.triangles.size()) << "the sphere, then every triangle of the mesh";
  }
}

TEST(TwoLevel, WrapModeNames) {
  for (WrapMode m : {WrapMode::kNone, WrapMode::kBox, WrapMode::kSphere}) {
    EXPECT_EQ(parse_wrap_mode(wrap_mode_name(m)), m);
  }
  EXPECT_THROW(parse_wrap_mode("cylinder"), UsageError);
}

}  // namespace
}  // namespace raylab
