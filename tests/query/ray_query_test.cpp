// The ray-query API against brute force and against what the answers must be.

#include "raylab/query/ray_query.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "raylab/accel/brute_force.h"
#include "raylab/query/camera_rays.h"
#include "raylab/render/camera.h"
#include "raylab/scene/mesh_generators.h"

namespace raylab {
namespace {

// An icosphere as flat arrays (a closed mesh), welded: shared vertices are one entry.
struct Arrays {
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
};

Arrays sphere_arrays(float radius, int level) {
  Geometry g;
  add_icosphere(g, 0, {0.f, 0.f, 0.f}, radius, level);
  Arrays a;
  std::vector<Vec3> seen;
  auto index_of = [&](Vec3 p) {
    for (std::size_t i = 0; i < seen.size(); ++i) {
      if (seen[i].x == p.x && seen[i].y == p.y && seen[i].z == p.z) return static_cast<std::uint32_t>(i);
    }
    seen.push_back(p);
    a.vertices.insert(a.vertices.end(), {p.x, p.y, p.z});
    return static_cast<std::uint32_t>(seen.size() - 1);
  };
  for (const Triangle& t : g.triangles) {
    a.indices.push_back(index_of(t.p0));
    a.indices.push_back(index_of(t.p1));
    a.indices.push_back(index_of(t.p2));
  }
  return a;
}

// Random rays from outside a ball of radius 3 toward random points inside radius 1.5.
std::vector<Ray> random_rays(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> normal;
  std::uniform_real_distribution<float> uniform(-1.5f, 1.5f);
  std::vector<Ray> rays(n);
  for (Ray& r : rays) {
    const Vec3 from = normalize(Vec3{normal(rng), normal(rng), normal(rng)}) * 3.f;
    const Vec3 to{uniform(rng), uniform(rng), uniform(rng)};
    r.origin = from;
    r.direction = to - from;
  }
  return rays;
}

TEST(RayQuery, ClosestHitsEqualBruteForceWithIdsNormalsAndUv) {
  const Arrays a = sphere_arrays(1.f, 2);
  const RayQuery query = RayQuery::from_triangles(a.vertices, a.indices);
  const std::vector<Ray> rays = random_rays(2000, 1);
  const std::vector<QueryHit> hits = query.intersect(rays);
  const BruteForce brute(query.geometry());
  std::size_t found = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Ray r = rays[i];
    Hit expected;
    const bool hit = brute.intersect(r, expected);
    ASSERT_EQ(hit, hits[i].valid()) << "ray " << i;
    if (!hit) {
      EXPECT_TRUE(std::isinf(hits[i].t));
      EXPECT_EQ(hits[i].object_id, -1);
      continue;
    }
    ++found;
    EXPECT_EQ(hits[i].t, expected.t);
    EXPECT_EQ(hits[i].prim_id, static_cast<std::int32_t>(expected.prim_id));
    EXPECT_EQ(hits[i].object_id, 0);
    EXPECT_EQ(hits[i].u, expected.u);
    EXPECT_EQ(hits[i].v, expected.v);
    // The triangle's own normal, as wound (outward for the icosphere), whatever side was hit.
    const Triangle& tri = query.geometry().triangles[expected.prim_id];
    const Vec3 n = normalize(triangle_normal(tri));
    EXPECT_NEAR(hits[i].normal.x, n.x, 1e-6f);
    EXPECT_NEAR(hits[i].normal.y, n.y, 1e-6f);
    EXPECT_NEAR(hits[i].normal.z, n.z, 1e-6f);
    EXPECT_GT(dot(hits[i].normal, tri.p0), 0.f);
  }
  EXPECT_GT(found, rays.size() / 4);  // the ball fills about 40% of the targets' cube
}

TEST(RayQuery, PrimitiveIdIsTheTriangleRowOfTheInput) {
  // Two unit squares at z = 0 and z = 1, a degenerate triangle between them keeps its row.
  const std::vector<float> v = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1};
  const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 0, 0, 3, 4, 5};
  const RayQuery query = RayQuery::from_triangles(v, idx);
  Ray down;
  down.origin = {0.2f, 0.2f, 5.f};
  down.direction = {0.f, 0.f, -1.f};
  const std::vector<QueryHit> hits = query.intersect(std::vector<Ray>{down});
  EXPECT_EQ(hits[0].prim_id, 2);
  EXPECT_EQ(hits[0].t, 4.f);
}

