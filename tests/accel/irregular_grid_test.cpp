// The irregular grid must answer every query as brute force does (up to float ties) for every
// build configuration (no merging, no expansion, one level, fine cells, mailboxes), on the stress
// scenes of test_scenes.h and on rays aimed at its own weak points: rays in lattice planes, along
// cell edges, from and through cell corners, axis-parallel rays with +0 and -0, far coordinates.
// Its cells must tile the lattice, hold every primitive touching them, and expand only over
// cells whose references they hold; cells_on_ray must be the walk the counted query does.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/irregular_grid.h"
#include "raylab/core/error.h"
#include "raylab/geometry/overlap.h"
#include "raylab/render/camera.h"
#include "stadium_scene.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

IrregularGridConfig with(void (*change)(IrregularGridConfig&)) {
  IrregularGridConfig c;
  change(c);
  return c;
}

struct NamedConfig {
  const char* name;
  IrregularGridConfig config;
};

// The default, each stage off, one level only, fine cells, a cost model that merges nothing
// unequal, and mailboxes.
const std::vector<NamedConfig> kConfigs = {
    {"default", {}},
    {"no merge", with([](IrregularGridConfig& c) { c.merge_rounds = 0; })},
    {"no expansion", with([](IrregularGridConfig& c) { c.expand_rounds = 0; })},
    {"top level only", with([](IrregularGridConfig& c) { c.max_depth = 0; })},
    {"two levels", with([](IrregularGridConfig& c) { c.max_depth = 3; })},
    {"fine", with([](IrregularGridConfig& c) { c.top_density = 1.f, c.sub_density = 8.f, c.max_shift = 6; })},
    {"costly tests", with([](IrregularGridConfig& c) { c.prim_cost = 100.f, c.expand_rounds = 8; })},
    {"no mailbox", with([](IrregularGridConfig& c) { c.mailbox = false; })},
};

// Checks every query of `grid` against brute force on `rays`; returns the total work.
TraversalStats check(const Geometry& g, const IrregularGrid& grid, const std::vector<Ray>& rays,
                     const std::string& label) {
  const BruteForce brute(g);
  Sampler s(99);
  int failures = 0;
  auto fail = [&](const std::string& what, const Ray& r) {
    if (++failures <= 5) ADD_FAILURE() << label << ": " << what << " for " << describe(r);
  };
  TraversalStats total;
  for (const Ray& ray : rays) {
    const auto [rb, hb, fb, rv, hv, fv] = both_hits(brute, grid, ray);
    if (const std::string wrong = closest_hit_disagreement(g, ray, fb, hb, fv, hv, rv); !wrong.empty()) {
      fail(wrong, ray);
    }
    const auto [rc, hc, fc, st] = counted_hit(grid, ray);
    if (fc != fv || !same_hit(hc, hv)) fail("intersect_counted differs from intersect", ray);
    // cells_on_ray is the counted query's own walk.
    if (grid.cells_on_ray(ray).size() != st.nodes_visited) fail("cells_on_ray differs from the walk", ray);
    total += st;

    // Any-hit, with a random tmax well away from the closest hit.
    Ray sh = with_random_tmax(ray, fb, hb.t, s);
    if (!(sh.tmax > sh.tmin)) sh.tmax = kInf;
    if (fb && std::fabs(sh.tmax - hb.t) <= kRelTol * hb.t) continue;
    const bool expected = fb && hb.t < sh.tmax;
    TraversalStats so;
    if (grid.occluded(sh) != expected) fail(expected ? "occluded missed" : "occluded phantom", sh);
    if (grid.occluded_counted(sh, so) != expected) fail("occluded_counted", sh);
  }
  EXPECT_EQ(failures, 0) << label << ": of " << rays.size() << " rays";
  return total;
}

// ---------------------------------------------------------------------------------------------
// Against brute force on the shared stress scenes

class IrregularGridVsBrute : public ::testing::TestWithParam<int> {};

