// The two-level grid ("grid2"): answers checked against brute force on the stress scenes for
// every combination of mailboxing and empty-space jumps and at extreme densities, on rays along
// cell faces, through corners, axis-parallel with +-0 components and far from the origin, on the
// teapot in a stadium (where it must adapt), on empty and one-primitive scenes; plus the build's
// invariants (cells tile the boxes, every primitive is in every cell it overlaps), the cells a
// ray walks (UniformGrid's too), and info(). (accel_vs_brute_test.cpp also runs "grid2" with
// its defaults under every wrap mode.)

#include "raylab/accel/two_level_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/uniform_grid.h"
#include "raylab/core/error.h"
#include "raylab/geometry/overlap.h"
#include "raylab/render/camera.h"
#include "stadium_scene.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

// {mailbox, skip_empty} at the default densities.
TwoLevelGridConfig variant(int i) {
  TwoLevelGridConfig c;
  c.mailbox = (i & 1) == 0;
  c.skip_empty = (i & 2) == 0;
  return c;
}

// `b` grown by `m` on every side.
Box3 grow(const Box3& b, float m) { return {b.lo - Vec3(m), b.hi + Vec3(m)}; }

// Whether `inner` lies in `outer`.
bool inside(const Box3& outer, const Box3& inner) { return outer.contains(inner.lo) && outer.contains(inner.hi); }

TwoLevelGridConfig densities(float top, float leaf) {
  TwoLevelGridConfig c;
  c.top_density = top;
  c.leaf_density = leaf;
  return c;
}

// ---------------------------------------------------------------------------------------------
// Against brute force

class Grid2Variant : public ::testing::TestWithParam<int> {};

TEST_P(Grid2Variant, StressScenesAgreeWithBruteForce) {
  for (const NamedScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    Sampler s(scene.seed + 200);
    const Geometry g = scene.make(s);
    const TwoLevelGrid grid(g, variant(GetParam()));
    EXPECT_EQ(grid.info().primitive_count, g.size());
    compare(g, grid, BruteForce(g), random_rays(g, s, 1500), s);
  }
}

TEST_P(Grid2Variant, RaysInFacePlanes) {
  Sampler s(61);
  const Geometry cubes = closed_meshes(s);
  rays_in_face_planes(TwoLevelGrid(cubes, variant(GetParam())), cubes, -2.f, 2.f, 62);
}

INSTANTIATE_TEST_SUITE_P(Grid2, Grid2Variant, ::testing::Range(0, 4), [](const auto& info) {
  return std::string((info.param & 1) ? "NoMailbox" : "Mailbox") + ((info.param & 2) ? "NoSkip" : "Skip");
});

// One-cell leaf grids (a tiny leaf density), a top grid finer than the primitives (a high top
// density) and fine leaves: the answers must not change.
TEST(Grid2Density, AnswersDoNotDependOnDensities) {
  for (const TwoLevelGridConfig& config : {densities(1.f, 1e-3f), densities(50.f, 1.f), densities(0.01f, 16.f)}) {
    SCOPED_TRACE(std::to_string(config.top_density) + " " + std::to_string(config.leaf_density));
    for (const NamedScene& scene : kScenes) {
      SCOPED_TRACE(scene.name);
      Sampler s(scene.seed + 300);
      const Geometry g = scene.make(s);
      compare(g, TwoLevelGrid(g, config), BruteForce(g), random_rays(g, s, 500), s);
    }
  }
}

TEST(Grid2Density, MustBePositive) {
  const Geometry g;
  EXPECT_THROW(TwoLevelGrid(g, densities(0.f, 1.f)), UsageError);
  EXPECT_THROW(TwoLevelGrid(g, densities(1.f, -1.f)), UsageError);
  EXPECT_THROW(TwoLevelGrid(g, densities(1.f, std::nanf(""))), UsageError);
}

