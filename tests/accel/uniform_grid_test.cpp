// The uniform grid ("grid"): answers checked against brute force on the stress scenes, with every
// combination of mailboxing and empty-space jumps, and on scenes built so that rays run exactly
// along cell boundaries, through cell corners and edges, start on boundaries, or meet primitives
// that touch cell faces; plus the resolution rule, mailbox accounting and the storage invariants.
// (accel_vs_brute_test.cpp also runs the grid with its defaults, under every wrap mode.)

#include "raylab/accel/uniform_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/factory.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

// The four traversal variants, {mailbox, skip_empty}, at the default density.
constexpr float kD = GridConfig{}.density;
const GridConfig kVariants[] = {{kD, true, true}, {kD, false, true}, {kD, true, false}, {kD, false, false}};

std::vector<std::uint32_t> all_ids(const Geometry& g) { return g.primitive_ids(); }

// Intersect and occluded of `grid` against brute force on `rays`, one failure message per ray
// class; every primitive kind goes through the same path as in the stress scenes.
void expect_same_as_brute(const Geometry& g, const Accelerator& grid, const std::vector<Ray>& rays) {
  const BruteForce brute(g);
  int failures = 0;
  for (const Ray& ray : rays) {
    const auto [rb, hb, fb, rg, hg, fg] = both_hits(brute, grid, ray);
    bool ok = fb == fg;
    if (ok && fb) {
      // The same primitive, or another one at the same distance (a tie broken the same way
      // requires the same set of candidates, which brute force has by construction).
      ok = near(hb.t, hg.t) && rg.tmax == hg.t;
      if (ok && hb.prim_id != hg.prim_id) ok = is_tie(g, hg.prim_id, ray, hb.t);
    }
    if (ok && !fb) ok = rg.tmax == ray.tmax && !hg.valid();
    Ray ro = ray;
    if (fb) ro.tmax = hb.t * 1.5f + 1e-3f;
    const bool expected = fb;
    if (ok) ok = grid.occluded(ro) == expected && brute.occluded(ro) == expected;
    if (!ok && ++failures <= 5) {
      ADD_FAILURE() << "o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
                    << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z << ") tmin=" << ray.tmin
                    << " brute " << fb << " " << hb.t << " #" << hb.prim_id << " grid " << fg << " " << hg.t << " #"
                    << hg.prim_id;
    }
  }
  EXPECT_EQ(failures, 0) << "of " << rays.size() << " rays";
}

// ---------------------------------------------------------------------------------------------
// Against brute force on the stress scenes

class GridVariant : public ::testing::TestWithParam<int> {
 protected:
  GridConfig config() const { return kVariants[GetParam()]; }
};

TEST_P(GridVariant, StressScenesAgreeWithBruteForce) {
  for (const NamedScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    Sampler s(scene.seed + 100);
    const Geometry g = scene.make(s);
    const auto ids = all_ids(g);
    const UniformGrid grid(g, ids, config());
    const BruteForce brute(g);
    EXPECT_EQ(grid.info().primitive_count, g.size());
    compare(g, grid, brute, random_rays(g, s, 1500), s);
  }
}

// Rays in the face planes of axis-aligned cubes (zero-thickness boxes), through the same helper
// as the BVH's test.
TEST_P(GridVariant, RaysInFacePlanes) {
  Sampler s(61);
  const Geometry cubes = closed_meshes(s);
  const auto ids = all_ids(cubes);
  rays_in_face_planes(UniformGrid(cubes, ids, config()), cubes, -2.f, 2.f, 62);
}

std::string variant_name(const ::testing::TestParamInfo<int>& info) {
  const GridConfig& c = kVariants[info.param];
  return std::string(c.mailbox ? "Mailbox" : "NoMailbox") + (c.skip_empty ? "Skip" : "NoSkip");
}
INSTANTIATE_TEST_SUITE_P(Grid, GridVariant, ::testing::Range(0, 4), variant_name);