TEST(RayQuery, DoubleVerticesGiveTheFloatAnswers) {
  const Arrays a = sphere_arrays(1.f, 1);
  const std::vector<double> vd(a.vertices.begin(), a.vertices.end());
  const RayQuery qf = RayQuery::from_triangles(a.vertices, a.indices);
  const RayQuery qd = RayQuery::from_triangles(vd, a.indices);
  const std::vector<Ray> rays = random_rays(500, 2);
  const std::vector<QueryHit> hf = qf.intersect(rays), hd = qd.intersect(rays);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(hf[i].t, hd[i].t);
    EXPECT_EQ(hf[i].prim_id, hd[i].prim_id);
  }
}

TEST(RayQuery, BadArraysAreRefusedNamingTheArgument) {
  const std::vector<float> v = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  auto message = [](auto&& make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] {
              RayQuery::from_triangles(std::vector<float>{0, 0}, std::vector<std::uint32_t>{});
            }).find("vertices"),
            std::string::npos);
  EXPECT_NE(message([&] {
              RayQuery::from_triangles(v, std::vector<std::uint32_t>{0, 1});
            }).find("indices"),
            std::string::npos);
  EXPECT_NE(message([&] {
              RayQuery::from_triangles(v, std::vector<std::uint32_t>{0, 1, 3});
            }).find("refers to vertex 3"),
            std::string::npos);
  std::vector<float> nan_v = v;
  nan_v[4] = std::nanf("");
  EXPECT_NE(message([&] {
              RayQuery::from_triangles(nan_v, std::vector<std::uint32_t>{0, 1, 2});
            }).find("vertex 1"),
            std::string::npos);
  const std::vector<double> huge = {0, 0, 0, 1e300, 0, 0, 0, 1, 0};
  EXPECT_NE(message([&] {
              RayQuery::from_triangles(huge, std::vector<std::uint32_t>{0, 1, 2});
            }).find("vertex 1"),
            std::string::npos);
}

TEST(RayQuery, AnswersDoNotDependOnThreadsOrOnPacketing) {
  const Arrays a = sphere_arrays(1.f, 3);
  RayQuery query = RayQuery::from_triangles(a.vertices, a.indices);
  query.build("bvh");
  // Coherent camera rays (traced as packets) and scattered rays (traced one by one): both must
  // equal the single-ray answers, on one thread and on several.
  CameraSpec cam;
  cam.from = {0.f, 0.5f, 4.f};
  std::vector<Ray> rays = pixel_centre_rays(cam, 64, 48);
  const std::vector<Ray> scattered = random_rays(3000, 3);
  rays.insert(rays.end(), scattered.begin(), scattered.end());
  QueryOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const std::vector<QueryHit> h1 = query.intersect(rays, one), h2 = query.intersect(rays, two);
  std::vector<std::uint8_t> o1(rays.size()), o2(rays.size());
  query.occluded(RayBatch::of(rays), o1.data(), one);
  query.occluded(RayBatch::of(rays), o2.data(), two);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Ray r = rays[i];
    Hit single;
    const bool hit = query.accelerator().intersect(r, single);
    ASSERT_EQ(h1[i].valid(), hit) << i;
    EXPECT_EQ(h1[i].t, hit ? single.t : h1[i].t);
    EXPECT_EQ(h1[i].prim_id, h2[i].prim_id);
    EXPECT_EQ(h1[i].t, h2[i].t);
    EXPECT_EQ(o1[i], hit ? 1 : 0) << i;
    EXPECT_EQ(o1[i], o2[i]);
  }
}

TEST(RayQuery, RaysReadInPlaceFromOneArrayOfSixColumns) {
  const Arrays a = sphere_arrays(1.f, 2);
  const RayQuery query = RayQuery::from_triangles(a.vertices, a.indices);
  const std::vector<Ray> rays = random_rays(300, 4);
  std::vector<float> six;
  for (const Ray& r : rays)
    six.insert(six.end(), {r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z});
  RayBatch batch;
  batch.count = rays.size();
  batch.origins = six.data();
  batch.directions = six.data() + 3;
  batch.origin_stride = batch.direction_stride = 6;
  std::vector<float> t(rays.size());
  std::vector<std::int32_t> prim(rays.size());
  query.intersect(batch, HitArrays{t.data(), prim.data(), nullptr, nullptr, nullptr});
  const std::vector<QueryHit> expected = query.intersect(rays);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(t[i], expected[i].t);
    EXPECT_EQ(prim[i], expected[i].prim_id);
  }
}

