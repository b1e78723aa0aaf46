// Embree behind our interface (`--accel embree`) against brute force on the shared test scenes
// (test_scenes.h): the same closest hit up to a relative 1e-4 in t (Embree computes triangle
// distances its own way) and the same primitive except at ties and rare grazes of triangle edges, the same any-hit
// answers, our barycentric convention, the half-open [tmin, tmax) interval, subsets of ids, group items (user geometry
// calling back into nested structures), and concurrent queries. Skipped where raylab was built without Embree 3.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/embree_accel.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

// Relative tolerance of distances: Embree's t comes from another formula than ours, so it is
// looser than the kRelTol our structures meet.
constexpr float kEmbreeRelTol = 1e-4f;

double max_abs(Vec3 v) { return std::max({std::fabs(double(v.x)), std::fabs(double(v.y)), std::fabs(double(v.z))}); }

// True when `id` is a triangle and `p` lies within float resolution (1e-5 of the coordinates'
// magnitude, about 100 ulps) of one of its edge lines: a grazing hit that two correct float tests
// may decide differently (the scenes hold slivers 1e-4 wide and triangles of 1e-4 at 1e4 from
// the origin, finer than the coordinates can resolve).
bool grazes_triangle_edge(const Geometry& g, std::uint32_t id, Vec3 p, Vec3 origin) {
  if (id >= g.triangles.size()) return false;
  const Triangle& t = g.triangles[id];
  const Vec3 v[3] = {t.p0, t.p1, t.p2};
  double scale = std::max(max_abs(p), max_abs(origin));
  for (const Vec3& x : v) scale = std::max(scale, max_abs(x));
  for (int i = 0; i < 3; ++i) {
    const Vec3 a = v[i], b = v[(i + 1) % 3];
    const double e[3] = {double(b.x) - a.x, double(b.y) - a.y, double(b.z) - a.z};
    const double w[3] = {double(p.x) - a.x, double(p.y) - a.y, double(p.z) - a.z};
    const double c[3] = {e[1] * w[2] - e[2] * w[1], e[2] * w[0] - e[0] * w[2], e[0] * w[1] - e[1] * w[0]};
    const double len = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    const double dist = len > 0.0 ? std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / len
                                  : std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    if (dist <= 1e-5 * scale) return true;
  }
  return false;
}

// How far apart two correct float tests may put the hit of `ray` on triangle `id`, along the
// ray, in absolute units: float steps at the vertices' distance from the origin, amplified by the
// triangle's shape (a sliver's normal, computed from nearly parallel edges, is off by about
// eps * longest^2 / (2 area)) and by the ray's obliquity. Embree computes t that way; ours is
// watertight and more precise. 0 for other shapes (both sides run our code).
double position_tolerance(const Geometry& g, std::uint32_t id, const Ray& ray) {
  if (id >= g.triangles.size()) return 0.0;
  const Triangle& t = g.triangles[id];
  const Vec3 n = triangle_normal(t);
  const double area2 = length(n);
  const double longest = std::max({length(t.p1 - t.p0), length(t.p2 - t.p1), length(t.p0 - t.p2)});
  const double reach = std::max({length(t.p0 - ray.origin), length(t.p1 - ray.origin), length(t.p2 - ray.origin)});
  const double cosine = std::fabs(dot(n, ray.direction)) / (area2 * length(ray.direction));
  return 64.0 * 6e-8 * (longest * longest / area2) * reach / std::max(cosine, 1e-6);
}

// True when Embree's distance `te` to its primitive `id` matches `tb`: within kEmbreeRelTol, or within
// the triangle's position tolerance.
bool same_distance(const Geometry& g, std::uint32_t id, const Ray& ray, float tb, float te) {
  return near(tb, te, kEmbreeRelTol) ||
         std::fabs(double(tb) - te) * length(ray.direction) <= position_tolerance(g, id, ray);
}