// Densities from very coarse to fine must give the same answers.
TEST(GridDensity, AnswersDoNotDependOnDensity) {
  for (float density : {0.05f, 0.5f, 8.f, 40.f}) {
    SCOPED_TRACE(density);
    Sampler s(7);
    const Geometry g = every_shape_kind(s);
    const auto ids = all_ids(g);
    const UniformGrid grid(g, ids, GridConfig{density, true, true});
    expect_same_as_brute(g, grid, random_rays(g, s, 1500));
  }
}

// ---------------------------------------------------------------------------------------------
// Adversarial cases on a lattice whose cells are known: the box is [0, 8]^3 cut into 8^3 unit
// cells, so boundary planes lie at the integers.

constexpr int kLattice = 8;

// Spheres of radius 0.5 at every other cell centre, each touching its cell's six faces, plus
// triangles lying exactly in boundary planes and along boundary lines. The spheres at the two
// extreme corners make the box exactly [0, 8]^3.
Geometry lattice_scene() {
  Geometry g;
  for (int x = 0; x < kLattice; ++x)
    for (int y = 0; y < kLattice; ++y)
      for (int z = 0; z < kLattice; ++z) {
        const bool corner =
            (x == 0 && y == 0 && z == 0) || (x == kLattice - 1 && y == kLattice - 1 && z == kLattice - 1);
        if (corner || (x + y + z) % 3 == 0) g.add(Sphere{{x + 0.5f, y + 0.5f, z + 0.5f}, 0.5f}, 0);
      }
  // In the plane x = 4, spanning several cells, its vertices on cell corners.
  g.add(Triangle{{4.f, 1.f, 1.f}, {4.f, 6.f, 1.f}, {4.f, 1.f, 7.f}}, 1);
  // In the plane z = 3, a thin one along the line y = 2.
  g.add(Triangle{{1.f, 2.f, 3.f}, {7.f, 2.f, 3.f}, {7.f, 2.001f, 3.f}}, 1);
  // A small one around a cell corner, (5, 5, 5).
  g.add(Triangle{{4.9f, 5.f, 5.f}, {5.1f, 5.f, 5.f}, {5.f, 5.1f, 5.f}}, 1);
  return g;
}

UniformGrid lattice_grid(const Geometry& g, const std::vector<std::uint32_t>& ids, const GridConfig& config) {
  return UniformGrid(g, ids, {kLattice, kLattice, kLattice}, config);
}

TEST(GridLattice, BoxAndCellsAreTheIntendedOnes) {
  const Geometry g = lattice_scene();
  const auto ids = all_ids(g);
  const UniformGrid grid = lattice_grid(g, ids, {});
  EXPECT_EQ(grid.bounds().lo, Vec3(0.f));
  EXPECT_EQ(grid.bounds().hi, Vec3(8.f));
  EXPECT_EQ(grid.resolution(), (std::array<int, 3>{8, 8, 8}));
  // A sphere touching its cell's faces is inserted into the neighbours too (exact overlap plus
  // the rounding margin) but not into cells it does not touch: the sphere in cell (0, 0, 0)
  // touches cells (1, 0, 0) and (0, 1, 0) at one point each, not cell (1, 1, 1) or (2, 0, 0).
  auto contains = [&](int x, int y, int z, std::uint32_t id) {
    const auto prims = grid.cell_primitives(x, y, z);
    return std::find(prims.begin(), prims.end(), id) != prims.end();
  };
  const std::uint32_t first_sphere = static_cast<std::uint32_t>(g.triangles.size());
  EXPECT_TRUE(contains(0, 0, 0, first_sphere));
  EXPECT_TRUE(contains(1, 0, 0, first_sphere));
  EXPECT_FALSE(contains(2, 0, 0, first_sphere));
  EXPECT_FALSE(contains(1, 1, 1, first_sphere));
  // The triangle in the plane x = 4 lies on the boundary of cells x = 3 and x = 4.
  EXPECT_TRUE(contains(3, 2, 2, 0));
  EXPECT_TRUE(contains(4, 2, 2, 0));
  EXPECT_FALSE(contains(5, 2, 2, 0));
}