TEST_P(IrregularGridVsBrute, EveryConfiguration) {
  const NamedScene& scene = kScenes[static_cast<std::size_t>(GetParam())];
  Sampler s(scene.seed + 300);
  const Geometry g = scene.make(s);
  const std::vector<Ray> rays = random_rays(g, s, 1200);
  for (const NamedConfig& c : kConfigs) {
    const IrregularGrid grid(g, c.config);
    EXPECT_EQ(grid.info().primitive_count, g.size());
    EXPECT_EQ(grid.bounds().lo, g.bounds().lo);
    EXPECT_EQ(grid.bounds().hi, g.bounds().hi);
    const TraversalStats st = check(g, grid, rays, std::string(scene.name) + " " + c.name);
    if (c.config.max_depth > 0) {  // a real grid tests far fewer than all
      EXPECT_LT(st.prim_tests * 4, std::uint64_t(g.size()) * rays.size()) << c.name;
    }
  }
}

std::string scene_name(const ::testing::TestParamInfo<int>& info) {
  return kScenes[static_cast<std::size_t>(info.param)].name;
}
INSTANTIATE_TEST_SUITE_P(Scenes, IrregularGridVsBrute, ::testing::Range(0, static_cast<int>(kScenes.size())),
                         scene_name);

// ---------------------------------------------------------------------------------------------
// The build's invariants

bool boxes_meet(const std::array<std::uint16_t, 6>& a, const std::uint16_t lo[3], const std::uint16_t hi[3]) {
  for (int k = 0; k < 3; ++k) {
    if (a[k] >= hi[k] || lo[k] >= a[k + 3]) return false;
  }
  return true;
}

std::vector<std::uint32_t> refs_of(const IrregularGridData& d, std::size_t c) {
  return {d.refs.begin() + d.cells[c].first, d.refs.begin() + d.cells[c + 1].first};
}

void check_invariants(const Geometry& g, const IrregularGridData& d, const std::string& label) {
  SCOPED_TRACE(label);
  const std::size_t n = d.cell_count();
  ASSERT_EQ(d.boxes.size(), n);
  ASSERT_EQ(d.cells.back().first, d.refs.size());
  EXPECT_EQ(d.top.size(), std::size_t(d.top_res[0]) * d.top_res[1] * d.top_res[2]);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(d.lattice[a], d.top_res[a] << d.depth);
    EXPECT_LE(d.lattice[a], kIrregularMaxLattice);
    EXPECT_EQ(d.plane(a, 0), d.bounds.lo[a]);
    EXPECT_GE(d.plane(a, d.lattice[a]), d.bounds.hi[a]) << "the lattice covers the primitives";
  }
  for (const auto& node : d.nodes) EXPECT_GE(node.shift, 1u);
  // The cells tile the lattice: their volumes add up to it, and every voxel's cell holds it.
  std::uint64_t volume = 0;
  for (const auto& b : d.boxes) {
    for (int a = 0; a < 3; ++a) ASSERT_LT(b[a], b[a + 3]);
    volume += std::uint64_t(b[3] - b[0]) * (b[4] - b[1]) * (b[5] - b[2]);
  }
  EXPECT_EQ(volume, std::uint64_t(d.lattice[0]) * d.lattice[1] * d.lattice[2]);
  Sampler s(7);
  for (int i = 0; i < 20000; ++i) {
    const std::uint32_t v[3] = {s.rng.next_u32() % d.lattice[0], s.rng.next_u32() % d.lattice[1],
                                s.rng.next_u32() % d.lattice[2]};
    const auto& b = d.boxes[d.cell_at(v[0], v[1], v[2])];
    for (int a = 0; a < 3; ++a) ASSERT_TRUE(b[a] <= v[a] && v[a] < b[a + 3]) << "voxel outside its cell";
  }
  std::size_t nonempty = 0;
  for (std::size_t c = 0; c < n; ++c) {
    const std::vector<std::uint32_t> mine = refs_of(d, c);
    nonempty += !mine.empty();
    EXPECT_TRUE(std::adjacent_find(mine.begin(), mine.end(), std::greater_equal<>()) == mine.end())
        << "references must be ascending and unique";
    // Every primitive touching the cell's own box is referenced. (Not checked for cylinders,
    // whose overlap test is only conservative and need not accept a box when it accepts a
    // larger one.)
    const Box3 box = d.lattice_box(d.boxes[c].data(), d.boxes[c].data() + 3);
    for (std::uint32_t slot = 0; slot < d.ids.size(); ++slot) {
      if (g.resolve(d.ids[slot]).kind == ShapeKind::kCylinder) continue;
      const Box3 pb = g.bounds(d.ids[slot]);
      const bool near_box = pb.lo.x <= box.hi.x && box.lo.x <= pb.hi.x && pb.lo.y <= box.hi.y && box.lo.y <= pb.hi.y &&
                            pb.lo.z <= box.hi.z && box.lo.z <= pb.hi.z;
      if (!near_box || !overlaps_box(g, d.ids[slot], box)) continue;
      EXPECT_TRUE(std::binary_search(mine.begin(), mine.end(), slot)) << "cell " << c << " lacks slot " << slot;
    }
    // The expanded box holds the cell, and every cell it meets lists only the cell's references.
    const IrregularCell& e = d.cells[c];
    for (int a = 0; a < 3; ++a) EXPECT_TRUE(e.lo[a] <= d.boxes[c][a] && d.boxes[c][a + 3] <= e.hi[a]);
    for (std::size_t o = 0; o < n; ++o) {
      if (o == c || !boxes_meet(d.boxes[o], e.lo, e.hi)) continue;
      const std::vector<std::uint32_t> theirs = refs_of(d, o);
      EXPECT_TRUE(std::includes(mine.begin(), mine.end(), theirs.begin(), theirs.end()))
          << "cell " << c << " expanded over cell " << o;
    }
  }
  EXPECT_EQ(d.nonempty_cells, nonempty);
}

