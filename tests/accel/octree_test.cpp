// The octree must answer every query as brute force does (up to float ties) for every build
// configuration, including one cell (L = 0) and one primitive per cell (K = 1), on the stress
// scenes of test_scenes.h and on rays chosen to hit its own weak points: rays lying in cell
// boundaries, through cell corners, starting on them, axis-parallel rays with +0 and -0
// components, far origins, tmin > 0 and finite tmax. Its tree must respect K and L, and every
// leaf must reference every primitive that touches its cell.

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/octree.h"
#include "raylab/geometry/overlap.h"
#include "raylab/render/camera.h"
#include "stadium_scene.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

// Brute force's answers for a ray set, computed once and checked against several octrees.
struct Reference {
  std::vector<Ray> rays;
  std::vector<Hit> hits;      // closest hit (invalid: none)
  std::vector<Ray> shadow;    // the same rays with a random tmax
  std::vector<int> occluded;  // brute force's any-hit answer for `shadow`; -1: too close to call
};

Reference make_reference(const Geometry& g, std::vector<Ray> rays, Sampler& s) {
  const BruteForce brute(g);
  Reference ref;
  ref.rays = std::move(rays);
  for (const Ray& ray : ref.rays) {
    Ray r = ray;
    Hit h;
    brute.intersect(r, h);
    ref.hits.push_back(h);
    if (std::isfinite(ray.tmax)) {  // the ray's own limit: occluded exactly when something was hit
      ref.shadow.push_back(ray);
      ref.occluded.push_back(h.valid() ? 1 : 0);
      continue;
    }
    Ray sh = with_random_tmax(ray, h.valid(), h.t, s);
    const bool close = h.valid() && std::fabs(sh.tmax - h.t) <= kRelTol * h.t;
    if (!(sh.tmax > sh.tmin)) sh.tmax = kInf;
    ref.shadow.push_back(sh);
    ref.occluded.push_back(close ? -1 : (h.valid() && h.t < sh.tmax) ? 1 : 0);
  }
  return ref;
}

// Checks every query of `octree` against the reference; returns the total traversal work.
TraversalStats check(const Geometry& g, const Octree& octree, const Reference& ref, const std::string& label) {
  int failures = 0;
  auto fail = [&](const std::string& what, const Ray& r) {
    if (++failures <= 5) ADD_FAILURE() << label << ": " << what << " for " << describe(r);
  };
  TraversalStats total;
  for (std::size_t i = 0; i < ref.rays.size(); ++i) {
    const Ray& ray = ref.rays[i];
    const Hit& hb = ref.hits[i];
    Ray rv = ray;
    Hit hv;
    const bool fv = octree.intersect(rv, hv);
    if (const std::string wrong = closest_hit_disagreement(g, ray, hb.valid(), hb, fv, hv, rv); !wrong.empty()) {
      fail(wrong, ray);
    }

    const auto [rc, hc, fc, st] = counted_hit(octree, ray);
    if (fc != fv || !same_hit(hc, hv) || rc.tmax != rv.tmax) {
      fail("intersect_counted differs from intersect", ray);
    }
    if (st.hits != (fv ? 1u : 0u) || st.nodes_visited > octree.tree().nodes.size() ||
        (octree.config().mailbox && st.prim_tests > g.size())) {
      fail("implausible counts", ray);
    }
    total += st;

    if (ref.occluded[i] >= 0) {
      const bool expected = ref.occluded[i] == 1;
      TraversalStats so;
      if (octree.occluded(ref.shadow[i]) != expected)
        fail(expected ? "occluded missed" : "occluded phantom", ref.shadow[i]);
      if (octree.occluded_counted(ref.shadow[i], so) != expected || so.hits != (expected ? 1u : 0u)) {
        fail("occluded_counted", ref.shadow[i]);
      }
    }
  }
  EXPECT_EQ(failures, 0) << label << ": of " << ref.rays.size() << " rays";
  return total;
}

OctreeConfig config(int k, int l, bool mailbox = true) { return {k, l, mailbox}; }

std::string name_of(const OctreeConfig& c) {
  return "K=" + std::to_string(c.max_items) + " L=" + std::to_string(c.max_depth) + (c.mailbox ? "" : " no mailbox");
}

// The configurations every scene is checked with: the default, one cell, one primitive per cell,
// shallow and deep trees, and no mailboxes.
const std::vector<OctreeConfig> kConfigs = {OctreeConfig{}, config(8, 0),  config(1, 10),
                                            config(2, 24),  config(16, 3), config(4, 8, false)};

// ---------------------------------------------------------------------------------------------
// Against brute force on the shared stress scenes

class OctreeVsBrute : public ::testing::TestWithParam<int> {};

TEST_P(OctreeVsBrute, EveryConfiguration) {
  const NamedScene& scene = kScenes[static_cast<std::size_t>(GetParam())];
  Sampler s(scene.seed + 100);
  const Geometry g = scene.make(s);
  const Reference ref = make_reference(g, random_rays(g, s, 1500), s);
  int hits = 0;
  for (const Hit& h : ref.hits) hits += h.valid() ? 1 : 0;
  EXPECT_GT(hits, static_cast<int>(ref.rays.size()) / 10) << "too few hits for a meaningful comparison";
  for (const OctreeConfig& c : kConfigs) {
    const Octree octree(g, c);
    EXPECT_EQ(octree.info().primitive_count, g.size());
    EXPECT_EQ(octree.bounds().lo, g.bounds().lo);
    EXPECT_EQ(octree.bounds().hi, g.bounds().hi);
    const TraversalStats st = check(g, octree, ref, std::string(scene.name) + " " + name_of(c));
    if (c.max_depth >= 8) {  // a real tree must test far fewer primitives than brute force does
      EXPECT_LT(st.prim_tests * 4, std::uint64_t(g.size()) * ref.rays.size()) << name_of(c);
    }
  }
}