// Rays exactly in boundary planes, along boundary lines, through corners, starting exactly on
// boundaries and inside cells, axis-parallel with +0 and -0 components, with tmin > 0.
std::vector<Ray> lattice_rays(Sampler& s) {
  std::vector<Ray> rays;
  auto integer = [&] { return float(s.rng.next_u32() % (kLattice + 1)); };
  for (int i = 0; i < 4000; ++i) {
    Ray r;
    const int kind = i % 8;
    r.origin = s.in_box(Vec3(-2.f), Vec3(10.f));
    r.direction = s.unit();
    const int a = static_cast<int>(s.rng.next_u32() % 3), b = (a + 1) % 3, c = (a + 2) % 3;
    if (kind == 0) {  // in a boundary plane
      r.origin[a] = integer();
      r.direction[a] = signed_zero(s);
    } else if (kind == 1) {  // along a boundary line
      r.origin[a] = integer();
      r.origin[b] = integer();
      r.direction[a] = signed_zero(s);
      r.direction[b] = signed_zero(s);
    } else if (kind == 2) {  // through cell corners: from a lattice point along a diagonal
      r.origin = {integer(), integer(), integer()};
      r.direction = {s.rng.next_float() < 0.5f ? 1.f : -1.f, s.rng.next_float() < 0.5f ? 1.f : -1.f,
                     s.rng.next_float() < 0.5f ? 1.f : -1.f};
      if (s.rng.next_float() < 0.3f) r.direction[c] = signed_zero(s);  // through edges' midpoints
    } else if (kind == 3) {  // starting exactly on a boundary, inside the grid
      r.origin = s.in_box(Vec3(0.f), Vec3(8.f));
      r.origin[a] = integer();
    } else if (kind == 4) {  // axis-parallel, the other components +0 or -0
      r.origin = s.in_box(Vec3(0.f), Vec3(8.f));
      r.direction = {signed_zero(s), signed_zero(s), signed_zero(s)};
      r.direction[a] = s.rng.next_float() < 0.5f ? 1.f : -1.f;
      if (s.rng.next_float() < 0.5f) r.origin[b] = integer();
    } else if (kind == 5) {  // inside a cell, aimed at a lattice point (corners of four cells)
      r.origin = s.in_box(Vec3(0.f), Vec3(8.f));
      r.direction = Vec3{integer(), integer(), integer()} - r.origin;
    } else if (kind == 6) {  // tmin > 0: the part of the ray before tmin does not count
      r.origin = s.in_box(Vec3(-2.f), Vec3(10.f));
      r.tmin = s.uni(0.f, 6.f);
    } else {  // aimed at a point on a sphere's surface where it touches its cell's face
      r.origin = s.in_box(Vec3(-2.f), Vec3(10.f));
      r.direction = Vec3{integer() + 0.5f, integer() + 0.5f, integer() + 0.5f} - r.origin;
      r.direction[a] = float(int(r.origin[a] + r.direction[a])) - r.origin[a];
    }
    rays.push_back(r);
  }
  return rays;
}

TEST(GridLattice, BoundaryCornerAndAxisParallelRaysAgreeWithBruteForce) {
  const Geometry g = lattice_scene();
  const auto ids = all_ids(g);
  for (const GridConfig& config : kVariants) {
    Sampler s(11);
    expect_same_as_brute(g, lattice_grid(g, ids, config), lattice_rays(s));
  }
}

// The lattice again, shifted far from the origin (coordinates near 1e4, cells of 1): rounding of
// the entry point and of boundary distances is then thousands of times a cell's ulp.
TEST(GridLattice, FarFromTheOriginAgreesWithBruteForce) {
  Geometry g = lattice_scene();
  const Vec3 shift{1e4f, -2e4f, 3e3f};
  for (Sphere& sp : g.spheres) sp.center += shift;
  for (Triangle& t : g.triangles) t = {t.p0 + shift, t.p1 + shift, t.p2 + shift};
  const auto ids = all_ids(g);
  Sampler s(12);
  std::vector<Ray> rays = lattice_rays(s);
  for (Ray& r : rays) r.origin += shift;
  expect_same_as_brute(g, lattice_grid(g, ids, {}), rays);
}