TEST(IrregularGridBuild, CellsTileTheLatticeAndHoldEveryTouchingPrimitive) {
  for (int scene : {0, 1, 4, 5}) {
    Sampler s(kScenes[scene].seed + 400);
    const Geometry g = kScenes[scene].make(s);
    for (const NamedConfig& c : {kConfigs[0], kConfigs[1], kConfigs[2], kConfigs[4]}) {
      check_invariants(g, build_irregular_grid(g, g.primitive_ids(), c.config),
                       std::string(kScenes[scene].name) + " " + c.name);
    }
  }
}

// Merging and expanding are what make the grid irregular: merging leaves fewer cells, and
// expansion lets rays cross in fewer steps.
TEST(IrregularGridBuild, MergingAndExpansionPay) {
  Sampler s(8);
  const Geometry g = spheres_and_triangles(s);
  const IrregularGridConfig merged{};
  const IrregularGridConfig unmerged = with([](IrregularGridConfig& c) { c.merge_rounds = 0; });
  const IrregularGridConfig unexpanded = with([](IrregularGridConfig& c) { c.expand_rounds = 0; });
  EXPECT_LT(IrregularGrid(g, merged).info().node_count * 4, IrregularGrid(g, unmerged).info().node_count * 3);
  const std::vector<Ray> rays = random_rays(g, s, 2000);
  auto cells_visited = [&](const IrregularGridConfig& c) {
    const IrregularGrid grid(g, c);
    std::uint64_t visited = 0;
    for (const Ray& r : rays) visited += counted_hit(grid, r).stats.nodes_visited;
    return visited;
  };
  EXPECT_LT(cells_visited(merged), cells_visited(unexpanded));
}

TEST(IrregularGridBuild, SubdivisionFollowsTheCountsAndTheCap) {
  Sampler s(9);
  const Geometry g = dense_soup(s);
  const IrregularGridData one = build_irregular_grid(g, g.primitive_ids(), with([](IrregularGridConfig& c) {
                                                       c.max_depth = 0;
                                                       c.merge_rounds = 0;
                                                     }));
  EXPECT_EQ(one.cell_count(), one.top.size());  // no subdivision: one cell per top cell
  EXPECT_TRUE(one.nodes.empty());
  const IrregularGridData deep = build_irregular_grid(g, g.primitive_ids(), with([](IrregularGridConfig& c) {
                                                        c.max_shift = 1;
                                                        c.max_depth = 5;
                                                        c.merge_rounds = 0;
                                                      }));
  EXPECT_EQ(deep.depth, 5);
  ASSERT_FALSE(deep.nodes.empty());
  // Every step halves (max_shift 1), and a dense soup needs more than one of them somewhere.
  bool nested = false;
  for (const auto& node : deep.nodes) {
    EXPECT_EQ(node.shift, 1u);
    for (std::uint32_t i = 0; i < 8; ++i) nested = nested || !(deep.map[node.begin + i] & IrregularGridData::kLeaf);
  }
  EXPECT_TRUE(nested);
}