std::string scene_name(const ::testing::TestParamInfo<int>& info) {
  return kScenes[static_cast<std::size_t>(info.param)].name;
}
INSTANTIATE_TEST_SUITE_P(Scenes, OctreeVsBrute, ::testing::Range(0, static_cast<int>(kScenes.size())), scene_name);

// ---------------------------------------------------------------------------------------------
// The tree itself

// Calls f(node index, depth, lattice corner) for every node, parents first.
void for_each_node(const OctreeTree& tree, const std::function<void(std::uint32_t, int, const std::uint32_t*)>& f) {
  std::function<void(std::uint32_t, int, std::array<std::uint32_t, 3>)> walk = [&](std::uint32_t index, int depth,
                                                                                   std::array<std::uint32_t, 3> lo) {
    f(index, depth, lo.data());
    const OctreeNode& node = tree.nodes[index];
    if (node.is_leaf()) return;
    const std::uint32_t half = kOctreeLatticeSteps >> (depth + 1);
    for (std::uint32_t c = 0; c < 8; ++c) {
      walk(node.first + c, depth + 1,
           {lo[0] + (c & 1 ? half : 0), lo[1] + (c & 2 ? half : 0), lo[2] + (c & 4 ? half : 0)});
    }
  };
  if (!tree.nodes.empty()) walk(0, 0, {0, 0, 0});
}

Box3 enlarged(const Box3& b, float margin) { return {b.lo - Vec3(margin), b.hi + Vec3(margin)}; }

Box3 clipped(const Box3& b, const Box3& to) { return {max(b.lo, to.lo), min(b.hi, to.hi)}; }

bool boxes_overlap(const Box3& a, const Box3& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

// Calls f(leaf index) for every leaf whose cell overlaps `box`.
void for_each_leaf_in(const OctreeTree& tree, const Box3& box,
                      const std::function<void(std::uint32_t, const Box3&)>& f) {
  std::function<void(std::uint32_t, int, std::array<std::uint32_t, 3>)> walk = [&](std::uint32_t index, int depth,
                                                                                   std::array<std::uint32_t, 3> lo) {
    const Box3 cell = tree.cell_box(lo.data(), depth);
    if (!boxes_overlap(cell, box)) return;
    const OctreeNode& node = tree.nodes[index];
    if (node.is_leaf()) return f(index, cell);
    const std::uint32_t half = kOctreeLatticeSteps >> (depth + 1);
    for (std::uint32_t c = 0; c < 8; ++c) {
      walk(node.first + c, depth + 1,
           {lo[0] + (c & 1 ? half : 0), lo[1] + (c & 2 ? half : 0), lo[2] + (c & 4 ? half : 0)});
    }
  };
  if (!tree.nodes.empty()) walk(0, 0, {0, 0, 0});
}

// Structure, K and L, and completeness: every primitive overlapping a leaf's cell is in the leaf.
void check_tree(const Geometry& g, const OctreeTree& tree, const OctreeConfig& c, const std::string& label) {
  SCOPED_TRACE(label);
  std::vector<int> seen(tree.nodes.size(), 0);
  std::size_t leaves = 0, refs_in_leaves = 0;
  int deepest = 0, failures = 0;
  const Box3 root = tree.cell_box(std::array<std::uint32_t, 3>{0, 0, 0}.data(), 0);
  EXPECT_TRUE(root.contains(tree.bounds.lo - Vec3(tree.margin)) && root.contains(tree.bounds.hi + Vec3(tree.margin)))
      << "the root cell must hold the primitives with the margin to spare";
  // One edge length for every axis; the corners, root_lo + root_size, round separately per axis.
  const Vec3 e = root.extent();
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(e[a], tree.root_size, 4e-7f * tree.root_size) << "the root cell is a cube";
  EXPECT_GE(tree.root_size, max_component(tree.bounds.extent())) << "the root cell holds the bounds";
  for_each_node(tree, [&](std::uint32_t index, int depth, const std::uint32_t* lo) {
    ++seen[index];
    const OctreeNode& node = tree.nodes[index];
    if (!node.is_leaf()) {
      EXPECT_LT(depth, c.max_depth) << "an interior node at depth L";
      EXPECT_LE(std::size_t(node.first) + 8, tree.nodes.size());
      return;
    }
    ++leaves;
    refs_in_leaves += node.count;
    deepest = std::max(deepest, depth);
    ASSERT_LE(std::size_t(node.first) + node.count, tree.refs.size());
    const std::uint32_t* r = tree.refs.data() + node.first;
    EXPECT_TRUE(std::is_sorted(r, r + node.count) && std::adjacent_find(r, r + node.count) == r + node.count)
        << "references in ascending order, each once";
    if (depth < c.max_depth && node.count > static_cast<std::uint32_t>(c.max_items)) {
      // Only the split rule may leave such a leaf: recompute what its children would hold, from
      // the exact overlap test, and ask the rule.
      const std::uint32_t half = kOctreeLatticeSteps >> (depth + 1);
      std::array<std::size_t, 8> counts{};
      std::array<Box3, 8> contents;
      for (std::uint32_t o = 0; o < 8; ++o) {
        const std::uint32_t child_lo[3] = {lo[0] + (o & 1 ? half : 0), lo[1] + (o & 2 ? half : 0),
                                           lo[2] + (o & 4 ? half : 0)};
        const Box3 octant = enlarged(tree.cell_box(child_lo, depth + 1), tree.margin);
        for (std::uint32_t k = 0; k < node.count; ++k) {
          if (!overlaps_box(g, tree.ids[r[k]], octant)) continue;
          ++counts[o];
          contents[o].extend(clipped(g.bounds(tree.ids[r[k]]), octant));
        }
      }
      const Box3 cell = enlarged(tree.cell_box(lo, depth), tree.margin);
      Box3 content;
      for (std::uint32_t k = 0; k < node.count; ++k) content.extend(clipped(g.bounds(tree.ids[r[k]]), cell));
      EXPECT_FALSE(octree_split_pays(node.count, content, counts, contents))
          << "leaf " << index << " at depth " << depth << " holds " << node.count << " > K, and a split would pay";
    }
  });
  // Every primitive that really touches a leaf's cell is referenced there (the margin only adds).
  for (std::uint32_t i = 0; i < tree.ids.size(); ++i) {
    for_each_leaf_in(tree, g.bounds(tree.ids[i]), [&](std::uint32_t index, const Box3& cell) {
      const OctreeNode& node = tree.nodes[index];
      const std::uint32_t* r = tree.refs.data() + node.first;
      if (overlaps_box(g, tree.ids[i], cell) && !std::binary_search(r, r + node.count, i) && ++failures <= 5) {
        ADD_FAILURE() << "primitive " << tree.ids[i] << " touches leaf " << index << " but is not in it";
      }
    });
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; })) << "every node reached once";
  EXPECT_EQ(leaves, tree.leaf_count);
  EXPECT_EQ(refs_in_leaves, tree.refs.size());
  EXPECT_EQ(deepest, tree.max_depth);
  EXPECT_LE(tree.max_depth, c.max_depth);
  EXPECT_EQ(failures, 0);
}