// Triangles a few ulps off cell faces, on one side only, so that exact overlap puts each in the
// cells on its side and not the neighbours; rays aimed at points on them a hair from a cell edge.
// The walk, rounding its boundary distances, may pass that edge through the neighbouring cell;
// only the margin by which cell boxes are enlarged at insertion then keeps the triangle found.
TEST(GridLattice, PrimitivesUlpsFromCellFaces) {
  Sampler s(13);
  Geometry g = lattice_scene();
  std::vector<Vec3> targets;
  for (int i = 0; i < 60; ++i) {
    const int a = static_cast<int>(s.rng.next_u32() % 3), b = (a + 1) % 3, c = (a + 2) % 3;
    const float plane = float(1 + s.rng.next_u32() % (kLattice - 1));  // an inner boundary plane
    const float edge = float(1 + s.rng.next_u32() % (kLattice - 1));   // a boundary line in it
    auto ulps_off = [&](float x, float toward) {
      for (int k = 1 + int(s.rng.next_u32() % 3); k > 0; --k) x = std::nextafter(x, toward);
      return x;
    };
    // In a plane just off a boundary plane, its edge just off a boundary line: each of the two
    // lies in one cell along its axis, not touching the neighbours.
    const float side_a = i % 2 ? 1.f : -1.f, side_b = i % 4 < 2 ? 1.f : -1.f;
    const float off_a = ulps_off(plane, 100.f * side_a), off_b = ulps_off(edge, 100.f * side_b);
    Vec3 p0, p1, p2;
    p0[a] = p1[a] = p2[a] = off_a;
    p0[b] = off_b, p1[b] = edge + 0.6f * side_b, p2[b] = off_b;
    p0[c] = 3.1f, p1[c] = 3.5f, p2[c] = 3.9f;
    g.add(Triangle{p0, p1, p2}, 2);
    for (int k = 0; k < 40; ++k) {
      Vec3 target = p0 + (p2 - p0) * s.uni(0.2f, 0.8f);
      target[b] = off_b + side_b * s.uni(0.f, 3e-6f);  // a hair from the edge, on the triangle
      targets.push_back(target);
    }
  }
  const auto ids = all_ids(g);
  std::vector<Ray> rays;
  for (const Vec3& target : targets) {
    for (int k = 0; k < 4; ++k) {
      const Vec3 o = target + s.unit() * s.uni(0.5f, 12.f);
      rays.push_back({o, 0.f, target - o});
    }
  }
  for (const GridConfig& config : kVariants) expect_same_as_brute(g, lattice_grid(g, ids, config), rays);
}

// ---------------------------------------------------------------------------------------------
// Other adversarial scenes

// A triangle and a sphere spanning most of the grid among many small spheres: the big ones are
// in hundreds of cells, and found wherever the ray meets them; rays start inside and outside.
TEST(GridAdversarial, ObjectsSpanningManyCells) {
  Sampler s(21);
  Geometry g;
  g.add(Triangle{{-10.f, -10.f, -9.f}, {10.f, -10.f, 9.f}, {0.f, 10.f, 0.f}}, 0);
  for (int i = 0; i < 400; ++i) g.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.05f, 0.3f)}, 1);
  g.add(Sphere{{2.f, 1.f, -1.f}, 6.f}, 2);
  const auto ids = all_ids(g);
  for (const GridConfig& config : kVariants) {
    const UniformGrid grid(g, ids, GridConfig{4.f, config.mailbox, config.skip_empty});
    EXPECT_GT(grid.reference_count(), 2 * g.size());  // the big ones fill many cells
    Sampler r(22);
    expect_same_as_brute(g, grid, random_rays(g, r, 2000));
  }
}