// Spheres of radius 0.5 centred in the unit cubes of [0, 8]^3 (touching their cubes' faces) and
// triangles in the planes x = 4 and z = 2: primitives on and against cell planes.
Geometry lattice_scene() {
  Geometry g;
  g.add(Triangle{{4.f, 1.f, 1.f}, {4.f, 7.f, 2.f}, {4.f, 3.f, 7.f}}, 0);
  g.add(Triangle{{0.f, 0.f, 2.f}, {8.f, 0.f, 2.f}, {0.f, 8.f, 2.f}}, 0);
  for (int z = 0; z < 8; z += 2)
    for (int y = 0; y < 8; y += 2)
      for (int x = 0; x < 8; x += 2) g.add(Sphere{{x + 0.5f, y + 0.5f, z + 0.5f}, 0.5f}, 1);
  return g;
}

// Rays in lattice planes, along lattice lines, through lattice points (cell corners for every
// resolution that divides 8), axis-parallel with +0 and -0 components, starting on planes, and
// with tmin > 0.
std::vector<Ray> lattice_rays(Sampler& s) {
  std::vector<Ray> rays;
  auto integer = [&] { return float(s.rng.next_u32() % 9); };
  for (int i = 0; i < 3000; ++i) {
    Ray r;
    r.origin = s.in_box(Vec3(-2.f), Vec3(10.f));
    r.direction = s.unit();
    const int a = static_cast<int>(s.rng.next_u32() % 3), b = (a + 1) % 3;
    switch (i % 6) {
      case 0:  // in a lattice plane
        r.origin[a] = integer();
        r.direction[a] = signed_zero(s);
        break;
      case 1:  // along a lattice line
        r.origin[a] = integer();
        r.origin[b] = integer();
        r.direction[a] = signed_zero(s);
        r.direction[b] = signed_zero(s);
        break;
      case 2:  // through lattice points along a diagonal
        r.origin = {integer(), integer(), integer()};
        r.direction = {s.rng.next_float() < 0.5f ? 1.f : -1.f, s.rng.next_float() < 0.5f ? 1.f : -1.f,
                       s.rng.next_float() < 0.5f ? 1.f : -1.f};
        break;
      case 3:  // axis-parallel from inside
        r.origin = s.in_box(Vec3(0.f), Vec3(8.f));
        r.direction = {signed_zero(s), signed_zero(s), signed_zero(s)};
        r.direction[a] = s.rng.next_float() < 0.5f ? 1.f : -1.f;
        break;
      case 4:  // aimed at a lattice point from inside
        r.origin = s.in_box(Vec3(0.f), Vec3(8.f));
        r.direction = Vec3{integer(), integer(), integer()} - r.origin;
        break;
      default:  // tmin > 0
        r.tmin = s.uni(0.f, 6.f);
        break;
    }
    if (r.direction == Vec3(0.f)) r.direction = {0.f, 0.f, 1.f};
    rays.push_back(r);
  }
  return rays;
}

TEST(Grid2Lattice, BoundaryCornerAndAxisParallelRaysAgreeWithBruteForce) {
  const Geometry g = lattice_scene();
  // Densities that put top and leaf planes on the lattice's integers (8 top cells per axis over
  // the 8-unit box, 1 and 2 leaf cells per axis) and ones that do not.
  for (const TwoLevelGridConfig& config : {TwoLevelGridConfig{}, densities(4.f, 1.f), densities(0.2f, 8.f)}) {
    for (int v = 0; v < 4; ++v) {
      TwoLevelGridConfig c = config;
      c.mailbox = variant(v).mailbox;
      c.skip_empty = variant(v).skip_empty;
      Sampler s(11);
      compare(g, TwoLevelGrid(g, c), BruteForce(g), lattice_rays(s), s);
    }
  }
}