TEST(OctreeTree, RespectsKAndLAndHoldsEveryTouchingPrimitive) {
  for (int scene : {0, 4, 5}) {
    Sampler s(kScenes[scene].seed);
    const Geometry g = kScenes[scene].make(s);
    for (const OctreeConfig& c : {OctreeConfig{}, config(1, 6), config(3, 12), config(8, 0)}) {
      check_tree(g, build_octree(g, c), c, std::string(kScenes[scene].name) + " " + name_of(c));
    }
  }
}

TEST(OctreeTree, OneCellAndOnePrimitivePerCell) {
  Sampler s(11);
  const Geometry g = spheres_and_triangles(s);
  const OctreeTree one = build_octree(g, config(1, 0));
  ASSERT_EQ(one.nodes.size(), 1u);
  EXPECT_EQ(one.nodes[0].count, g.size());
  EXPECT_EQ(one.max_depth, 0);
  // K = 1 splits deeper than the default and keeps most leaves at one primitive or none.
  const OctreeTree fine = build_octree(g, config(1, 12));
  const OctreeTree coarse = build_octree(g, config(16, 12));
  EXPECT_GT(fine.leaf_count, coarse.leaf_count);
  std::size_t small = 0;
  for (const OctreeNode& n : fine.nodes) small += n.is_leaf() && n.count <= 1 ? 1 : 0;
  EXPECT_GT(small * 2, fine.leaf_count);
}

TEST(OctreeTree, DepthIsClampedAndKMayBeZero) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 0.f}, 1.f}, 0);
  g.add(Sphere{{3.f, 0.f, 0.f}, 1.f}, 0);
  EXPECT_EQ(Octree(g, config(1, 99)).config().max_depth, kOctreeDepthLimit);
  EXPECT_EQ(Octree(g, config(1, -4)).config().max_depth, 0);
  const Octree zero(g, config(0, 5));
  EXPECT_EQ(zero.config().max_items, 0);
  check_tree(g, zero.tree(), zero.config(), "K=0");
}

// All primitives in one cell: a thousand tiny triangles around one point. The tree must not
// explode (the gain rule and L bound it) and must still find them.
TEST(OctreeTree, AllPrimitivesInOneCell) {
  Sampler s(12);
  Geometry g;
  const Vec3 point{0.3f, 0.7f, 0.1f};
  for (int i = 0; i < 1000; ++i) g.add(random_triangle(s, point + s.unit() * 1e-6f, 1e-6f), 0);
  g.add(Sphere{{10.f, 10.f, 10.f}, 1.f}, 1);  // gives the root cell its size
  for (const OctreeConfig& c : {OctreeConfig{}, config(1, 24)}) {
    const Octree octree(g, c);
    check_tree(g, octree.tree(), c, name_of(c));
    // A chain of cells down to the point: at most eight children per level.
    EXPECT_LE(octree.tree().nodes.size(), std::size_t{8} * 8 * kOctreeDepthLimit + 1) << name_of(c);
    std::vector<Ray> rays = random_rays(g, s, 500);
    for (int i = 0; i < 500; ++i) {  // aimed at the point from everywhere
      const Vec3 o = s.in_box(Vec3(-5.f), Vec3(15.f));
      rays.push_back({o, 0.f, point + s.unit() * 1e-6f - o});
    }
    check(g, octree, make_reference(g, rays, s), name_of(c));
  }
}