// Rays starting between objects, some pointing away: objects behind the origin (t < 0) must not
// be reported, even those in the ray's own cells.
TEST(GridAdversarial, ObjectsBehindTheOrigin) {
  Geometry g;
  for (int i = 0; i < 10; ++i) g.add(Sphere{{float(2 * i), 0.f, 0.f}, 0.4f}, 0);
  const auto ids = all_ids(g);
  const UniformGrid grid(g, ids, GridConfig{4.f});
  for (int i = 0; i < 10; ++i) {
    Ray forward{{float(2 * i) + 1.f, 0.f, 0.f}, 0.f, {1.f, 0.f, 0.f}};
    Hit hit;
    if (i == 9) {
      EXPECT_FALSE(grid.intersect(forward, hit)) << i;  // nothing ahead; the spheres are behind
    } else {
      ASSERT_TRUE(grid.intersect(forward, hit)) << i;
      EXPECT_FLOAT_EQ(hit.t, 0.6f) << i;
      EXPECT_EQ(hit.prim_id, std::uint32_t(i + 1));
    }
    // From inside sphere i, pointing back: its own far side, not the spheres behind it.
    Ray back{{float(2 * i), 0.f, 0.f}, 0.f, {-1.f, 0.f, 0.f}};
    Hit h2;
    ASSERT_TRUE(grid.intersect(back, h2));
    EXPECT_EQ(h2.prim_id, std::uint32_t(i));
    EXPECT_FLOAT_EQ(h2.t, 0.4f);
  }
  Sampler s(23);
  expect_same_as_brute(g, grid, random_rays(g, s, 1000));
}

// Many tiny triangles around one point, all in one cell of a grid forced to 16^3 by a far
// triangle that stretches the box.
TEST(GridAdversarial, AllPrimitivesInOneCell) {
  Sampler s(24);
  Geometry g;
  for (int i = 0; i < 300; ++i) g.add(random_triangle(s, Vec3{0.1f, 0.1f, 0.1f} + s.unit() * 0.01f, 0.01f), 0);
  g.add(Triangle{{10.f, 10.f, 9.f}, {10.f, 9.f, 10.f}, {9.f, 10.f, 10.f}}, 1);
  const auto ids = all_ids(g);
  for (const GridConfig& config : kVariants) {
    const UniformGrid grid(g, ids, {16, 16, 16}, config);
    EXPECT_EQ(grid.cell_primitives(0, 0, 0).size(), 300u);
    for (int z = 0; z < 16; ++z)  // every other cell holds the far triangle (id 300) or nothing
      for (int y = 0; y < 16; ++y)
        for (int x = 1; x < 16; ++x)
          for (std::uint32_t id : grid.cell_primitives(x, y, z)) EXPECT_EQ(id, 300u);
    std::vector<Ray> rays = random_rays(g, s, 1000);
    for (int i = 0; i < 500; ++i) {  // and rays aimed into the crowded cell
      const Vec3 o = s.in_box(Vec3(-1.f), Vec3(2.f));
      rays.push_back({o, 0.f, Vec3{0.1f, 0.1f, 0.1f} + s.unit() * 0.015f - o});
    }
    expect_same_as_brute(g, grid, rays);
  }
}

// The queries on empty geometry are checked for every structure in accel_vs_brute_test.cpp;
// here, what is the grid's own: an empty id list, no cells, no work.
TEST(GridAdversarial, EmptyGeometry) {
  const Geometry g;
  const std::vector<std::uint32_t> none;
  const UniformGrid grid(g, none);
  Ray ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  Hit hit;
  TraversalStats st;
  EXPECT_FALSE(grid.intersect_counted(ray, hit, st));
  EXPECT_FALSE(grid.occluded_counted(ray, st));
  EXPECT_TRUE(grid.bounds().empty());
  EXPECT_EQ(grid.info().node_count, 0u);
  EXPECT_EQ(st.nodes_visited + st.prim_tests, 0u);
}