// Compares every query of `embree` with `brute` on `rays`. Returns the number of hits. Distances
// and barycentrics may differ by what the triangle's conditioning allows (position_tolerance);
// where the two disagree on which primitive is hit, it must be a tie, or one of the two hits must
// graze a triangle edge (then the ray is counted, not failed, and such rays must stay rare).
int compare_with_embree(const Geometry& g, const Accelerator& embree, const Accelerator& brute,
                        const std::vector<Ray>& rays, Sampler& s) {
  int failures = 0, hits = 0, ties = 0, grazes = 0;
  auto fail = [&](const std::string& what, const Ray& r) {
    if (++failures <= 5) ADD_FAILURE() << what << " for " << describe(r);
  };
  for (const Ray& ray : rays) {
    const auto [rb, hb, fb, re, he, fe] = both_hits(brute, embree, ray);
    bool agree = fb == fe;
    if (agree && fb && hb.prim_id == he.prim_id) {
      agree = same_distance(g, he.prim_id, ray, hb.t, he.t);
    } else if (agree && fb) {
      // A tie: Embree's primitive, tested alone by our code, hits where brute force's does.
      const std::optional<Hit> h = hit_alone(g, he.prim_id, ray);
      agree = h && near(h->t, hb.t, kEmbreeRelTol) && same_distance(g, he.prim_id, ray, h->t, he.t);
      ties += agree;
    }
    if (!agree) {
      if ((fb && grazes_triangle_edge(g, hb.prim_id, ray.at(hb.t), ray.origin)) ||
          (fe && grazes_triangle_edge(g, he.prim_id, ray.at(he.t), ray.origin))) {
        ++grazes;
      } else {
        fail(fb != fe ? (fb ? "Embree missed a hit" : "Embree found a phantom hit")
                      : "hits differ: t " + std::to_string(hb.t) + " prim " + std::to_string(hb.prim_id) + " vs t " +
                            std::to_string(he.t) + " prim " + std::to_string(he.prim_id),
             ray);
      }
      continue;
    }
    if (fb) {
      ++hits;
      if (re.tmax != he.t) fail("tmax not shrunk to the hit", ray);
      if (hb.prim_id == he.prim_id && he.prim_id < g.triangles.size()) {
        // Embree's u, v follow our convention (u of p1, v of p2), up to the position tolerance
        // over the triangle's smallest height.
        const Triangle& t = g.triangles[he.prim_id];
        const double longest = std::max({length(t.p1 - t.p0), length(t.p2 - t.p1), length(t.p0 - t.p2)});
        const double tol = 1e-4 + position_tolerance(g, he.prim_id, ray) * longest / length(triangle_normal(t));
        if (std::fabs(hb.u - he.u) > tol || std::fabs(hb.v - he.v) > tol) {
          fail("u, v differ: (" + std::to_string(hb.u) + ", " + std::to_string(hb.v) + ") vs (" + std::to_string(he.u) +
                   ", " + std::to_string(he.v) + "), tolerance " + std::to_string(tol),
               ray);
        }
      } else if (hb.prim_id == he.prim_id && (hb.t != he.t || hb.u != he.u || hb.v != he.v)) {
        fail("a user primitive's hit differs from our own code's", ray);  // same code, same ray
      }
    } else if (re.tmax != ray.tmax || he.valid()) {
      fail("a miss changed the ray or the hit", ray);
    }

    // Counted: the same answer; Embree has no traversal counts, so only hits are counted.
    const auto [rc, hc, fc, st] = counted_hit(embree, ray);
    if (fc != fe || hc.t != he.t || hc.prim_id != he.prim_id) fail("intersect_counted differs", ray);
    if (st.hits != (fc ? 1u : 0u) || st.nodes_visited != 0 || st.prim_tests != 0) fail("counts", ray);

    // Any-hit with a random tmax: occluded iff the closest hit lies before tmax.
    const Ray ro = with_random_tmax(ray, fb, hb.t, s);
    // Too close to call: within the tolerance of either distance, or between the two.
    if (fb && (near(ro.tmax, hb.t, kEmbreeRelTol) || near(ro.tmax, he.t, kEmbreeRelTol) ||
               (ro.tmax - hb.t) * (ro.tmax - he.t) <= 0.f)) {
      continue;
    }
    const bool expected = fb && hb.t < ro.tmax;
    if (embree.occluded(ro) != expected) fail(expected ? "occluded missed" : "occluded phantom", ro);
    TraversalStats so;
    if (embree.occluded_counted(ro, so) != expected || so.hits != (expected ? 1u : 0u)) fail("occluded_counted", ro);
  }
  EXPECT_EQ(failures, 0) << "of " << rays.size() << " rays";
  EXPECT_LT(ties, hits / 20 + 5) << "ties should be rare";
  EXPECT_LE(grazes, int(rays.size()) / 100) << "edge grazes should be rare";
  return hits;
}