// More than K primitives sharing one line: triangles with a common edge on the y axis (a fan of
// faces around it) and degenerate triangles lying on it, the scene of the accel fuzz target that
// took the octree 6 s and 80 MB. Splitting along the line keeps every reference in the two
// children on it at every level, which separates nothing; the tree must stay small, and still
// find every hit.
TEST(OctreeTree, PrimitivesSharingOneLine) {
  Geometry g;
  const Vec3 a{0.f, 0.f, 0.f}, b{0.f, 16384.f, 0.f};
  for (int i = 0; i < 8; ++i) {  // a fan of faces around the edge a-b
    const float angle = 0.7f * float(i);
    g.add(Triangle{a, b, Vec3{16384.f * std::cos(angle), 0.f, 16384.f * std::sin(angle)}}, 0);
  }
  for (int i = 0; i < 6; ++i) g.add(Triangle{a, b, Vec3{0.f, 64.f * float(i + 1), 0.f}}, 1);  // on the line
  for (const OctreeConfig& c : {OctreeConfig{}, config(4, 24)}) {
    const Octree octree(g, c);
    check_tree(g, octree.tree(), c, name_of(c));
    // A chain of cells down each end of the line, not 2^L cells along it.
    EXPECT_LE(octree.tree().nodes.size(), std::size_t{8} * 8 * kOctreeDepthLimit + 1) << name_of(c);
    Sampler s(13);
    std::vector<Ray> rays = random_rays(g, s, 500);
    for (int i = 0; i < 500; ++i) {  // aimed at points of the line from everywhere
      const Vec3 o = s.in_box(Vec3(-2e4f), Vec3(2e4f));
      rays.push_back({o, 0.f, Vec3{0.f, s.uni(0.f, 16384.f), 0.f} - o});
    }
    check(g, octree, make_reference(g, rays, s), name_of(c));
  }
}

TEST(OctreeSplitRule, NeverSplitsWhenTwoChildrenKeepEveryReference) {
  const Box3 content{{0.f, 0.f, 0.f}, {4.f, 4.f, 4.f}};
  std::array<std::size_t, 8> counts{};
  std::array<Box3, 8> contents;
  // Twenty references along an edge of the cell: both children on it keep all twenty in boxes of
  // a quarter of the area each, which the area terms alone would take (1 + 20 / 2 < 20).
  for (int c : {0, 1}) {
    counts[c] = 20;
    contents[c] = {{c * 2.f, 0.f, 0.f}, {c * 2.f + 2.f, 2.f, 2.f}};
  }
  EXPECT_FALSE(octree_split_pays(20, content, counts, contents));
  // The same areas with one reference fewer on one side separate something: the area rule decides.
  counts[1] = 19;
  EXPECT_TRUE(octree_split_pays(20, content, counts, contents));
  // One child keeping everything (a small object in a large cell) is still followed from 16 on.
  counts = {};
  counts[3] = 20;
  contents[3] = {{0.f, 0.f, 0.f}, {0.5f, 0.5f, 0.5f}};
  EXPECT_TRUE(octree_split_pays(20, content, counts, contents));
}