TEST(IrregularGridBuild, RejectsInvalidParameters) {
  const Geometry g;
  for (auto change :
       {+[](IrregularGridConfig& c) { c.top_density = 0.f; }, +[](IrregularGridConfig& c) { c.sub_density = -1.f; },
        +[](IrregularGridConfig& c) { c.max_shift = 7; }, +[](IrregularGridConfig& c) { c.max_shift = 0; },
        +[](IrregularGridConfig& c) { c.max_depth = 17; }, +[](IrregularGridConfig& c) { c.prim_cost = std::nanf(""); },
        +[](IrregularGridConfig& c) { c.merge_rounds = -1; }}) {
    EXPECT_THROW(IrregularGrid(g, with(change)), UsageError);
  }
}

// ---------------------------------------------------------------------------------------------
// Rays at the grid's weak points

// Rays in the lattice planes of cell faces, along cell edges, from cell corners and through them.
std::vector<Ray> boundary_rays(const IrregularGridData& d, Sampler& s, int count) {
  return rays_at_lattice_points(d.bounds, s, count, [&] {
    const auto& b = d.boxes[s.rng.next_u32() % d.boxes.size()];
    return Vec3{d.plane(0, b[3 * (s.rng.next_u32() % 2)]), d.plane(1, b[1 + 3 * (s.rng.next_u32() % 2)]),
                d.plane(2, b[2 + 3 * (s.rng.next_u32() % 2)])};
  });
}

TEST(IrregularGridAdversarial, RaysAlongAndThroughCellBoundaries) {
  for (int scene : {0, 4, 5}) {
    Sampler s(kScenes[scene].seed + 500);
    const Geometry g = kScenes[scene].make(s);
    for (const NamedConfig& c : {kConfigs[0], kConfigs[4]}) {
      const IrregularGridData d = build_irregular_grid(g, g.primitive_ids(), c.config);
      check(g, IrregularGrid(g, c.config), boundary_rays(d, s, 1000), std::string(kScenes[scene].name) + " " + c.name);
    }
  }
}

// Axis-aligned faces lying in lattice planes, hit by axis-parallel rays with +0 and -0.
TEST(IrregularGridAdversarial, AxisAlignedFacesOnLatticePlanes) {
  Geometry g;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(g, {2.f, 2.f, 2.f}, 2.f, 8, identity, 0);
  add_cube_mesh(g, {2.f, 2.f, 2.f}, 1.f, 8, identity, 1);
  Sampler s(13);
  const IrregularGridConfig fine = kConfigs[4].config;
  std::vector<Ray> rays = boundary_rays(build_irregular_grid(g, g.primitive_ids(), fine), s, 1000);
  const std::vector<Ray> axis_rays = axis_rays_in_cube_faces(s, 1500);
  rays.insert(rays.end(), axis_rays.begin(), axis_rays.end());
  check(g, IrregularGrid(g), rays, "cubes default");
  check(g, IrregularGrid(g, fine), rays, "cubes fine");
}

// Coordinates far from the origin: the margins scale with them.
TEST(IrregularGridAdversarial, FarFromTheOrigin) {
  Sampler s(14);
  Geometry g;
  const Vec3 far{3e4f, -2e4f, 1e4f};
  for (int i = 0; i < 300; ++i) g.add(random_triangle(s, far + s.in_box(Vec3(-5.f), Vec3(5.f)), 0.8f), 0);
  g.add(Sphere{far + Vec3(1.f, 1.f, 1.f), 2.f}, 1);
  std::vector<Ray> rays = random_rays(g, s, 1500);
  check(g, IrregularGrid(g), rays, "far");
}

// The teapot in a stadium: a dense mesh 1/1000 of a huge sparse scene.
TEST(IrregularGridAdversarial, TeapotInAStadium) {
  const Geometry g = teapot_in_stadium();
  Sampler s(17);
  std::vector<Ray> rays = random_rays(g, s, 500);
  const Camera camera(teapot_in_stadium_camera(), 32, 24);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) rays.push_back(camera.generate(float(x) + 0.5f, float(y) + 0.5f));
  for (int i = 0; i < 300; ++i) {
    const Vec3 o = s.in_box({-3.f, -3.f, 0.f}, {3.f, 3.f, 3.f});
    rays.push_back({o, 0.f, point_on(g, s.rng.next_u32() % 2256, s) - o});
  }
  const TraversalStats st = check(g, IrregularGrid(g), rays, "stadium");
  // Adaptivity: far fewer tests than the teapot's 2256 triangles for each ray that meets it.
  EXPECT_LT(st.prim_tests, 100 * rays.size());
}