TEST(EmbreeAccel, FactoryOffersItExactlyWhenAvailable) {
  const auto names = accelerator_names();
  const bool listed = std::find(names.begin(), names.end(), "embree") != names.end();
  EXPECT_EQ(listed, embree_available());
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 0.f}, 1.f}, 0);
  if (embree_available()) {
    EXPECT_EQ(make_accelerator("embree", g)->info().name, "embree");
  } else {
    EXPECT_THROW(make_accelerator("embree", g), UsageError);
  }
}

class EmbreeVsBrute : public ::testing::TestWithParam<NamedScene> {};

TEST_P(EmbreeVsBrute, SameHitsAsBruteForce) {
  if (!embree_available()) GTEST_SKIP() << "built without Embree 3";
  Sampler s(GetParam().seed);
  const Geometry g = GetParam().make(s);
  const auto embree = make_accelerator("embree", g);
  const BruteForce brute(g);
  const AccelInfo info = embree->info();
  EXPECT_EQ(info.name, "embree");
  EXPECT_EQ(info.primitive_count, g.size());
  EXPECT_GT(info.memory_bytes, g.size() * 8u) << "Embree's memory monitor should see the scene";
  EXPECT_GE(info.build_seconds, 0.0);
  const Box3 b = embree->bounds(), gb = g.bounds();
  EXPECT_TRUE(b.lo == gb.lo && b.hi == gb.hi);
  const std::vector<Ray> rays = random_rays(g, s, 3000);
  EXPECT_GT(compare_with_embree(g, *embree, brute, rays, s), 300);
}

TEST_P(EmbreeVsBrute, SubsetOfIds) {
  if (!embree_available()) GTEST_SKIP() << "built without Embree 3";
  Sampler s(GetParam().seed + 100);
  const Geometry g = GetParam().make(s);
  std::vector<std::uint32_t> ids;
  for (std::uint32_t id = 1; id < g.size(); id += 3) ids.push_back(id);
  const auto embree = make_embree_accelerator(g, ids);
  const BruteForce brute(g, ids);
  EXPECT_EQ(embree->info().primitive_count, ids.size());
  compare_with_embree(g, *embree, brute, random_rays(g, s, 1000), s);
}