// The lattice shifted far from the origin (coordinates near 1e4, cells of 1 or less): rounding
// of entry points and boundary distances is then thousands of times a cell's ulp.
TEST(Grid2Lattice, FarFromTheOriginAgreesWithBruteForce) {
  Geometry g = lattice_scene();
  const Vec3 shift{1e4f, -2e4f, 3e3f};
  for (Sphere& sp : g.spheres) sp.center += shift;
  for (Triangle& t : g.triangles) t = {t.p0 + shift, t.p1 + shift, t.p2 + shift};
  Sampler s(12);
  std::vector<Ray> rays = lattice_rays(s);
  for (Ray& r : rays) r.origin += shift;
  compare(g, TwoLevelGrid(g), BruteForce(g), rays, s);
}

// ---------------------------------------------------------------------------------------------
// Adaptivity: the teapot in a stadium

TEST(Grid2Adversarial, TeapotInAStadium) {
  const Geometry g = teapot_in_stadium();
  Sampler s(17);
  std::vector<Ray> rays = random_rays(g, s, 600);
  const Camera camera(teapot_in_stadium_camera(), 32, 24);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) rays.push_back(camera.generate(float(x) + 0.5f, float(y) + 0.5f));
  for (int i = 0; i < 300; ++i) {  // at the teapot from nearby
    const Vec3 o = s.in_box({-3.f, -3.f, 0.f}, {3.f, 3.f, 3.f});
    rays.push_back({o, 0.f, point_on(g, s.rng.next_u32() % 2256, s) - o});
  }
  const TwoLevelGrid grid(g);
  compare(g, grid, BruteForce(g), rays, s);
  // The ground and the spheres span their top cells and go to the cells' lists, so the leaf
  // grid of the teapot's cell covers the teapot only: at least 20 times fewer tests than the
  // uniform grid, which puts the whole teapot in a cell or two.
  const UniformGrid uniform(g);
  TraversalStats two_level, one_level;
  for (const Ray& ray : rays) {
    Ray r1 = ray, r2 = ray;
    Hit h1, h2;
    grid.intersect_counted(r1, h1, two_level);
    uniform.intersect_counted(r2, h2, one_level);
  }
  EXPECT_LT(two_level.prim_tests * 20, one_level.prim_tests);
}

// ---------------------------------------------------------------------------------------------
// Contract details

TEST(Grid2, EmptyGeometry) {
  const Geometry g;
  const std::vector<std::uint32_t> none;
  const TwoLevelGrid grid(g, none);
  Ray ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  Hit hit;
  TraversalStats st;
  EXPECT_FALSE(grid.intersect_counted(ray, hit, st));
  EXPECT_FALSE(grid.occluded_counted(ray, st));
  EXPECT_TRUE(grid.bounds().empty());
  EXPECT_EQ(grid.info().node_count, 0u);
  EXPECT_EQ(grid.info().max_depth, 0);
  EXPECT_EQ(st.nodes_visited + st.prim_tests, 0u);
  EXPECT_TRUE(grid.cells_on_ray(ray).empty());
}

