// The packet path of the uniform samplers (RenderOptions::packets) must give the image of the
// single-ray path bit for bit, with the same ray counts, on every structure; and it must really
// send packets: primary rays in groups of 16, shadow rays toward point lights as any-hit groups.

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "../test_paths.h"
#include "raylab/accel/embree_accel.h"
#include "raylab/accel/factory.h"
#include "raylab/accel/two_level.h"
#include "raylab/io/scene_loader.h"
#include "raylab/render/renderer.h"
#include "raylab/scene/builtin_scenes.h"

namespace raylab {
namespace {

int kind(RayKind k) { return static_cast<int>(k); }

// Forwards every query to another structure and records how it was asked: single rays, or
// packets of which sizes. Packets go on to the inner structure's own packet entry points.
class RecordingAccelerator : public Accelerator {
 public:
  explicit RecordingAccelerator(const Accelerator& inner) : m_inner(inner) {}

  Box3 bounds() const override { return m_inner.bounds(); }
  bool intersect(Ray& ray, Hit& hit) const override {
    ++single_intersects;
    return m_inner.intersect(ray, hit);
  }
  bool occluded(const Ray& ray) const override {
    ++single_occludeds;
    return m_inner.occluded(ray);
  }
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const override {
    ++single_intersects;
    return m_inner.intersect_counted(ray, hit, stats);
  }
  bool occluded_counted(const Ray& ray, TraversalStats& stats) const override {
    ++single_occludeds;
    return m_inner.occluded_counted(ray, stats);
  }
  void intersect(std::span<Ray> rays, std::span<Hit> hits) const override {
    record(intersect_packets, rays.size());
    m_inner.intersect(rays, hits);
  }
  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> result) const override {
    record(occluded_packets, rays.size());
    m_inner.occluded(rays, result);
  }
  AccelInfo info() const override { return m_inner.info(); }

  /// Rays sent in packets (sum of the sizes).
  static std::uint64_t rays_in(const std::map<std::size_t, std::uint64_t>& packets) {
    std::uint64_t n = 0;
    for (const auto& [size, count] : packets) n += size * count;
    return n;
  }

  mutable std::atomic<std::uint64_t> single_intersects{0};
  mutable std::atomic<std::uint64_t> single_occludeds{0};
  mutable std::map<std::size_t, std::uint64_t> intersect_packets;  // size -> calls
  mutable std::map<std::size_t, std::uint64_t> occluded_packets;   // size -> calls

 private:
  void record(std::map<std::size_t, std::uint64_t>& packets, std::size_t size) const {
    const std::lock_guard<std::mutex> lock(m_mutex);
    ++packets[size];
  }

  const Accelerator& m_inner;
  mutable std::mutex m_mutex;
};

struct Rendered {
  Film film;
  RenderStats stats;
};

Rendered render_with(const Scene& scene, const Accelerator& accel, bool packets, int threads, bool count = false) {
  Film film(scene.settings.width, scene.settings.height);
  RenderOptions options;
  options.threads = threads;
  options.packets = packets;
  options.count_traversal = count;
  const RenderResult r = render(scene, accel, film, options);
  return {std::move(film), r.stats};
}

bool same_bits(const Film& a, const Film& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Color)) == 0;
}

void expect_same_counts(const RenderStats& a, const RenderStats& b) {
  for (int k = 0; k < kind(RayKind::kCount); ++k) {
    EXPECT_EQ(a.rays[k], b.rays[k]) << ray_kind_name(static_cast<RayKind>(k));
    EXPECT_EQ(a.ray_hits[k], b.ray_hits[k]) << ray_kind_name(static_cast<RayKind>(k));
  }
  EXPECT_EQ(a.traversal.nodes_visited, b.traversal.nodes_visited);
  EXPECT_EQ(a.traversal.prim_tests, b.traversal.prim_tests);
  EXPECT_EQ(a.traversal.hits, b.traversal.hits);
}

Scene sized(Scene s, int width, int height) {
  s.settings.width = width;
  s.settings.height = height;
  return s;
}