INSTANTIATE_TEST_SUITE_P(Scenes, EmbreeVsBrute, ::testing::ValuesIn(kScenes),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(EmbreeAccel, BarycentricsFollowOurConvention) {
  if (!embree_available()) GTEST_SKIP() << "built without Embree 3";
  Geometry g;
  const Triangle t{{0.f, 0.f, 0.f}, {4.f, 0.f, 0.f}, {0.f, 4.f, 0.f}};
  g.add(t, 0);
  const auto embree = make_accelerator("embree", g);
  // The point 0.25 p1 + 0.5 p2 = (1, 2, 0): u is the weight of p1, v that of p2.
  Ray ray{{1.f, 2.f, 5.f}, 0.f, {0.f, 0.f, -1.f}, kInf};
  Hit hit;
  ASSERT_TRUE(embree->intersect(ray, hit));
  EXPECT_FLOAT_EQ(hit.t, 5.f);
  EXPECT_EQ(hit.prim_id, 0u);
  EXPECT_NEAR(hit.u, 0.25f, 1e-6f);
  EXPECT_NEAR(hit.v, 0.5f, 1e-6f);
}

TEST(EmbreeAccel, IntervalIsHalfOpenLikeOurs) {
  if (!embree_available()) GTEST_SKIP() << "built without Embree 3";
  // A triangle (Embree's own test) and a sphere (our test through a user geometry), each hit at
  // exactly t = 2 by its ray.
  Geometry g;
  g.add(Triangle{{-1.f, -1.f, 2.f}, {1.f, -1.f, 2.f}, {0.f, 1.f, 2.f}}, 0);
  g.add(Sphere{{10.f, 0.f, 3.f}, 1.f}, 0);
  const auto embree = make_accelerator("embree", g);
  const BruteForce brute(g);
  for (const Vec3 origin : {Vec3{0.f, 0.f, 0.f}, Vec3{10.f, 0.f, 0.f}}) {
    for (const float tmax : {2.f, std::nextafter(2.f, kInf)}) {
      for (const float tmin : {0.f, 2.f, std::nextafter(2.f, kInf)}) {
        const Ray ray{origin, tmin, {0.f, 0.f, 1.f}, tmax};
        Ray re = ray, rb = ray;
        Hit he, hb;
        const bool expected = brute.intersect(rb, hb);
        EXPECT_EQ(embree->intersect(re, he), expected) << describe(ray) << " tmax " << tmax;
        EXPECT_EQ(embree->occluded(ray), expected) << describe(ray) << " tmax " << tmax;
        EXPECT_EQ(expected, tmin <= 2.f && tmax > 2.f);  // the reference itself
      }
    }
  }
}

// A group item wrapping a nested structure, as the two-level structure makes them.
GroupShape wrap(const Accelerator& inner) {
  GroupShape group;
  group.box = inner.bounds();
  group.context = &inner;
  group.intersect = [](const void* c, Ray& ray, Hit& hit) {
    return static_cast<const Accelerator*>(c)->intersect(ray, hit);
  };
  group.occluded = [](const void* c, const Ray& ray) { return static_cast<const Accelerator*>(c)->occluded(ray); };
  return group;
}

TEST(EmbreeAccel, GroupItemsCallBackIntoNestedStructures) {
  if (!embree_available()) GTEST_SKIP() << "built without Embree 3";
  Sampler s(7);
  Geometry g = every_shape_kind(s);
  // Three groups over interleaved thirds of the primitives, each a nested brute force.
  std::vector<std::unique_ptr<BruteForce>> parts;
  for (std::uint32_t part = 0; part < 3; ++part) {
    std::vector<std::uint32_t> ids;
    for (std::uint32_t id = part; id < g.size(); id += 3) ids.push_back(id);
    parts.push_back(std::make_unique<BruteForce>(g, ids));
  }
  for (const auto& p : parts) g.groups.push_back(wrap(*p));
  const std::vector<std::uint32_t> groups = {kGroupIdBase, kGroupIdBase + 1, kGroupIdBase + 2};
  const auto embree = make_embree_accelerator(g, groups);
  const BruteForce top(g, groups);
  const BruteForce flat(g);
  const std::vector<Ray> rays = random_rays(g, s, 2000);
  // Every query goes through our own code, so the answers are identical to the flat reference.
  int hits = 0;
  for (const Ray& ray : rays) {
    Ray re = ray, rf = ray;
    Hit he, hf;
    const bool fe = embree->intersect(re, he), ff = flat.intersect(rf, hf);
    ASSERT_EQ(fe, ff) << describe(ray);
    hits += fe;
    if (fe) {
      EXPECT_EQ(he.t, hf.t) << describe(ray);
      EXPECT_EQ(he.prim_id, hf.prim_id) << describe(ray);
      EXPECT_EQ(he.u, hf.u);
      EXPECT_EQ(he.v, hf.v);
    }
    EXPECT_EQ(embree->occluded(ray), ff) << describe(ray);
  }
  EXPECT_GT(hits, 300);
  compare_with_embree(g, *embree, top, rays, s);
}

// Rays from far origins aimed at the vertices and edge midpoints of a tilted triangle grid. Each
// passes through the grid's interior, so brute force finds exactly one owner of the point (our
// tie rule). Embree's robust test is watertight too but may give the point to a neighbour, which
// our test misses; the filter then rejects it, and Embree need not offer ours. The accelerator
// answers such queries by brute force: before it did, 2876 of these 5998 rays lost their hit
// (AMD EPYC, AVX2 kernels). What remains is Embree offering no triangle at all at a vertex (55 of
// them, none at edges), which no filter sees; the other tests tolerate such grazes too.
TEST(EmbreeAccel, SharedEdgesSeenFromFarAwayKeepTheirHits) {
  if (!embree_available()) GTEST_SKIP() << "built without Embree 3";
  constexpr int kCells = 24;
  const Vec3 base{0.37f, -1.9f, 2.3f}, du{0.113f, 0.021f, -0.037f}, dv{-0.017f, 0.097f, 0.059f};
  auto vertex = [&](int i, int j) { return base + du * float(i) + dv * float(j); };
  Geometry g;
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      g.add(Triangle{vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)}, 0);
      g.add(Triangle{vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)}, 0);
    }
  }
  const auto embree = make_accelerator("embree", g);
  const BruteForce brute(g);
  Sampler s(31);
  int rays = 0, lost[4] = {0, 0, 0, 0};
  for (int n = 0; n < 6000; ++n) {
    const int i = 1 + int(s.rng.next_u32() % (kCells - 1)), j = 1 + int(s.rng.next_u32() % (kCells - 1));
    const int kind = int(s.rng.next_u32() % 4);
    Vec3 target = vertex(i, j);                                            // kind 0
    if (kind == 1) target = (vertex(i, j) + vertex(i + 1, j)) * 0.5f;      // an edge along u
    if (kind == 2) target = (vertex(i, j) + vertex(i, j + 1)) * 0.5f;      // an edge along v
    if (kind == 3) target = (vertex(i, j) + vertex(i + 1, j + 1)) * 0.5f;  // a diagonal
    const Vec3 origin = target + s.unit() * s.log_uniform(10.f, 1e5f);
    const Ray ray{origin, 0.f, target - origin, kInf};
    Ray rb = ray;
    Hit hb;
    if (!brute.intersect(rb, hb)) continue;  // a grazing direction may slip past every triangle
    ++rays;
    Ray re = ray;
    Hit he;
    if (!embree->intersect(re, he)) {
      ++lost[kind];
      EXPECT_FALSE(embree->occluded(ray)) << describe(ray) << ": occluded, but no closest hit";
      continue;
    }
    EXPECT_EQ(he.prim_id, hb.prim_id) << describe(ray);
    EXPECT_EQ(he.t, hb.t) << describe(ray);
    EXPECT_TRUE(embree->occluded(ray)) << describe(ray);
  }
  EXPECT_GT(rays, 5000);
  EXPECT_EQ(lost[1] + lost[2] + lost[3], 0) << "hits lost at edges, of " << rays << " rays";
  EXPECT_LE(lost[0], rays / 50) << "hits lost at vertices, of " << rays << " rays";
}