// ---------------------------------------------------------------------------------------------
// Contract details

TEST(IrregularGrid, EmptyGeometry) {
  const Geometry g;
  const IrregularGrid grid(g);
  Ray ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  Hit hit;
  TraversalStats st;
  EXPECT_FALSE(grid.intersect_counted(ray, hit, st));
  EXPECT_FALSE(grid.occluded_counted(ray, st));
  EXPECT_EQ(grid.info().node_count, 0u);
  EXPECT_EQ(st.nodes_visited, 0u);
  EXPECT_TRUE(grid.cells_on_ray(ray).empty());
}

TEST(IrregularGrid, SinglePrimitive) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 3);
  const IrregularGrid grid(g);
  // The queries' answers are checked for every structure (AccelVsBrute.OnePrimitive).
  EXPECT_GE(grid.info().leaf_count, 1u);
}

// The walk drawn by cells_on_ray: boxes in ray order, each one entered no later than the ray
// leaves the previous, the last one holding the hit.
TEST(IrregularGrid, CellsOnRayFollowTheRay) {
  Sampler s(15);
  const Geometry g = spheres_and_triangles(s);
  const IrregularGrid grid(g);
  int checked = 0;
  for (const Ray& ray : random_rays(g, s, 500)) {
    const std::vector<WalkedCell> cells = grid.cells_on_ray(ray);
    const auto [rc, hc, fc, st] = counted_hit(grid, ray);
    ASSERT_EQ(cells.size(), st.nodes_visited);
    if (cells.empty()) continue;
    const Vec3 inv = safe_reciprocal(ray.direction);
    float previous_exit = -kInf;
    for (const WalkedCell& c : cells) {
      float enter = 0.f;
      const Box3 near_box{c.box.lo - Vec3(1e-3f), c.box.hi + Vec3(1e-3f)};
      EXPECT_TRUE(intersect_box(near_box, ray.origin, inv, ray.tmin, kInf, enter)) << describe(ray);
      // Expanded boxes may overlap, but each is left no earlier than the one before.
      float exit = kInf;
      for (int a = 0; a < 3; ++a) {
        if (ray.direction[a] == 0.f) continue;
        exit = std::min(exit, ((ray.direction[a] > 0.f ? c.box.hi[a] : c.box.lo[a]) - ray.origin[a]) * inv[a]);
      }
      EXPECT_GE(exit, previous_exit - 1e-4f * std::max(1.f, std::fabs(previous_exit))) << describe(ray);
      previous_exit = exit;
    }
    if (fc) {
      const Vec3 p = rc.at(hc.t);
      const Box3 last = cells.back().box;
      const Box3 near_last{last.lo - Vec3(1e-3f), last.hi + Vec3(1e-3f)};
      EXPECT_TRUE(near_last.contains(p)) << describe(ray);
      EXPECT_TRUE(cells.back().has_primitives);
    }
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(IrregularGrid, InfoDescribesTheGrid) {
  Sampler s(21);
  const Geometry g = spheres_and_triangles(s);
  const IrregularGrid grid(g);
  const AccelInfo info = grid.info();
  const IrregularGridData& d = grid.data();
  EXPECT_EQ(info.name, "irregular");
  EXPECT_EQ(info.primitive_count, g.size());
  EXPECT_EQ(info.node_count, d.cell_count());
  EXPECT_EQ(info.leaf_count, d.nonempty_cells);
  EXPECT_GT(info.leaf_count, 0u);
  EXPECT_LT(info.leaf_count, info.node_count);
  EXPECT_GE(info.memory_bytes,
            d.cells.size() * sizeof(IrregularCell) +
                (d.refs.size() + d.ids.size() + d.top.size() + d.map.size()) * sizeof(std::uint32_t));
  EXPECT_TRUE(d.boxes.empty()) << "the accelerator keeps only the expanded boxes";
  EXPECT_GE(info.build_seconds, 0.0);
}

}  // namespace
}  // namespace raylab