// Several point lights (one with fall-off, one below the floor that no lit surface faces), a
// directional light, single-sample sphere lights (1 and 2 samples both round to one), a sampled
// quad light, and mirror and glass spheres over a matte floor.
Scene many_lights_scene() {
  Scene s;
  s.camera.from = {0.f, 2.f, 6.f};
  s.camera.at = {0.f, 0.5f, 0.f};
  s.camera.vfov_degrees = 50.f;
  s.settings.max_depth = 4;
  s.settings.ambient = {0.05f, 0.05f, 0.05f};
  Material floor;
  floor.ks = 0.3f;
  s.geometry.add(Quad{{-5.f, 0.f, -5.f}, {0.f, 0.f, 10.f}, {10.f, 0.f, 0.f}},
                 s.add_object("floor", s.add_material(floor)));
  Material mirror;
  mirror.kd = 0.2f;
  mirror.reflectivity = 0.7f;
  s.geometry.add(Sphere{{-1.2f, 0.8f, 0.f}, 0.8f}, s.add_object("mirror", s.add_material(mirror)));
  Material glass;
  glass.kd = 0.05f;
  glass.transmittance = 0.9f;
  glass.ior = 1.5f;
  s.geometry.add(Sphere{{1.1f, 0.7f, 0.6f}, 0.7f}, s.add_object("glass", s.add_material(glass)));
  Material matte;
  matte.color = {0.8f, 0.3f, 0.2f};
  matte.ks = 0.5f;
  s.geometry.add(Sphere{{0.2f, 0.4f, -1.5f}, 0.4f}, s.add_object("matte", s.add_material(matte)));

  auto point = [&](Vec3 p, float power, bool falloff) {
    Light l;
    l.position = p;
    l.intensity = {power, power, power};
    l.falloff = falloff;
    s.lights.push_back(l);
  };
  point({3.f, 5.f, 4.f}, 0.6f, false);
  point({-4.f, 3.f, 1.f}, 8.f, true);
  point({0.f, -3.f, 0.f}, 1.f, false);
  Light sun;
  sun.kind = Light::Kind::kDirectional;
  sun.direction = {0.3f, -1.f, -0.4f};
  sun.intensity = {0.4f, 0.4f, 0.35f};
  s.lights.push_back(sun);
  for (int samples : {1, 2}) {
    Light ball;
    ball.kind = Light::Kind::kSphere;
    ball.position = {samples == 1 ? 2.f : -2.f, 4.f, -1.f};
    ball.radius = 0.3f;
    ball.samples = samples;
    ball.intensity = {0.2f, 0.2f, 0.2f};
    s.lights.push_back(ball);
  }
  Light panel;
  panel.kind = Light::Kind::kQuad;
  panel.position = {-0.5f, 4.f, -0.5f};
  panel.edge_u = {1.f, 0.f, 0.f};
  panel.edge_v = {0.f, 0.f, 1.f};
  panel.samples = 4;
  panel.intensity = {0.3f, 0.3f, 0.3f};
  s.lights.push_back(panel);
  return s;
}

Scene mesh_scene() {
  Scene s = load_mesh(raylab::test::source_dir() + "/scenes/meshes/torus.obj");
  fit_camera_and_lights(s);
  return s;
}

// Image sizes that are not multiples of 4 or of the 16-pixel tile: edge blocks and packets are
// partial there.
struct NamedScene {
  std::string name;
  Scene scene;
};

std::vector<NamedScene> test_scenes() {
  std::vector<NamedScene> out;
  out.push_back({"demo", sized(make_demo_scene(), 26, 15)});
  out.push_back({"torus mesh", sized(mesh_scene(), 22, 17)});
  out.push_back({"spd:balls", sized(load_scene("spd:balls?size=1"), 18, 18)});
  out.push_back({"many lights", sized(many_lights_scene(), 25, 14)});
  return out;
}

std::vector<std::string> test_accelerators() {
  std::vector<std::string> names{"bvh", "grid", "brute"};
  if (embree_available()) names.push_back("embree");
  return names;
}

// The main property: packets on and off give the same bits and the same ray counts, for every
// scene, structure, sample count and thread count. (Brute force skips the demo, whose torus
// makes it take seconds; it still sees a mesh in the torus scene.)
TEST(Packets, ImageAndRayCountsMatchSingleRays) {
  for (NamedScene& named : test_scenes()) {
    for (const std::string& name : test_accelerators()) {
      if (name == "brute" && named.name == "demo") continue;
      const std::unique_ptr<Accelerator> accel = make_accelerator(name, named.scene.geometry);
      for (int spp : {1, 4}) {
        named.scene.settings.spp = spp;
        for (int threads : {1, 2}) {
          SCOPED_TRACE(named.name + ", " + name + ", spp " + std::to_string(spp) + ", threads " +
                       std::to_string(threads));
          const Rendered single = render_with(named.scene, *accel, false, threads);
          const Rendered packed = render_with(named.scene, *accel, true, threads);
          EXPECT_TRUE(same_bits(single.film, packed.film));
          expect_same_counts(single.stats, packed.stats);
          EXPECT_GT(packed.stats.rays[kind(RayKind::kShadow)], 0u);
        }
      }
    }
  }
}

// Sample counts whose packets span blocks (3 spp: 12-ray blocks), pixels (9 spp: one row at a
// time) or stay within a pixel (16 and 25 spp); samplers other than the default; and filters
// wider than a pixel, whose sums depend on the order samples are added in.
TEST(Packets, OtherSampleCountsSamplersAndFiltersMatchSingleRays) {
  Scene scene = sized(many_lights_scene(), 13, 11);
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  struct Case {
    int spp;
    std::string sampler, filter;
  };
  for (const Case& c : std::vector<Case>{{3, "random", "box"},
                                         {9, "jittered", "box"},
                                         {16, "cmj", "box"},
                                         {25, "jittered", "box"},
                                         {1, "center", "gaussian"},
                                         {4, "jittered", "tent"},
                                         {2, "sobol", "mitchell"}}) {
    SCOPED_TRACE(c.sampler + " " + std::to_string(c.spp) + " " + c.filter);
    scene.settings.spp = c.spp;
    scene.settings.sampler = c.sampler;
    scene.settings.filter = c.filter;
    scene.settings.filter_radius = 0.f;  // the filter's own default
    const Rendered single = render_with(scene, *accel, false, 2);
    const Rendered packed = render_with(scene, *accel, true, 2);
    EXPECT_TRUE(same_bits(single.film, packed.film));
    expect_same_counts(single.stats, packed.stats);
  }
}