TEST(GridAdversarial, OnePrimitive) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 3);
  const auto ids = all_ids(g);
  const UniformGrid grid(g, ids);
  // A 2 x 2 x 2 box: 2 * cbrt(D / 8) cells per axis.
  const int n = int(std::lround(2.0 * std::cbrt(GridConfig{}.density / 8.0)));
  EXPECT_EQ(grid.info().node_count, std::size_t(n * n * n));
  // The queries' answers are checked for every structure (AccelVsBrute.OnePrimitive); here, the
  // grid's own: a ray that misses the grid's box costs nothing beyond the box test.
  TraversalStats st;
  Hit hit;
  Ray away{{0.f, 5.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  EXPECT_FALSE(grid.intersect_counted(away, hit, st));
  EXPECT_EQ(st.nodes_visited, 0u);
  EXPECT_EQ(st.prim_tests, 0u);
}

// A closest hit passed in (as the two-level structure does) limits the search and takes part in
// the tie rule: equal distances go to the lower id, whatever order the grid meets them in.
TEST(GridAdversarial, IncomingHitAndTies) {
  Geometry g;
  // Two coincident triangles (ids 0 and 1) and a sphere behind them.
  const Triangle t{{-1.f, -1.f, 2.f}, {1.f, -1.f, 2.f}, {0.f, 1.f, 2.f}};
  g.add(t, 0);
  g.add(t, 0);
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 1);
  const auto ids = all_ids(g);
  const UniformGrid grid(g, ids, GridConfig{8.f});
  Ray ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  Hit hit;
  ASSERT_TRUE(grid.intersect(ray, hit));
  EXPECT_EQ(hit.prim_id, 0u);
  EXPECT_FLOAT_EQ(hit.t, 2.f);
  // An incoming hit at the same distance with a higher id loses to triangle 0...
  Ray r2{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}, 2.f};
  Hit incoming{2.f, 7u, 0.f, 0.f};
  ASSERT_TRUE(grid.intersect(r2, incoming));
  EXPECT_EQ(incoming.prim_id, 0u);
  // ...and a closer incoming hit is kept: nothing is found and nothing changes.
  Ray r3{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}, 1.f};
  Hit closer{1.f, 9u, 0.f, 0.f};
  EXPECT_FALSE(grid.intersect(r3, closer));
  EXPECT_EQ(closer.prim_id, 9u);
  EXPECT_EQ(r3.tmax, 1.f);
}

// A grid over some of the primitives sees only those.
// ---------------------------------------------------------------------------------------------
// Mailboxes

// Big triangles crossing the whole grid, each in many cells: with mailboxes every primitive is
// tested at most once per ray; without, the same ones are tested again in each cell.
TEST(GridMailbox, EachPrimitiveTestedOncePerRay) {
  Sampler s(31);
  Geometry g;
  for (int i = 0; i < 40; ++i) g.add(random_triangle(s, s.in_box(Vec3(-2.f), Vec3(2.f)), 8.f), 0);
  const auto ids = all_ids(g);
  const UniformGrid with(g, ids, GridConfig{20.f, true, false});
  const UniformGrid without(g, ids, GridConfig{20.f, false, false});
  EXPECT_GT(with.mailbox_bytes_per_thread(), 0u);
  EXPECT_EQ(without.mailbox_bytes_per_thread(), 0u);
  std::uint64_t tests_with = 0, tests_without = 0;
  for (const Ray& ray : random_rays(g, s, 1000)) {
    TraversalStats a, b;
    Ray ra = ray, rb = ray;
    Hit ha, hb;
    const bool fa = with.intersect_counted(ra, ha, a), fb = without.intersect_counted(rb, hb, b);
    ASSERT_EQ(fa, fb);
    EXPECT_TRUE(same_hit(ha, hb));
    EXPECT_LE(a.prim_tests, g.size());
    EXPECT_LE(a.prim_tests, b.prim_tests);
    TraversalStats oa;
    with.occluded_counted(ray, oa);
    EXPECT_LE(oa.prim_tests, g.size());
    tests_with += a.prim_tests;
    tests_without += b.prim_tests;
  }
  // Measured: about a third of the tests saved at this density.
  EXPECT_LT(tests_with * 4, tests_without * 3) << "mailboxes should save the repeated tests";
}