// Every interior node's child boxes: an empty child has the empty box; any other child's box lies
// in its enlarged cell and holds every primitive of its subtree's leaves, clipped to that cell, so
// a ray that can hit one of them in the child's cell enters the box.
TEST(OctreeTree, ChildBoxesHoldWhatTheChildrenHold) {
  for (int scene : {0, 4, 5}) {
    Sampler s(kScenes[scene].seed);
    const Geometry g = kScenes[scene].make(s);
    for (const OctreeConfig& c : {OctreeConfig{}, config(1, 8)}) {
      SCOPED_TRACE(std::string(kScenes[scene].name) + " " + name_of(c));
      const OctreeTree tree = build_octree(g, c);
      std::size_t interior = 0;
      int failures = 0;
      for_each_node(tree, [&](std::uint32_t index, int depth, const std::uint32_t* lo) {
        const OctreeNode& node = tree.nodes[index];
        if (node.is_leaf()) return;
        ++interior;
        const OctreeChildBoxes& boxes = tree.child_boxes(node);
        const std::uint32_t half = kOctreeLatticeSteps >> (depth + 1);
        for (std::uint32_t o = 0; o < 8; ++o) {
          const Box3 box{{boxes.lo[0][o], boxes.lo[1][o], boxes.lo[2][o]},
                         {boxes.hi[0][o], boxes.hi[1][o], boxes.hi[2][o]}};
          const OctreeNode& child = tree.nodes[node.first + o];
          if (child.is_leaf() && child.count == 0) {
            EXPECT_TRUE(box.empty()) << "an empty child has the empty box";
            continue;
          }
          const std::uint32_t child_lo[3] = {lo[0] + (o & 1 ? half : 0), lo[1] + (o & 2 ? half : 0),
                                             lo[2] + (o & 4 ? half : 0)};
          const Box3 cell = enlarged(tree.cell_box(child_lo, depth + 1), tree.margin);
          EXPECT_TRUE(cell.contains(box.lo) && cell.contains(box.hi)) << "a content box lies in its cell";
          for_each_leaf_in(tree, cell, [&](std::uint32_t leaf, const Box3& leaf_cell) {
            const Box3 own = tree.cell_box(child_lo, depth + 1);
            if (!own.contains(leaf_cell.lo) || !own.contains(leaf_cell.hi)) return;  // a neighbour's leaf
            const OctreeNode& l = tree.nodes[leaf];
            for (std::uint32_t k = 0; k < l.count; ++k) {
              const Box3 part = clipped(g.bounds(tree.ids[tree.refs[l.first + k]]), cell);
              if (part.empty() || (box.contains(part.lo) && box.contains(part.hi))) continue;
              if (++failures <= 5)
                ADD_FAILURE() << "a primitive of child " << o << " of node " << index << " sticks out";
            }
          });
        }
      });
      EXPECT_EQ(interior, tree.boxes.size()) << "one entry of child boxes per interior node";
      EXPECT_EQ(failures, 0);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Adversarial rays

// Centres of `count` interior nodes of the tree (the corners their eight children share).
std::vector<Vec3> interior_centres(const OctreeTree& tree) {
  std::vector<Vec3> centres;
  for_each_node(tree, [&](std::uint32_t index, int depth, const std::uint32_t* lo) {
    if (tree.nodes[index].is_leaf()) return;
    const std::uint32_t half = kOctreeLatticeSteps >> (depth + 1);
    centres.push_back({tree.plane(0, lo[0] + half), tree.plane(1, lo[1] + half), tree.plane(2, lo[2] + half)});
  });
  return centres;
}

// Rays lying in the centre planes of cells, along the lines where two of them meet (cell edges),
// starting exactly at cell corners, and aimed through them.
std::vector<Ray> boundary_rays(const Geometry& g, const OctreeTree& tree, Sampler& s, int count) {
  const std::vector<Vec3> centres = interior_centres(tree);
  return rays_at_lattice_points(g.bounds(), s, count, [&] { return centres[s.rng.next_u32() % centres.size()]; });
}

TEST(OctreeAdversarial, RaysAlongAndThroughCellBoundaries) {
  for (int scene : {0, 4, 5}) {
    Sampler s(kScenes[scene].seed + 200);
    const Geometry g = kScenes[scene].make(s);
    for (const OctreeConfig& c : {OctreeConfig{}, config(1, 10)}) {
      const Octree octree(g, c);
      check(g, octree, make_reference(g, boundary_rays(g, octree.tree(), s, 1200), s),
            std::string(kScenes[scene].name) + " " + name_of(c));
    }
  }
}

// The cube mesh's faces are axis aligned, so its triangles lie in planes that are also the
// planes of cells: a face at a centre plane sits on the boundary of two cells.
TEST(OctreeAdversarial, AxisAlignedFacesOnCellPlanes) {
  Geometry g;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(g, {2.f, 2.f, 2.f}, 2.f, 8, identity, 0);
  add_cube_mesh(g, {2.f, 2.f, 2.f}, 1.f, 8, identity, 1);  // faces at x = 1, 3: quarter planes
  Sampler s(13);
  const Octree octree(g, config(2, 10));
  std::vector<Ray> rays = boundary_rays(g, octree.tree(), s, 1500);
  const std::vector<Ray> axis_rays = axis_rays_in_cube_faces(s, 1500);
  rays.insert(rays.end(), axis_rays.begin(), axis_rays.end());
  check(g, octree, make_reference(g, rays, s), "cubes");
}

// What the build's margin is for: small triangles with a vertex an ulp or two inside one of the
// eight cells meeting at a cell corner, and rays aimed at that vertex. Rounding in the traversal
// may route such a ray through the neighbouring cells only; without the margin, they would not
// hold the triangle and the hit would be lost.
TEST(OctreeAdversarial, PrimitivesJustInsideACellCorner) {
  Sampler s(22);
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 0.f}, 0.01f}, 0);  // fixes the root cell: bounds [0, 8]^3
  g.add(Sphere{{8.f, 8.f, 8.f}, 0.01f}, 0);
  // The tree is only known after the build, but its lattice depends on the bounds alone: take
  // the corners from a first tree over the two spheres and the corners' triangles.
  OctreeTree lattice = build_octree(g, config(1, 0));
  std::vector<Vec3> corners;
  for (std::uint32_t i = 1; i < 8; ++i)
    for (std::uint32_t j = 1; j < 8; ++j)
      for (std::uint32_t k = 1; k < 8; ++k) {
        const std::uint32_t step = kOctreeLatticeSteps / 8;
        corners.push_back({lattice.plane(0, i * step), lattice.plane(1, j * step), lattice.plane(2, k * step)});
      }
  std::vector<Vec3> vertices;
  for (const Vec3& c : corners) {
    for (int copy = 0; copy < 2; ++copy) {  // two per corner, so the cells around it split (K = 1)
      const int octant = static_cast<int>(s.rng.next_u32() % 8);
      Vec3 dir, v = c;
      for (int a = 0; a < 3; ++a) {
        const float sign = (octant >> a & 1) ? 1.f : -1.f;
        dir[a] = sign;
        v[a] = std::nextafter(std::nextafter(c[a], sign * kInf), sign * kInf);  // two ulps inside
      }
      g.add(Triangle{v, v + dir * Vec3{0.3f, 0.05f, 0.1f}, v + dir * Vec3{0.05f, 0.3f, 0.2f}}, 1);
      vertices.push_back(v);
    }
  }
  std::vector<Ray> rays;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 target = vertices[s.rng.next_u32() % vertices.size()];
    // From nearby, and from up to ten scene sizes away, where rounding is larger.
    const Vec3 o = target + s.unit() * (i % 2 ? s.uni(0.5f, 12.f) : s.uni(12.f, 80.f));
    rays.push_back({o, 0.f, target - o});
  }
  const Reference ref = make_reference(g, rays, s);
  for (const OctreeConfig& c : {config(1, 12), config(2, 8), OctreeConfig{}}) check(g, Octree(g, c), ref, name_of(c));
}