TEST(Grid2, OnePrimitive) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 3);
  const TwoLevelGrid grid(g);
  // The queries' answers are checked for every structure (AccelVsBrute.OnePrimitive); here, the
  // grid's own: a ray that misses the box costs nothing beyond the box test.
  TraversalStats st;
  Hit hit;
  Ray away{{0.f, 5.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  EXPECT_FALSE(grid.intersect_counted(away, hit, st));
  EXPECT_EQ(st.nodes_visited + st.prim_tests, 0u);
}

TEST(Grid2, SubsetOfIdsAndIncomingHit) {
  Sampler s(31);
  const Geometry g = every_shape_kind(s);
  const std::vector<std::uint32_t> ids = every_third_id(g);
  const TwoLevelGrid grid(g, ids);
  const BruteForce brute(g, ids);
  EXPECT_EQ(grid.info().primitive_count, ids.size());
  int hits = 0;
  for (const Ray& ray : random_rays(g, s, 800)) {
    const auto [rb, hb, fb, rv, hv, fv] = both_hits(brute, grid, ray);
    ASSERT_EQ(fb, fv) << describe(ray);
    if (!fb) continue;
    ++hits;
    EXPECT_TRUE(near(hb.t, hv.t)) << describe(ray);
    EXPECT_TRUE(hb.prim_id == hv.prim_id || is_tie(g, hv.prim_id, ray, hb.t)) << describe(ray);
    EXPECT_TRUE(std::binary_search(ids.begin(), ids.end(), hv.prim_id));
    // A closest hit passed in limits the search: nothing beyond it, and it stays when nothing
    // is closer.
    Ray limited = ray;
    limited.tmax = hb.t * 0.999f;
    Hit prior{limited.tmax, 12345u, 0.f, 0.f};
    if (!grid.intersect(limited, prior)) {
      EXPECT_EQ(prior.prim_id, 12345u);
    } else {
      EXPECT_LT(prior.t, hb.t);
    }
  }
  EXPECT_GT(hits, 80);
}

TEST(Grid2Mailbox, EachPrimitiveTestedOncePerRay) {
  Sampler s(32);
  Geometry g;
  for (int i = 0; i < 60; ++i) g.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(2.f, 5.f)}, 0);  // span cells
  const TwoLevelGrid with(g, densities(4.f, 8.f)), without(g, [] {
    TwoLevelGridConfig c = densities(4.f, 8.f);
    c.mailbox = false;
    return c;
  }());
  std::uint64_t tests_with = 0, tests_without = 0;
  for (const Ray& ray : random_rays(g, s, 300)) {
    TraversalStats a, b;
    Ray r1 = ray, r2 = ray;
    Hit h1, h2;
    EXPECT_EQ(with.intersect_counted(r1, h1, a), without.intersect_counted(r2, h2, b));
    EXPECT_LE(a.prim_tests, g.size());
    tests_with += a.prim_tests;
    tests_without += b.prim_tests;
  }
  EXPECT_LT(tests_with, tests_without);  // big spheres sit in many cells
}

// ---------------------------------------------------------------------------------------------
// Build invariants

// Every primitive that overlaps a top cell is in its list or in every leaf cell it overlaps;
// top cells tile the box, leaf grids lie in their cells and their cells tile the leaf box.
void check_invariants(const Geometry& g, const TwoLevelGrid& grid) {
  const auto res = grid.top_resolution();
  const Box3 box = grid.bounds();
  const Box3 first = grid.top_cell_box(0, 0, 0), last = grid.top_cell_box(res[0] - 1, res[1] - 1, res[2] - 1);
  EXPECT_EQ(first.lo, box.lo);
  EXPECT_EQ(last.hi, box.hi);
  std::size_t top_cells = 0, leaf_cells = 0, nonempty = 0, refs = 0;
  int missing = 0;
  for (int z = 0; z < res[2]; ++z)
    for (int y = 0; y < res[1]; ++y)
      for (int x = 0; x < res[0]; ++x) {
        ++top_cells;
        const Box3 cell = grid.top_cell_box(x, y, z);
        if (x + 1 < res[0]) {
          EXPECT_EQ(cell.hi.x, grid.top_cell_box(x + 1, y, z).lo.x);
        }
        if (y + 1 < res[1]) {
          EXPECT_EQ(cell.hi.y, grid.top_cell_box(x, y + 1, z).lo.y);
        }
        if (z + 1 < res[2]) {
          EXPECT_EQ(cell.hi.z, grid.top_cell_box(x, y, z + 1).lo.z);
        }
        const auto list = grid.top_cell_primitives(x, y, z);
        refs += list.size();
        for (std::uint32_t id : list)
          EXPECT_TRUE(overlaps_box(g, id, grow(cell, 1e-3f * max_component(cell.extent()))));
        const auto lr = grid.leaf_resolution(x, y, z);
        if (lr[0] == 0) continue;
        const Box3 leaf_box = grid.leaf_grid_box(x, y, z);
        EXPECT_TRUE(inside(cell, leaf_box)) << x << " " << y << " " << z;
        EXPECT_EQ(grid.leaf_cell_box(x, y, z, 0, 0, 0).lo, leaf_box.lo);
        EXPECT_EQ(grid.leaf_cell_box(x, y, z, lr[0] - 1, lr[1] - 1, lr[2] - 1).hi, leaf_box.hi);
        for (int k = 0; k < lr[2]; ++k)
          for (int j = 0; j < lr[1]; ++j)
            for (int i = 0; i < lr[0]; ++i) {
              ++leaf_cells;
              const Box3 leaf = grid.leaf_cell_box(x, y, z, i, j, k);
              const auto prims = grid.leaf_cell_primitives(x, y, z, i, j, k);
              nonempty += !prims.empty();
              refs += prims.size();
              EXPECT_TRUE(std::is_sorted(prims.begin(), prims.end()));
              for (std::uint32_t id = 0; id < g.size(); ++id) {
                if (!overlaps_box(g, id, leaf)) continue;
                const bool listed = std::binary_search(list.begin(), list.end(), id) ||
                                    std::binary_search(prims.begin(), prims.end(), id);
                if (!listed && ++missing <= 5) ADD_FAILURE() << "primitive " << id << " not in its leaf cell";
              }
            }
      }
  EXPECT_EQ(missing, 0);
  const AccelInfo info = grid.info();
  EXPECT_EQ(info.name, "grid2");
  EXPECT_EQ(info.node_count, top_cells + leaf_cells);
  EXPECT_EQ(info.leaf_count, nonempty);
  EXPECT_EQ(grid.leaf_cell_count(), leaf_cells);
  EXPECT_EQ(grid.reference_count(), refs);
  EXPECT_EQ(info.max_depth, 1);
  EXPECT_GE(info.memory_bytes, refs * 4 + g.size() * 4 + (leaf_cells + 1) * 4);
}