// Mailbox stamps are per thread: rays traced concurrently on several threads still test each
// primitive at most once and agree with a single-threaded run.
TEST(GridMailbox, ThreadsDoNotShareStamps) {
  Sampler s(32);
  Geometry g;
  for (int i = 0; i < 30; ++i) g.add(random_triangle(s, s.in_box(Vec3(-2.f), Vec3(2.f)), 6.f), 0);
  const auto ids = all_ids(g);
  const UniformGrid grid(g, ids, GridConfig{20.f});
  const std::vector<Ray> rays = random_rays(g, s, 4000);
  std::vector<Hit> serial(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Ray r = rays[i];
    grid.intersect(r, serial[i]);
  }
  std::vector<Hit> parallel(rays.size());
  std::vector<std::uint64_t> tests(rays.size());
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (std::size_t i = t; i < rays.size(); i += 4) {
        Ray r = rays[i];
        TraversalStats st;
        grid.intersect_counted(r, parallel[i], st);
        tests[i] = st.prim_tests;
      }
    });
  }
  for (auto& th : threads) th.join();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_TRUE(same_hit(serial[i], parallel[i])) << i;
    EXPECT_LE(tests[i], g.size()) << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Resolution and storage

TEST(GridResolution, FollowsTheDensityRule) {
  // A 4 x 2 x 1 box, 1000 primitives, D = 2: s = cbrt(2000 / 8) = 6.30, n = round(e * s).
  const Box3 box{{0.f, 0.f, 0.f}, {4.f, 2.f, 1.f}};
  const double s = std::cbrt(2000.0 / 8.0);
  EXPECT_EQ(grid_resolution(box, 1000, 2.f),
            (std::array<int, 3>{int(std::lround(4 * s)), int(std::lround(2 * s)), int(std::lround(1 * s))}));
  // Cells scale with D and N: about D * N in all.
  for (float d : {0.5f, 2.f, 10.f}) {
    for (std::size_t n : {100u, 10000u, 1000000u}) {
      const auto r = grid_resolution({{-1.f, -2.f, -3.f}, {5.f, 1.f, 0.f}}, n, d);
      const double cells = double(r[0]) * r[1] * r[2];
      EXPECT_NEAR(cells / (d * n), 1.0, 0.35) << d << " " << n;
    }
  }
  // A flat box (no extent in z): one cell along z, the rule solved in the plane.
  const auto flat = grid_resolution({{0.f, 0.f, 0.f}, {4.f, 1.f, 0.f}}, 1000, 2.f);
  const double s2 = std::sqrt(2000.0 / 4.0);
  EXPECT_EQ(flat, (std::array<int, 3>{int(std::lround(4 * s2)), int(std::lround(1 * s2)), 1}));
  // A thin box: z would get far less than one cell; it gets one, and x and y share the rest.
  const auto thin = grid_resolution({{0.f, 0.f, 0.f}, {4.f, 1.f, 1e-4f}}, 1000, 2.f);
  EXPECT_EQ(thin, flat);
  // A box flat in two axes: cells along the remaining one only.
  EXPECT_EQ(grid_resolution({{0.f, 0.f, 0.f}, {0.f, 3.f, 0.f}}, 50, 2.f), (std::array<int, 3>{1, 100, 1}));
  // Degenerate inputs.
  EXPECT_EQ(grid_resolution({}, 10, 2.f), (std::array<int, 3>{1, 1, 1}));
  EXPECT_EQ(grid_resolution(box, 0, 2.f), (std::array<int, 3>{1, 1, 1}));
  EXPECT_EQ(grid_resolution({{1.f, 1.f, 1.f}, {1.f, 1.f, 1.f}}, 10, 2.f), (std::array<int, 3>{1, 1, 1}));
  // The cap on cells, with the proportions kept.
  const auto capped = grid_resolution(box, 100000000, 10.f);
  EXPECT_LE(double(capped[0]) * capped[1] * capped[2], double(kGridMaxCells));
  EXPECT_GT(double(capped[0]) * capped[1] * capped[2], 0.9 * double(kGridMaxCells));
  EXPECT_NEAR(double(capped[0]) / capped[2], 4.0, 0.1);
}

