// shading_surface_at: surface_at without the surface coordinates of hits whose material never
// reads them. Everything else it reports must be surface_at's to the bit, and wherever the
// material reads the coordinates they must be surface_at's too.

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "raylab/core/rng.h"
#include "raylab/geometry/shading.h"
#include "raylab/scene/scene.h"

namespace raylab {
namespace {

// The same bits, so that a render shading with either gives the same image.
bool same_bits(Vec3 a, Vec3 b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

// One primitive of every kind, each its own object, all of material `material`.
Scene every_shape(const Material& material) {
  Scene scene;
  const std::uint32_t m = scene.add_material(material);
  auto object = [&] { return scene.add_object("shape", m); };
  scene.geometry.add(Triangle{{-1.f, 0.f, 0.f}, {1.f, 0.2f, 0.f}, {0.f, 1.5f, 0.5f}}, object());
  scene.geometry.add(Sphere{{4.f, 0.f, 0.f}, 1.5f}, object());
  scene.geometry.add(Cylinder{{-4.f, -1.f, 0.f}, 1.f, {-4.f, 1.f, 0.5f}, 0.5f}, object());
  scene.geometry.add(Disk{{0.f, 4.f, 0.f}, normalize(Vec3{0.2f, 1.f, 0.1f}), 1.f}, object());
  scene.geometry.add(Quad{{3.f, 3.f, 0.f}, {1.f, 0.5f, 0.f}, {0.f, 0.2f, 1.5f}}, object());
  return scene;
}

// Calls `check(ray, hit)` for random rays aimed at each primitive of `scene` that hit it; returns
// how many did.
template <class Check>
int for_random_hits(const Scene& scene, Check&& check) {
  const Geometry& g = scene.geometry;
  Pcg32 rng(1234, 5);
  int hits = 0;
  for (std::uint32_t id = 0; id < g.size(); ++id) {
    const Box3 b = g.bounds(id);
    for (int i = 0; i < 400; ++i) {
      const Vec3 target = b.lo + b.extent() * Vec3{rng.next_float(), rng.next_float(), rng.next_float()};
      const Vec3 o = target + Vec3{rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f} * 16.f;
      Ray ray{o, 0.f, target - o};
      Hit hit;
      if (!g.intersect(id, WatertightRay(ray), ray, hit)) continue;
      hit.prim_id = id;
      ++hits;
      check(ray, hit);
    }
  }
  return hits;
}

TEST(ShadingSurface, UntexturedHitsDifferOnlyInTheirCoordinates) {
  const Scene scene = every_shape(Material{});
  int skipped = 0;
  const int hits = for_random_hits(scene, [&](const Ray& ray, const Hit& hit) {
    const SurfaceInteraction full = surface_at(scene, ray, hit);
    const SurfaceInteraction shading = shading_surface_at(scene, ray, hit);
    EXPECT_TRUE(same_bits(shading.position, full.position)) << "prim " << hit.prim_id;
    EXPECT_TRUE(same_bits(shading.geometric_normal, full.geometric_normal)) << "prim " << hit.prim_id;
    EXPECT_TRUE(same_bits(shading.shading_normal, full.shading_normal)) << "prim " << hit.prim_id;
    EXPECT_EQ(shading.front_face, full.front_face);
    EXPECT_EQ(shading.object_id, full.object_id);
    if (scene.geometry.resolve(hit.prim_id).kind != ShapeKind::kSphere) {
      // Other shapes' coordinates cost less than asking the material, and are kept.
      EXPECT_EQ(shading.u, full.u);
      EXPECT_EQ(shading.v, full.v);
      return;
    }
    EXPECT_EQ(shading.u, 0.f) << "prim " << hit.prim_id;
    EXPECT_EQ(shading.v, 0.f) << "prim " << hit.prim_id;
    skipped += full.u != 0.f || full.v != 0.f;
  });
  EXPECT_GT(hits, 500);
  EXPECT_GT(skipped, 100) << "the sphere's hits have coordinates that were skipped";
}

TEST(ShadingSurface, MaterialsThatReadCoordinatesGetThem) {
  Material checker;
  checker.texture = Texture(Texture::Kind::kChecker, Color{0.1f, 0.2f, 0.3f}, 0.25f);
  Material emissive;
  emissive.maps.emission = std::make_shared<TextureImage>(1, 1, std::vector<Color>{Color{1.f}});
  for (const Material& material : {checker, emissive}) {
    ASSERT_TRUE(reads_surface_coordinates(material));
    const Scene scene = every_shape(material);
    const int hits = for_random_hits(scene, [&](const Ray& ray, const Hit& hit) {
      const SurfaceInteraction full = surface_at(scene, ray, hit);
      const SurfaceInteraction shading = shading_surface_at(scene, ray, hit);
      EXPECT_TRUE(same_bits(shading.position, full.position));
      EXPECT_TRUE(same_bits(shading.shading_normal, full.shading_normal));
      EXPECT_EQ(std::memcmp(&shading.u, &full.u, sizeof(float)), 0) << "prim " << hit.prim_id;
      EXPECT_EQ(std::memcmp(&shading.v, &full.v, sizeof(float)), 0) << "prim " << hit.prim_id;
    });
    EXPECT_GT(hits, 500);
  }
}

TEST(ShadingSurface, EveryTextureAndMapReadsTheCoordinates) {
  EXPECT_FALSE(reads_surface_coordinates(Material{}));
  const auto image = std::make_shared<TextureImage>(1, 1, std::vector<Color>{Color{0.5f}});
  std::vector<Material> reading(7);
  reading[0].texture = Texture(Texture::Kind::kChecker, Color{0.f});
  reading[1].texture = Texture::from_image(image);
  reading[2].texture = Texture::zone_plate(Color{0.f}, Vec2{0.5f, 0.5f}, 10.f, 0.5f);
  reading[3].maps.metallic_roughness = image;
  reading[4].maps.emission = image;
  reading[5].maps.transmission = image;
  reading[6].maps.normal = image;
  Material bump;
  bump.maps.bump = image;
  reading.push_back(bump);
  for (std::size_t i = 0; i < reading.size(); ++i) EXPECT_TRUE(reads_surface_coordinates(reading[i])) << i;
}

}  // namespace
}  // namespace raylab