TEST(Grid2Build, EveryPrimitiveIsInEveryCellItOverlaps) {
  for (const NamedScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    Sampler s(scene.seed + 400);
    const Geometry g = scene.make(s);
    check_invariants(g, TwoLevelGrid(g, densities(1.f, 1.f)));
  }
  check_invariants(lattice_scene(), TwoLevelGrid(lattice_scene(), densities(4.f, 1.f)));
}

TEST(Grid2Build, BigPrimitivesGoToTheTopCellsLists) {
  // A ground quad under a few small spheres: every top cell it crosses lists it, and the leaf
  // grid of the cell with the spheres covers their box only.
  Geometry g;
  g.add(Quad{{-100.f, -100.f, 0.f}, {200.f, 0.f, 0.f}, {0.f, 200.f, 0.f}}, 0);
  for (int i = 0; i < 50; ++i) g.add(Sphere{{0.01f * i, 0.f, 1.f}, 0.01f}, 1);
  const TwoLevelGrid grid(g);
  const auto res = grid.top_resolution();
  std::uint32_t quad = 0;  // ids go by kind, the quad's after the spheres'
  while (g.bounds(quad).extent().x < 100.f) ++quad;
  int listing = 0;
  for (int y = 0; y < res[1]; ++y)
    for (int x = 0; x < res[0]; ++x) listing += grid.top_cell_primitives(x, y, 0) == std::vector<std::uint32_t>{quad};
  EXPECT_EQ(listing, res[0] * res[1]);
  const Box3 c = grid.bounds();
  const Vec3 centre = c.center();
  const int x = int((0.25f - c.lo.x) / c.extent().x * res[0]), y = int((0.f - c.lo.y) / c.extent().y * res[1]);
  const int z = int((centre.z - c.lo.z) / std::max(c.extent().z, 1e-6f) * res[2]);
  const Box3 leaf = grid.leaf_grid_box(x, y, std::min(z, res[2] - 1));
  EXPECT_LT(max_component(leaf.extent()), 1.f);
  check_invariants(g, grid);
}

// ---------------------------------------------------------------------------------------------
// The cells a ray walks (CellWalk), for both grids