// Direction components that are tiny but not zero (down to denormals): crossings of their planes
// are huge or overflow to infinity, and must neither become NaN nor lose the ray.
TEST(OctreeAdversarial, NearlyAxisParallelRays) {
  Sampler s(23);
  const Geometry g = every_shape_kind(s);
  const Octree octree(g, config(2, 12));
  const float tiny[] = {1e-8f, 1e-20f, 1e-30f, 1e-38f, 1e-42f};
  std::vector<Ray> rays;
  for (int i = 0; i < 2000; ++i) {
    Ray r;
    r.origin = s.in_box(Vec3(-12.f), Vec3(12.f));
    const int axis = i % 3;
    for (int a = 0; a < 3; ++a) {
      const float sign = s.rng.next_float() < 0.5f ? 1.f : -1.f;
      r.direction[a] = a == axis ? sign : sign * tiny[s.rng.next_u32() % 5];
    }
    rays.push_back(r);
  }
  check(g, octree, make_reference(g, rays, s), "nearly axis-parallel");
}

// Far origins: every plane crossing is a large parameter, rounded at its own scale.
TEST(OctreeAdversarial, RaysFromFarAway) {
  Sampler s(14);
  const Geometry g = spheres_and_triangles(s);
  const Octree octree(g);
  std::vector<Ray> rays;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 o = s.unit() * s.uni(100.f, 1000.f);  // the scene is 20 across
    rays.push_back({o, 0.f, point_on(g, s.rng.next_u32() % g.size(), s) - o});
  }
  check(g, octree, make_reference(g, rays, s), "far");
}

// Primitives behind the origin must not be reported; tmin > 0 skips those before it; a finite
// tmax hides those beyond it. Layers of quads along z, crossed by rays from inside the stack.
TEST(OctreeAdversarial, BehindTheOriginTminAndTmax) {
  Sampler s(15);
  Geometry g;
  for (int layer = -5; layer <= 5; ++layer) {
    const float z = static_cast<float>(layer);
    g.add(Quad{{-4.f, -4.f, z}, {8.f, 0.f, 0.f}, {0.f, 8.f, 0.f}}, 0);
    for (int i = 0; i < 60; ++i) g.add(Sphere{s.in_box({-4.f, -4.f, z + 0.2f}, {4.f, 4.f, z + 0.8f}), 0.05f}, 1);
  }
  const Octree octree(g, config(4, 10));
  std::vector<Ray> rays;
  for (int i = 0; i < 3000; ++i) {
    Ray r;
    r.origin = s.in_box({-3.f, -3.f, -5.f}, {3.f, 3.f, 5.f});
    r.direction = Vec3{s.uni(-0.2f, 0.2f), s.uni(-0.2f, 0.2f), s.rng.next_float() < 0.5f ? 1.f : -1.f};
    if (i % 3 == 0) r.tmin = s.uni(0.f, 4.f);
    if (i % 4 == 0) r.tmax = r.tmin + s.uni(0.f, 3.f);
    rays.push_back(r);
  }
  const Reference ref = make_reference(g, rays, s);
  check(g, octree, ref, "layers");
  // Exact answers for a vertical ray from z = 0.5 upward: the quad at z = 1 at t = 0.5, or with
  // tmin = 1, the quad at z = 2 (or a sphere before it); nothing at all below tmax = 0.4.
  Ray up{{0.01f, 0.02f, 0.5f}, 0.f, {0.f, 0.f, 1.f}};
  Hit h;
  ASSERT_TRUE(octree.intersect(up, h));
  EXPECT_LE(h.t, 0.5f);
  Ray later{{0.01f, 0.02f, 0.5f}, 1.0f, {0.f, 0.f, 1.f}};
  Hit h2;
  ASSERT_TRUE(octree.intersect(later, h2));
  EXPECT_GE(h2.t, 1.0f);
  EXPECT_LE(h2.t, 1.5f);
  const Ray short_ray{{0.01f, 0.02f, 0.5f}, 0.f, {0.f, 0.f, 1.f}, 0.4f};
  EXPECT_EQ(octree.occluded(short_ray), BruteForce(g).occluded(short_ray));
}