TEST(EmbreeAccel, ConcurrentQueriesGiveTheSameAnswers) {
  if (!embree_available()) GTEST_SKIP() << "built without Embree 3";
  Sampler s(8);
  const Geometry g = spheres_and_triangles(s);
  const auto embree = make_accelerator("embree", g);
  const std::vector<Ray> rays = random_rays(g, s, 4000);
  std::vector<Hit> serial(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Ray r = rays[i];
    embree->intersect(r, serial[i]);
  }
  constexpr int kThreads = 4;
  std::vector<std::vector<Hit>> parallel(kThreads, std::vector<Hit>(rays.size()));
  {
    std::vector<std::jthread> pool;
    for (int t = 0; t < kThreads; ++t) {
      pool.emplace_back([&, t] {
        for (std::size_t i = 0; i < rays.size(); ++i) {
          Ray r = rays[(i + t * 997) % rays.size()];
          embree->intersect(r, parallel[t][(i + t * 997) % rays.size()]);
        }
      });
    }
  }
  for (int t = 0; t < kThreads; ++t) {
    for (std::size_t i = 0; i < rays.size(); ++i) {
      ASSERT_EQ(parallel[t][i].prim_id, serial[i].prim_id) << "thread " << t << " ray " << i;
      ASSERT_EQ(parallel[t][i].t, serial[i].t);
    }
  }
}

}  // namespace
}  // namespace raylab