// cells_on_ray reports exactly the cells the counted query counts, in the order the ray meets
// them, each crossed by the ray before its closest hit.
void check_walk(const Accelerator& accel, const CellWalk& walk, const std::vector<Ray>& rays) {
  int bad = 0;
  for (const Ray& ray : rays) {
    const auto [rc, hc, fc, st] = counted_hit(accel, ray);
    const std::vector<WalkedCell> cells = walk.cells_on_ray(ray);
    if (cells.size() != st.nodes_visited && ++bad <= 5) {
      ADD_FAILURE() << cells.size() << " cells, " << st.nodes_visited << " counted for " << describe(ray);
    }
    const float end = fc ? hc.t : ray.tmax;
    for (const WalkedCell& c : cells) {
      // The ray's stretch through the cell: the slab test on the box, enlarged by rounding.
      const Box3 box = grow(c.box, 1e-4f * std::max(1.f, max_component(abs(c.box.hi)) + max_component(abs(c.box.lo))));
      float t0 = ray.tmin, t1 = end;
      for (int a = 0; a < 3; ++a) {
        if (ray.direction[a] == 0.f) {
          if (ray.origin[a] < box.lo[a] || ray.origin[a] > box.hi[a]) t0 = kInf;
          continue;
        }
        float ta = (box.lo[a] - ray.origin[a]) / ray.direction[a], tb = (box.hi[a] - ray.origin[a]) / ray.direction[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
      }
      if (!(t0 <= t1 * 1.0001f + 1e-4f) && ++bad <= 5) ADD_FAILURE() << "a walked cell off the ray: " << describe(ray);
    }
  }
  EXPECT_EQ(bad, 0);
}

TEST(Grid2Walk, CellsOnRayAreTheKernelsCells) {
  Sampler s(41);
  const Geometry g = spheres_and_triangles(s);
  const std::vector<Ray> rays = random_rays(g, s, 400);
  for (int v = 0; v < 4; ++v) {
    const TwoLevelGrid grid(g, variant(v));
    check_walk(grid, grid, rays);
  }
  const Geometry stadium = teapot_in_stadium();
  const TwoLevelGrid grid(stadium);
  check_walk(grid, grid, random_rays(stadium, s, 300));
}

TEST(Grid2Walk, UniformGridCellsOnRayAreTheKernelsCells) {
  Sampler s(42);
  const Geometry g = spheres_and_triangles(s);
  const std::vector<Ray> rays = random_rays(g, s, 400);
  for (bool skip : {true, false}) {
    GridConfig c;
    c.skip_empty = skip;
    const UniformGrid grid(g, c);
    check_walk(grid, grid, rays);
  }
}

TEST(Grid2Walk, WithoutJumpsTheCellsFollowTheRay) {
  // Without jumps, the top cells follow each other along the ray, face to face.
  Sampler s(43);
  const Geometry g = spheres_and_triangles(s);
  TwoLevelGridConfig c;
  c.skip_empty = false;
  const TwoLevelGrid grid(g, c);
  for (const Ray& ray : random_rays(g, s, 200)) {
    std::vector<Box3> tops;
    for (const WalkedCell& cell : grid.cells_on_ray(ray)) {
      // Top cells are the ones of the top grid's size.
      const Vec3 e = cell.box.extent(), t = grid.top_cell_box(0, 0, 0).extent();
      if (std::fabs(e.x - t.x) <= 1e-4f * t.x && std::fabs(e.y - t.y) <= 1e-4f * t.y &&
          std::fabs(e.z - t.z) <= 1e-4f * t.z)
        tops.push_back(cell.box);
    }
    for (std::size_t i = 1; i < tops.size(); ++i) {
      int shared = 0;  // adjacent cells share a face: equal bounds on two axes, touching on one
      for (int a = 0; a < 3; ++a)
        shared += tops[i].lo[a] == tops[i - 1].lo[a] || tops[i].lo[a] == tops[i - 1].hi[a] ||
                  tops[i].hi[a] == tops[i - 1].lo[a];
      EXPECT_EQ(shared, 3) << describe(ray);
    }
  }
}

}  // namespace
}  // namespace raylab