// A few primitives spanning almost every cell among many small ones: found in any cell, and
// with mailboxes tested at most once per ray.
TEST(OctreeAdversarial, ObjectsSpanningManyCells) {
  Sampler s(16);
  Geometry g;
  for (int i = 0; i < 1500; ++i) g.add(random_triangle(s, s.in_box(Vec3(-10.f), Vec3(10.f)), 0.2f), 0);
  g.add(Triangle{{-10.f, -10.f, -10.f}, {10.f, -10.f, 10.f}, {-10.f, 10.f, 10.f}}, 1);  // across the box
  g.add(Sphere{{0.f, 0.f, 0.f}, 7.f}, 2);
  g.add(Quad{{-10.f, 0.3f, -10.f}, {20.f, 0.f, 0.f}, {0.f, 0.f, 20.f}}, 3);
  g.add(Cylinder{{-9.f, -9.f, -9.f}, 0.5f, {9.f, 9.f, 9.f}, 0.5f}, 4);
  const Reference ref = make_reference(g, random_rays(g, s, 2500), s);
  const Octree with(g, config(4, 10)), without(g, config(4, 10, false));
  const TraversalStats a = check(g, with, ref, "mailbox");
  const TraversalStats b = check(g, without, ref, "no mailbox");
  EXPECT_LT(a.prim_tests, b.prim_tests) << "mailboxes must save repeated tests of the big primitives";
  EXPECT_EQ(a.nodes_visited, b.nodes_visited) << "mailboxes change tests, not the cells visited";
}

// The teapot in a stadium: a dense mesh 1/1000 of a huge sparse scene.
TEST(OctreeAdversarial, TeapotInAStadium) {
  const Geometry g = teapot_in_stadium();
  Sampler s(17);
  const Octree octree(g);
  std::vector<Ray> rays = random_rays(g, s, 600);
  const Camera camera(teapot_in_stadium_camera(), 32, 24);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) rays.push_back(camera.generate(float(x) + 0.5f, float(y) + 0.5f));
  for (int i = 0; i < 300; ++i) {  // at the teapot from nearby
    const Vec3 o = s.in_box({-3.f, -3.f, 0.f}, {3.f, 3.f, 3.f});
    rays.push_back({o, 0.f, point_on(g, s.rng.next_u32() % 2256, s) - o});
  }
  const Reference ref = make_reference(g, rays, s);
  const TraversalStats st = check(g, octree, ref, "stadium");
  // Adaptivity: a tree cut at depth 8 has cells 8 m wide, the whole teapot in one of them, and
  // tests most of its 2256 triangles for every ray that passes; the default tree reaches down to
  // the teapot's scale and must test at least 20 times fewer.
  const OctreeConfig shallow = config(OctreeConfig{}.max_items, 8);
  const TraversalStats coarse = check(g, Octree(g, shallow), ref, "stadium " + name_of(shallow));
  EXPECT_LT(st.prim_tests * 20, coarse.prim_tests);
}

// ---------------------------------------------------------------------------------------------
// Contract details

// The queries on empty geometry are checked for every structure in accel_vs_brute_test.cpp;
// here, what is the octree's own: no nodes, no work.
TEST(Octree, EmptyGeometry) {
  const Geometry g;
  const Octree octree(g);
  Ray ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  Hit hit;
  TraversalStats st;
  EXPECT_FALSE(octree.intersect_counted(ray, hit, st));
  EXPECT_FALSE(octree.occluded_counted(ray, st));
  EXPECT_EQ(octree.info().node_count, 0u);
  EXPECT_EQ(st.prim_tests, 0u);
}

TEST(Octree, SinglePrimitive) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 3);
  const Octree octree(g);
  EXPECT_EQ(octree.info().leaf_count, 1u);
  EXPECT_EQ(octree.info().node_count, 1u);  // the queries: AccelVsBrute.OnePrimitive
}

// Coincident triangles hit at exactly the same t, each in many cells: the lowest id wins however
// the cells are visited, and an incoming hit (another structure's answer) is honoured.
TEST(Octree, TiesAndTheIncomingHit) {
  Sampler s(18);
  Geometry g;
  for (int i = 0; i < 400; ++i) g.add(random_triangle(s, s.in_box(Vec3(-5.f), Vec3(5.f)), 0.3f), 0);
  const Triangle big{{-4.f, -4.f, 0.5f}, {4.f, -4.f, 0.5f}, {0.f, 4.f, 0.5f}};
  for (int copy = 0; copy < 4; ++copy) g.add(big, 1);  // ids 400 .. 403, identical
  const Octree octree(g, config(2, 10));
  const BruteForce brute(g);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 o = s.in_box({-3.f, -3.f, 3.f}, {3.f, 1.f, 4.f});
    const Vec3 target = s.in_box({-1.f, -2.f, 0.5f}, {1.f, 0.f, 0.5f});
    Ray ro{o, 0.f, target - o}, rb = ro;
    Hit ho, hb;
    ASSERT_TRUE(octree.intersect(ro, ho));
    ASSERT_TRUE(brute.intersect(rb, hb));
    EXPECT_TRUE(same_hit(ho, hb));
    if (hb.prim_id < 400) continue;  // a small triangle in front
    EXPECT_EQ(ho.prim_id, 400u);
    // Starting from brute force's hit of copy 402 at the same t: only a lower id may replace it.
    Ray again{o, 0.f, target - o, ho.t};
    Hit incoming{ho.t, 402, 0.f, 0.f};
    EXPECT_TRUE(octree.intersect(again, incoming));
    EXPECT_EQ(incoming.prim_id, 400u);
    // From a hit closer than the triangle, nothing changes.
    Ray closer{o, 0.f, target - o, ho.t * 0.5f};
    Hit kept{ho.t * 0.5f, 7, 0.25f, 0.25f};
    EXPECT_FALSE(octree.intersect(closer, kept));
    EXPECT_EQ(kept.prim_id, 7u);
    EXPECT_EQ(closer.tmax, ho.t * 0.5f);
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

// Mailboxes are per thread: rays traced in parallel get the answers of rays traced one by one.
TEST(Octree, ParallelQueriesAgreeWithSequentialOnes) {
  Sampler s(20);
  const Geometry g = spheres_and_triangles(s);
  const Octree octree(g);
  const std::vector<Ray> rays = random_rays(g, s, 4000);
  std::vector<Hit> sequential(rays.size()), parallel(rays.size());
  std::vector<TraversalStats> seq_stats(rays.size()), par_stats(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Ray r = rays[i];
    octree.intersect_counted(r, sequential[i], seq_stats[i]);
  }
  tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) {
    Ray r = rays[i];
    octree.intersect_counted(r, parallel[i], par_stats[i]);
  });
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_TRUE(same_hit(sequential[i], parallel[i])) << i;
    EXPECT_EQ(seq_stats[i].prim_tests, par_stats[i].prim_tests) << i;
  }
}