// Instanced meshes (a two-level structure) are traced by the same packet path.
TEST(Packets, InstancedSceneMatchesSingleRays) {
  Scene scene = sized(load_scene(raylab::test::source_dir() + "/scenes/instances.json"), 20, 12);
  scene.settings.spp = 1;
  SceneAccelOptions structure;
  structure.top = "bvh";
  const std::unique_ptr<Accelerator> accel =
      make_scene_accelerator(scene.geometry, scene.prototypes, scene.instances, structure);
  const Rendered single = render_with(scene, *accel, false, 2);
  const Rendered packed = render_with(scene, *accel, true, 2);
  EXPECT_TRUE(same_bits(single.film, packed.film));
  expect_same_counts(single.stats, packed.stats);
}

// --stats counts traversal work through the counted single-ray kernels (there is no counted
// packet entry point), so with counting on the counts match to the node.
TEST(Packets, CountedTraversalMatchesSingleRays) {
  Scene scene = sized(make_demo_scene(), 20, 12);
  scene.settings.spp = 4;
  const std::unique_ptr<Accelerator> accel = make_accelerator("bvh", scene.geometry);
  const Rendered single = render_with(scene, *accel, false, 2, true);
  const Rendered packed = render_with(scene, *accel, true, 2, true);
  EXPECT_TRUE(same_bits(single.film, packed.film));
  EXPECT_GT(packed.stats.traversal.nodes_visited, 0u);
  expect_same_counts(single.stats, packed.stats);
}

// With packets on, every primary ray goes in a packet of 16 (the image is a whole number of 4x4
// blocks at 1 spp, of 2x2 blocks at 4 spp) and the shadow rays toward the point and directional
// lights go as any-hit packets; only secondary rays and area-light samples go one by one. With
// packets off, no packet call is made at all.
TEST(Packets, PrimaryAndShadowRaysReallyGoAsPackets) {
  for (int spp : {1, 4}) {
    SCOPED_TRACE(spp);
    Scene scene = sized(many_lights_scene(), 32, 24);
    scene.settings.spp = spp;
    const std::unique_ptr<Accelerator> bvh = make_accelerator("bvh", scene.geometry);

    const RecordingAccelerator on(*bvh);
    const RenderStats packed = render_with(scene, on, true, 2).stats;
    const std::uint64_t primary = packed.rays[kind(RayKind::kPrimary)];
    EXPECT_EQ(primary, 32u * 24u * spp);
    ASSERT_EQ(on.intersect_packets.size(), 1u);
    EXPECT_EQ(on.intersect_packets.begin()->first, 16u);
    EXPECT_EQ(on.intersect_packets.begin()->second, primary / 16);
    EXPECT_EQ(on.single_intersects.load(),
              packed.rays[kind(RayKind::kReflection)] + packed.rays[kind(RayKind::kRefraction)]);
    const std::uint64_t packed_shadows = RecordingAccelerator::rays_in(on.occluded_packets);
    EXPECT_GT(packed_shadows, 0u);
    EXPECT_LE(on.occluded_packets.rbegin()->first, 16u);
    EXPECT_EQ(packed_shadows + on.single_occludeds.load(), packed.rays[kind(RayKind::kShadow)]);
    EXPECT_GT(on.single_occludeds.load(), 0u);  // the quad light's samples and the secondary hits

    const RecordingAccelerator off(*bvh);
    const RenderStats single = render_with(scene, off, false, 2).stats;
    EXPECT_TRUE(off.intersect_packets.empty());
    EXPECT_TRUE(off.occluded_packets.empty());
    EXPECT_EQ(off.single_intersects.load(), single.rays[kind(RayKind::kPrimary)] +
                                                single.rays[kind(RayKind::kReflection)] +
                                                single.rays[kind(RayKind::kRefraction)]);
    EXPECT_EQ(off.single_occludeds.load(), single.rays[kind(RayKind::kShadow)]);
  }
}

// The adaptive samplers keep single rays whatever the setting.
TEST(Packets, AdaptiveSamplersTraceSingleRays) {
  Scene scene = sized(many_lights_scene(), 16, 12);
  scene.settings.sampler = "adaptive";
  scene.settings.spp = 4;
  const std::unique_ptr<Accelerator> bvh = make_accelerator("bvh", scene.geometry);
  const RecordingAccelerator on(*bvh);
  const Rendered packed = render_with(scene, on, true, 1);
  EXPECT_TRUE(on.intersect_packets.empty());
  EXPECT_TRUE(on.occluded_packets.empty());
  EXPECT_TRUE(same_bits(packed.film, render_with(scene, *bvh, false, 1).film));
}

}  // namespace
}  // namespace raylab