TEST(GridResolution, BuiltGridsUseIt) {
  Sampler s(41);
  const Geometry g = spheres_and_triangles(s);
  const auto ids = all_ids(g);
  for (float d : {1.f, 5.f}) {
    const UniformGrid grid(g, ids, GridConfig{d});
    EXPECT_EQ(grid.resolution(), grid_resolution(g.bounds(), g.size(), d));
    const auto r = grid.resolution();
    EXPECT_EQ(grid.info().node_count, std::size_t(r[0]) * r[1] * r[2]);
  }
  EXPECT_THROW(UniformGrid(g, ids, GridConfig{0.f}), std::exception);
  EXPECT_THROW(UniformGrid(g, ids, GridConfig{-1.f}), std::exception);
}

// Storage invariants: references are exactly the cells' lists, ascending within a cell, each
// primitive referenced at least once, and every cell that a primitive's box lies inside holds it.
TEST(GridStorage, CellListsAreConsistent) {
  Sampler s(42);
  const Geometry g = every_shape_kind(s);
  const auto ids = all_ids(g);
  const UniformGrid grid(g, ids, GridConfig{3.f});
  const auto r = grid.resolution();
  std::size_t refs = 0, nonempty = 0;
  std::set<std::uint32_t> seen;
  for (int z = 0; z < r[2]; ++z)
    for (int y = 0; y < r[1]; ++y)
      for (int x = 0; x < r[0]; ++x) {
        const auto prims = grid.cell_primitives(x, y, z);
        refs += prims.size();
        nonempty += prims.empty() ? 0 : 1;
        seen.insert(prims.begin(), prims.end());
        EXPECT_EQ(std::set<std::uint32_t>(prims.begin(), prims.end()).size(), prims.size()) << "duplicates";
      }
  EXPECT_EQ(refs, grid.reference_count());
  EXPECT_EQ(nonempty, grid.info().leaf_count);
  EXPECT_EQ(seen.size(), g.size());
  const AccelInfo info = grid.info();
  EXPECT_EQ(info.name, "grid");
  EXPECT_GE(info.memory_bytes, (info.node_count + 1 + refs) * sizeof(std::uint32_t));
  // The factory builds the grid with the default configuration.
  const auto made = make_accelerator("grid", g);
  EXPECT_EQ(made->info().name, "grid");
  EXPECT_EQ(made->info().node_count, UniformGrid(g, ids).info().node_count);
}

// Empty-space jumps change the work, not the answers, and save cells on a sparse scene.
TEST(GridSkip, JumpsVisitFewerCellsOnSparseScenes) {
  Sampler s(43);
  Geometry g;
  for (int i = 0; i < 200; ++i) g.add(Sphere{s.in_box(Vec3(-1.f), Vec3(1.f)), 0.05f}, 0);
  g.add(Sphere{{40.f, 40.f, 40.f}, 0.05f}, 1);  // far away: the box is mostly empty
  const auto ids = all_ids(g);
  const UniformGrid skip(g, ids, GridConfig{20.f, true, true});
  const UniformGrid walk(g, ids, GridConfig{20.f, true, false});
  TraversalStats a, b;
  for (const Ray& ray : random_rays(g, s, 2000)) {
    Ray ra = ray, rb = ray;
    Hit ha, hb;
    ASSERT_EQ(skip.intersect_counted(ra, ha, a), walk.intersect_counted(rb, hb, b));
    EXPECT_TRUE(same_hit(ha, hb));
  }
  EXPECT_EQ(a.prim_tests, b.prim_tests);
  EXPECT_LT(a.nodes_visited * 3, b.nodes_visited);
}

}  // namespace
}  // namespace raylab