// cells_on_ray is the query's own walk: without mailboxes a closest-hit query tests every
// reference of every leaf it enters, so the leaves listed as tested, looked up in the tree, hold
// exactly the primitive tests the counted query reports; each listed cell is a cell of the tree,
// and they come in order along the ray.
TEST(Octree, CellsOnRayAreTheLeavesTheQueryTests) {
  Sampler s(22);
  const Geometry g = spheres_and_triangles(s);
  const Octree octree(g, config(4, 10, false));
  const OctreeTree& tree = octree.tree();
  // Every cell of the tree by its box: the leaves with their reference counts, interior nodes -1.
  std::map<std::array<float, 6>, long> cells;
  auto key = [](const Box3& b) { return std::array<float, 6>{b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z}; };
  for_each_node(tree, [&](std::uint32_t index, int depth, const std::uint32_t* lo) {
    const OctreeNode& node = tree.nodes[index];
    cells[key(tree.cell_box(lo, depth))] = node.is_leaf() ? long(node.count) : -1;
  });
  std::vector<Ray> rays = random_rays(g, s, 1500);
  for (const Vec3& c : interior_centres(tree)) rays.push_back({c, 0.f, s.unit()});  // from cell corners
  std::size_t tested_somewhere = 0;
  int failures = 0;
  for (const Ray& ray : rays) {
    const auto [rc, hc, fc, st] = counted_hit(octree, ray);
    const std::vector<WalkedCell> walked = octree.cells_on_ray(ray);
    std::uint64_t refs = 0, leaves = 0;
    float last_entry = -kInf;
    bool ordered = true, known = true;
    for (const WalkedCell& cell : walked) {
      const auto it = cells.find(key(cell.box));
      if (it == cells.end()) {
        known = false;
        continue;
      }
      if (cell.has_primitives) {
        known = known && it->second > 0;
        refs += std::uint64_t(std::max(it->second, 0L));
        ++leaves;
      }
      // Where the ray enters the cell (the cells share faces, so with rounding to spare).
      float t0 = ray.tmin, t1 = ray.tmax;
      for (int a = 0; a < 3; ++a) {
        const float inv = 1.f / ray.direction[a];
        float n = (cell.box.lo[a] - ray.origin[a]) * inv, f = (cell.box.hi[a] - ray.origin[a]) * inv;
        if (n > f) std::swap(n, f);
        if (n == n) t0 = std::max(t0, n);
        if (f == f) t1 = std::min(t1, f);
      }
      ordered = ordered && t0 >= last_entry - 1e-4f * std::max(1.f, std::fabs(last_entry));
      last_entry = std::max(last_entry, t0);
    }
    tested_somewhere += leaves > 0 ? 1 : 0;
    if ((!known || !ordered || refs != st.prim_tests || leaves > st.nodes_visited) && ++failures <= 5) {
      ADD_FAILURE() << describe(ray) << ": " << walked.size() << " cells, " << leaves << " tested holding " << refs
                    << " references; the query tested " << st.prim_tests << (known ? "" : "; a cell not in the tree")
                    << (ordered ? "" : "; out of order");
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(tested_somewhere, rays.size() / 4) << "most rays should test some leaf";
  // A ray that misses the scene walks nothing.
  const Box3 b = g.bounds();
  EXPECT_TRUE(octree.cells_on_ray({b.hi + b.extent(), 0.f, {1.f, 1.f, 1.f}}).empty());
}

TEST(Octree, InfoDescribesTheTree) {
  Sampler s(21);
  const Geometry g = spheres_and_triangles(s);
  const Octree octree(g);
  const AccelInfo info = octree.info();
  EXPECT_EQ(info.name, "octree");
  EXPECT_EQ(info.primitive_count, g.size());
  EXPECT_EQ(info.node_count, octree.tree().nodes.size());
  EXPECT_EQ(octree.tree().boxes.size() * 8 + 1, octree.tree().nodes.size()) << "child boxes for every interior node";
  EXPECT_EQ(info.leaf_count, octree.tree().leaf_count);
  EXPECT_EQ(info.max_depth, octree.tree().max_depth);
  EXPECT_GT(info.max_depth, 0);
  // Nodes, references and ids at least; a thread's mailboxes (4 bytes a primitive) too.
  EXPECT_GE(info.memory_bytes, info.node_count * sizeof(OctreeNode) +
                                   octree.tree().boxes.size() * sizeof(OctreeChildBoxes) +
                                   (octree.tree().refs.size() + 2 * std::size_t{g.size()}) * sizeof(std::uint32_t));
  EXPECT_GE(info.build_seconds, 0.0);
}

}  // namespace
}  // namespace raylab