// Crossing counts through the wide BVH equal brute force's exactly, and every ray from outside
// that leaves a closed mesh crosses it an even number of times, rays aimed exactly at its
// vertices included.
TEST(RayQuery, CrossingCountsOfAClosedMeshAreEvenAndMatchBruteForce) {
  const Arrays a = sphere_arrays(1.f, 2);
  RayQuery query = RayQuery::from_triangles(a.vertices, a.indices);
  std::vector<Ray> rays = random_rays(2000, 5);
  std::mt19937 rng(6);
  std::normal_distribution<float> normal;
  for (std::size_t v = 0; v < a.vertices.size(); v += 3) {
    const Vec3 p{a.vertices[v], a.vertices[v + 1], a.vertices[v + 2]};
    for (int k = 0; k < 4; ++k) {
      Ray r;
      r.origin = normalize(Vec3{normal(rng), normal(rng), normal(rng)}) * 3.f;
      r.direction = p - r.origin;
      rays.push_back(r);
    }
  }
  std::vector<std::uint32_t> counts(rays.size()), brute_counts(rays.size());
  query.build("bvh");
  query.count_intersections(RayBatch::of(rays), counts.data());
  query.build("brute");
  query.count_intersections(RayBatch::of(rays), brute_counts.data());
  std::size_t crossing = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(counts[i], brute_counts[i]) << "ray " << i;
    EXPECT_EQ(counts[i] % 2, 0u) << "ray " << i;
    crossing += counts[i] > 0 ? 1 : 0;
  }
  EXPECT_GT(crossing, rays.size() / 2);
}

TEST(RayQuery, AllHitsOfEveryStructureListTheSameCrossings) {
  const Arrays a = sphere_arrays(1.f, 2);
  RayQuery query = RayQuery::from_triangles(a.vertices, a.indices);
  const std::vector<Ray> rays = random_rays(500, 7);
  const BruteForce brute(query.geometry());
  for (const char* name : {"bvh", "bvh2", "grid", "grid2", "octree", "irregular"}) {
    query.build(name);
    for (const Ray& r : rays) {
      std::vector<Hit> expected, found;
      brute.all_hits(r, expected);
      query.accelerator().all_hits(r, found);
      ASSERT_EQ(found.size(), expected.size()) << name;
      for (std::size_t k = 0; k < found.size(); ++k) {
        EXPECT_EQ(found[k].prim_id, expected[k].prim_id) << name;
        EXPECT_EQ(found[k].t, expected[k].t) << name;
      }
    }
  }
}

TEST(RayQuery, ContainsAgreesWithTheBallAwayFromItsSurface) {
  const Arrays a = sphere_arrays(1.f, 3);
  const RayQuery query = RayQuery::from_triangles(a.vertices, a.indices);
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> uniform(-1.4f, 1.4f);
  std::vector<float> points;
  std::vector<bool> expected;
  while (expected.size() < 3000) {
    const Vec3 p{uniform(rng), uniform(rng), uniform(rng)};
    // The level-3 icosphere lies between radius 0.98 and 1.
    if (length(p) > 0.97f && length(p) < 1.01f) continue;
    points.insert(points.end(), {p.x, p.y, p.z});
    expected.push_back(length(p) < 0.97f);
  }
  std::vector<std::uint8_t> inside(expected.size());
  query.contains(points.data(), expected.size(), 3, inside.data());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(inside[i] == 1, expected[i]) << "point " << i;
}

TEST(RayQuery, StopRequestInterruptsABatch) {
  const Arrays a = sphere_arrays(1.f, 1);
  const RayQuery query = RayQuery::from_triangles(a.vertices, a.indices);
  const std::vector<Ray> rays = random_rays(200000, 9);
  std::vector<float> t(rays.size());
  QueryOptions options;
  int asked = 0;
  options.should_stop = [&] { return ++asked == 2; };
  EXPECT_THROW(query.intersect(RayBatch::of(rays), HitArrays{t.data()}, options), QueryInterrupted);
  EXPECT_EQ(asked, 2);
}

TEST(RayQuery, UnknownStructureNamesTheValidOnes) {
  const Arrays a = sphere_arrays(1.f, 0);
  RayQuery query = RayQuery::from_triangles(a.vertices, a.indices);
  try {
    query.build("kdtree");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("octree"), std::string::npos) << e.what();
  }
}

TEST(PinholeRays, AreTheRenderersPixelCentreRays) {
  CameraSpec cam;
  cam.from = {1.f, 2.f, 3.f};
  cam.vfov_degrees = 60.f;
  std::vector<float> out(7 * 5 * 6);
  pinhole_rays(cam, 7, 5, out);
  const Camera camera(cam, 7, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) {
      const Ray r = camera.generate(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      const float* o = &out[static_cast<std::size_t>((y * 7 + x) * 6)];
      EXPECT_EQ(o[0], r.origin.x);
      EXPECT_EQ(o[2], r.origin.z);
      EXPECT_EQ(o[3], r.direction.x);
      EXPECT_EQ(o[5], r.direction.z);
    }
  }
  EXPECT_THROW(pinhole_rays(cam, 0, 5, out), std::invalid_argument);
  EXPECT_THROW(pinhole_rays(cam, 7, 4, out), std::invalid_argument);
}

}  // namespace
}  // namespace raylab
