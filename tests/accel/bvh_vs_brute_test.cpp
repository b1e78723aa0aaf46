// The BVH must answer every query exactly as brute force does (up to float ties), on scenes built
// to stress it: overlap, slivers, sizes over eight orders of magnitude, dense soups, every shape
// kind, and closed meshes with axis-aligned (zero-thickness box) faces.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "raylab/accel/brute_force.h"
#include "raylab/accel/bvh.h"
#include "raylab/accel/factory.h"
#include "raylab/core/error.h"
#include "raylab/core/rng.h"

namespace raylab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kRelTol = 1e-5f;

bool near(float a, float b) { return std::fabs(a - b) <= kRelTol * std::max(std::fabs(a), std::fabs(b)); }

struct Sampler {
  Pcg32 rng;
  explicit Sampler(std::uint64_t seed) : rng(seed, 17) {}
  float uni(float lo, float hi) { return lo + (hi - lo) * rng.next_float(); }
  Vec3 in_box(Vec3 lo, Vec3 hi) { return lo + (hi - lo) * Vec3{rng.next_float(), rng.next_float(), rng.next_float()}; }
  Vec3 unit() {
    for (;;) {
      const Vec3 p = in_box(Vec3(-1.f), Vec3(1.f));
      const float l2 = dot(p, p);
      if (l2 > 1e-4f && l2 <= 1.f) return p / std::sqrt(l2);
    }
  }
  float log_uniform(float lo, float hi) { return lo * std::pow(hi / lo, rng.next_float()); }
};

Triangle random_triangle(Sampler& s, Vec3 center, float size) {
  return {center + s.unit() * size, center + s.unit() * size, center + s.unit() * size};
}

// ---------------------------------------------------------------------------------------------
// Scenes (all from fixed seeds)

Geometry spheres_and_triangles(Sampler& s) {
  Geometry g;
  for (int i = 0; i < 700; ++i) g.add(random_triangle(s, s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.3f, 3.f)), 0);
  for (int i = 0; i < 400; ++i) g.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.2f, 2.f)}, 1);
  return g;
}

Geometry slivers(Sampler& s) {
  Geometry g;
  for (int i = 0; i < 1200; ++i) {
    const Vec3 p0 = s.in_box(Vec3(-10.f), Vec3(10.f));
    const Vec3 along = s.unit() * s.uni(5.f, 20.f);
    Vec3 side = cross(along, s.unit());
    side = side / length(side) * s.uni(1e-4f, 1e-2f);
    g.add(Triangle{p0, p0 + along, p0 + along * s.uni(0.f, 1.f) + side}, 0);
  }
  return g;
}

Geometry sizes_over_eight_decades(Sampler& s) {
  Geometry g;
  for (int i = 0; i < 1200; ++i) {
    const Vec3 c = s.in_box(Vec3(-1e4f), Vec3(1e4f));
    const float size = s.log_uniform(1e-4f, 1e4f);
    if (i % 3 == 0) {
      g.add(Sphere{c, size}, 0);
    } else if (i % 3 == 1) {
      g.add(random_triangle(s, c, size), 0);
    } else {
      g.add(Quad{c, s.unit() * size, s.unit() * size}, 0);
    }
  }
  return g;
}

Geometry dense_soup(Sampler& s) {
  Geometry g;
  for (int i = 0; i < 1500; ++i) g.add(random_triangle(s, s.in_box(Vec3(0.f), Vec3(1.f)), s.uni(0.05f, 0.2f)), 0);
  return g;
}

Geometry every_shape_kind(Sampler& s) {
  Geometry g;
  auto p = [&] { return s.in_box(Vec3(-10.f), Vec3(10.f)); };
  for (int i = 0; i < 300; ++i) g.add(random_triangle(s, p(), s.uni(0.3f, 2.f)), 0);
  for (int i = 0; i < 200; ++i) g.add(Sphere{p(), s.uni(0.2f, 1.5f)}, 1);
  for (int i = 0; i < 250; ++i) {
    const Vec3 base = p();
    const float r = s.uni(0.1f, 1.f);
    g.add(Cylinder{base, r, base + s.unit() * s.uni(0.5f, 4.f), i % 2 ? r : s.uni(0.f, 1.f)}, 2);
  }
  for (int i = 0; i < 150; ++i) g.add(Disk{p(), s.unit(), s.uni(0.2f, 2.f)}, 3);
  for (int i = 0; i < 150; ++i) g.add(Quad{p(), s.unit() * s.uni(0.3f, 3.f), s.unit() * s.uni(0.3f, 3.f)}, 4);
  // A few axis-aligned ones, whose bounding boxes are flat.
  g.add(Quad{{-10.f, -10.5f, -10.f}, {20.f, 0.f, 0.f}, {0.f, 0.f, 20.f}}, 4);
  g.add(Disk{{0.f, 0.f, 10.5f}, {0.f, 0.f, 1.f}, 5.f}, 3);
  return g;
}

// A cube surface [c - h, c + h] split into n x n cells per face, two triangles per cell, rotated by
// `rot` (columns of an orthonormal matrix). Each lattice point is transformed once and reused, so
// faces meeting at an edge share vertices bit for bit (recomputing them could round differently
// where the compiler contracts to FMA in one copy of the code and not another).
void add_cube_mesh(Geometry& g, Vec3 c, float h, int n, const Vec3 rot[3], std::uint32_t object) {
  std::map<std::array<int, 3>, Vec3> lattice;
  auto vertex = [&](std::array<int, 3> idx) {
    auto [it, fresh] = lattice.try_emplace(idx);
    if (fresh) {
      Vec3 local;
      for (int k = 0; k < 3; ++k) local[k] = -h + 2.f * h * float(idx[k]) / float(n);
      it->second = c + rot[0] * local.x + rot[1] * local.y + rot[2] * local.z;
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : {0, n})
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          auto vert = [&](int a, int b) {
            std::array<int, 3> idx;
            idx[axis] = side;
            idx[(axis + 1) % 3] = a;
            idx[(axis + 2) % 3] = b;
            return vertex(idx);
          };
          g.add(Triangle{vert(i, j), vert(i + 1, j), vert(i + 1, j + 1)}, object);
          g.add(Triangle{vert(i, j), vert(i + 1, j + 1), vert(i, j + 1)}, object);
        }
}

Geometry closed_meshes(Sampler&) {
  Geometry g;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(g, {0.f, 0.f, 0.f}, 2.f, 10, identity, 0);
  const Vec3 ex = normalize(Vec3{1.f, 0.4f, -0.3f});
  const Vec3 ey = normalize(cross(Vec3{0.1f, 0.2f, 1.f}, ex));
  const Vec3 rotated[3] = {ex, ey, cross(ex, ey)};
  add_cube_mesh(g, {7.f, 1.f, -1.f}, 1.5f, 8, rotated, 1);
  return g;
}

// ---------------------------------------------------------------------------------------------
// Rays and comparison

// A point on (or, for spheres, inside) primitive `id`: a ray aimed at it almost surely hits it.
Vec3 point_on(const Geometry& g, std::uint32_t id, Sampler& s) {
  const ShapeRef ref = g.resolve(id);
  if (ref.kind == ShapeKind::kTriangle) {
    const Triangle& t = g.triangles[ref.index];
    float a = s.rng.next_float(), b = s.rng.next_float();
    if (a + b > 1.f) a = 1.f - a, b = 1.f - b;
    return t.p0 + (t.p1 - t.p0) * a + (t.p2 - t.p0) * b;
  }
  if (ref.kind == ShapeKind::kSphere)
    return g.spheres[ref.index].center + s.unit() * (0.9f * g.spheres[ref.index].radius);
  const Box3 box = g.bounds(id);
  return s.in_box(box.lo, box.hi);
}

// Origins inside and outside the scene box; directions uniform, axis-parallel (with +0 and -0 in
// the other components), or aimed at a random primitive so that a good share of rays hit.
std::vector<Ray> random_rays(const Geometry& g, Sampler& s, int count) {
  const Box3 box = g.bounds();
  const Vec3 margin = box.extent();
  std::vector<Ray> rays(count);
  for (Ray& r : rays) {
    r.origin = s.rng.next_float() < 0.5f ? s.in_box(box.lo, box.hi) : s.in_box(box.lo - margin, box.hi + margin);
    const float kind = s.rng.next_float();
    if (kind < 0.15f) {
      Vec3 d{s.rng.next_float() < 0.5f ? 0.f : -0.f, s.rng.next_float() < 0.5f ? 0.f : -0.f,
             s.rng.next_float() < 0.5f ? 0.f : -0.f};
      d[static_cast<int>(s.rng.next_u32() % 3)] = s.rng.next_float() < 0.5f ? 1.f : -1.f;
      r.direction = d;
    } else if (kind < 0.5f) {
      r.direction = point_on(g, s.rng.next_u32() % g.size(), s) - r.origin;
    } else {
      r.direction = s.unit() * s.uni(0.5f, 2.f);
    }
    if (s.rng.next_float() < 0.1f) r.tmin = s.uni(0.f, 0.3f) * length(box.extent()) / length(r.direction);
  }
  return rays;
}

bool same_hit(const Hit& a, const Hit& b) { return a.t == b.t && a.prim_id == b.prim_id && a.u == b.u && a.v == b.v; }

// Compares every query of `bvh` with `brute` on `rays`; reports the first few failures in detail.
void compare(const Geometry& g, const Accelerator& bvh, const Accelerator& brute, const std::vector<Ray>& rays,
             Sampler& s) {
  int failures = 0, hits = 0;
  auto fail = [&](const std::string& what, const Ray& r) {
    if (++failures <= 5) {
      ADD_FAILURE() << what << " for ray o=(" << r.origin.x << ", " << r.origin.y << ", " << r.origin.z << ") d=("
                    << r.direction.x << ", " << r.direction.y << ", " << r.direction.z << ") tmin=" << r.tmin;
    }
  };
  TraversalStats bvh_stats;
  int counted = 0;
  for (const Ray& ray : rays) {
    Ray rb = ray, rv = ray;
    Hit hb, hv;
    const bool fb = brute.intersect(rb, hb);
    const bool fv = bvh.intersect(rv, hv);
    if (fb != fv) {
      fail(fb ? "BVH missed a hit" : "BVH found a phantom hit", ray);
      continue;
    }
    if (fb) {
      ++hits;
      if (rb.tmax != hb.t || rv.tmax != hv.t) fail("tmax not shrunk to the hit", ray);
      if (!near(hb.t, hv.t)) fail("t differs: " + std::to_string(hb.t) + " vs " + std::to_string(hv.t), ray);
      if (hb.prim_id != hv.prim_id) {
        // Allowed only for a tie: the BVH's primitive, tested alone, must hit at the same t.
        Ray alone = ray;
        Hit h;
        if (!g.intersect(hv.prim_id, WatertightRay(alone), alone, h) || !near(h.t, hb.t)) {
          fail("different primitive without a tie", ray);
        }
      }
    } else if (rv.tmax != ray.tmax || hv.valid()) {
      fail("a miss changed the ray or the hit", ray);
    }

    // Counted versions: the same answer, bit for bit, plus plausible counts.
    Ray rc = ray;
    Hit hc;
    TraversalStats st;
    const bool fc = bvh.intersect_counted(rc, hc, st);
    if (fc != fv || !same_hit(hc, hv)) fail("intersect_counted differs from intersect", ray);
    if (st.nodes_visited < 1 || st.prim_tests > g.size() || st.hits != (fc ? 1u : 0u)) fail("implausible counts", ray);
    bvh_stats += st;
    if (++counted % 8 == 0) {  // brute force is slow; a sample of rays checks its counts
      TraversalStats sb;
      Ray rbc = ray;
      Hit hbc;
      brute.intersect_counted(rbc, hbc, sb);
      if (sb.prim_tests != g.size() || sb.hits != (fb ? 1u : 0u) || !same_hit(hbc, hb)) {
        fail("brute intersect_counted", ray);
      }
    }

    // Any-hit with a random tmax: occluded iff the closest hit lies before tmax.
    Ray ro = ray;
    ro.tmax = fb ? hb.t * s.uni(0.5f, 1.5f) : (s.rng.next_float() < 0.5f ? kInf : s.uni(0.f, 1e5f));
    if (fb && std::fabs(ro.tmax - hb.t) <= kRelTol * hb.t) continue;  // too close to call
    const bool expected = fb && hb.t < ro.tmax;
    if (bvh.occluded(ro) != expected) fail(expected ? "BVH occluded missed" : "BVH occluded phantom", ro);
    if (brute.occluded(ro) != expected) fail("brute occluded disagrees with brute intersect", ro);
    TraversalStats so;
    if (bvh.occluded_counted(ro, so) != expected || so.hits != (expected ? 1u : 0u)) fail("occluded_counted", ro);
  }
  EXPECT_EQ(failures, 0) << "of " << rays.size() << " rays";
  EXPECT_GT(hits, int(rays.size()) / 10) << "too few hits for a meaningful comparison";
  // The BVH must do much less work than testing everything (brute force: size() tests a ray).
  EXPECT_LT(bvh_stats.prim_tests * 4, std::uint64_t(g.size()) * rays.size());
}

// Every structural promise of BvhTree, checked by walking it from the root.
void check_tree(const BvhTree& tree, const Geometry& g, const BvhConfig& config) {
  const std::uint32_t n = g.size();
  ASSERT_EQ(tree.prim_ids.size(), n);
  std::vector<int> seen(n, 0), slot_used(n, 0), node_seen(tree.nodes.size(), 0);
  for (std::uint32_t id : tree.prim_ids) {
    ASSERT_LT(id, n);
    ++seen[id];
  }
  for (std::uint32_t i = 0; i < n; ++i) EXPECT_EQ(seen[i], 1) << "prim " << i;
  auto box_of = [](const BvhNode& node) {
    return Box3{{node.lo[0], node.lo[1], node.lo[2]}, {node.hi[0], node.hi[1], node.hi[2]}};
  };
  auto inside = [](const Box3& in, const Box3& out) {
    return out.lo.x <= in.lo.x && out.lo.y <= in.lo.y && out.lo.z <= in.lo.z && in.hi.x <= out.hi.x &&
           in.hi.y <= out.hi.y && in.hi.z <= out.hi.z;
  };
  std::size_t leaves = 0;
  int max_depth = 0;
  std::vector<std::pair<std::uint32_t, int>> stack{{0u, 0}};
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    ASSERT_LT(index, tree.nodes.size());
    ASSERT_EQ(++node_seen[index], 1) << "node reached twice";
    const BvhNode& node = tree.nodes[index];
    const Box3 box = box_of(node);
    if (node.is_leaf()) {
      ++leaves;
      max_depth = std::max(max_depth, depth);
      EXPECT_LE(node.count, static_cast<std::uint32_t>(std::max(1, config.max_leaf_size)));
      ASSERT_LE(node.first + node.count, n);
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        ++slot_used[i];
        EXPECT_TRUE(inside(g.bounds(tree.prim_ids[i]), box)) << "prim outside its leaf";
      }
    } else {
      ASSERT_GT(node.first, index) << "children are laid out after their parent";
      ASSERT_LT(node.first + 1, tree.nodes.size());
      for (std::uint32_t c : {node.first, node.first + 1}) {
        EXPECT_TRUE(inside(box_of(tree.nodes[c]), box)) << "child box outside its parent";
        stack.emplace_back(c, depth + 1);
      }
    }
  }
  for (std::uint32_t i = 0; i < n; ++i) EXPECT_EQ(slot_used[i], 1) << "reference slot " << i;
  EXPECT_EQ(std::count(node_seen.begin(), node_seen.end(), 1), std::ptrdiff_t(tree.nodes.size())) << "orphan nodes";
  EXPECT_EQ(leaves, tree.leaf_count);
  EXPECT_EQ(max_depth, tree.max_depth);
  EXPECT_EQ(leaves * 2 - 1, tree.nodes.size()) << "a binary tree";
  // A SAH build must beat the one-leaf tree (cost n) by far on these scattered scenes.
  EXPECT_LT(sah_cost(tree, config), 0.2 * n);
}

using SceneMaker = std::function<Geometry(Sampler&)>;

void run_scene(const SceneMaker& make, std::uint64_t seed, int ray_count = 10000) {
  Sampler s(seed);
  const Geometry g = make(s);
  const Bvh bvh(g);
  const BruteForce brute(g);
  check_tree(bvh.tree(), g, BvhConfig{});
  const Box3 b = bvh.bounds(), gb = g.bounds();
  EXPECT_EQ(b.lo, gb.lo);
  EXPECT_EQ(b.hi, gb.hi);
  EXPECT_EQ(bvh.info().primitive_count, g.size());
  compare(g, bvh, brute, random_rays(g, s, ray_count), s);
}

TEST(BvhVsBrute, OverlappingSpheresAndTriangles) { run_scene(spheres_and_triangles, 1); }
TEST(BvhVsBrute, Slivers) { run_scene(slivers, 2); }
TEST(BvhVsBrute, SizesFrom1em4To1e4) { run_scene(sizes_over_eight_decades, 3); }
TEST(BvhVsBrute, DenseTriangleSoup) { run_scene(dense_soup, 4); }
TEST(BvhVsBrute, EveryShapeKind) { run_scene(every_shape_kind, 5); }
TEST(BvhVsBrute, ClosedMeshes) { run_scene(closed_meshes, 6); }

// Rays from inside the closed cubes exactly through shared triangle edges and vertices: the BVH
// must not lose them in its boxes (the cube's faces have zero-thickness boxes).
TEST(BvhVsBrute, ClosedMeshRaysThroughEdgesAndVertices) {
  Sampler s(60);
  const Geometry g = closed_meshes(s);
  const Bvh bvh(g);
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
      const bool fv = bvh.intersect(rv, hv), fb = brute.intersect(rb, hb);
      if (!fv || !fb || std::fabs(hv.t - 1.f) > 1e-4f || std::fabs(hb.t - 1.f) > 1e-4f ||
          !bvh.occluded(Ray{o, 0.f, target - o})) {
        if (++failures <= 5)
          ADD_FAILURE() << "leak through triangle " << i << " feature " << k << " bvh " << fv << " brute " << fb;
      }
    }
  }
  EXPECT_EQ(failures, 0);
}

// Rays lying in the plane of an axis-aligned cube's faces (origin on the plane, direction
// component +0 or -0 across it): slab tests of those faces see 0 * inf or a substituted tiny
// direction, and must not cull them. Planes at +-2, and at 0 where origin * inv_dir is exactly 0.
// Compared with brute force rather than with a fixed answer.
void rays_in_face_planes(const Geometry& g, float lo, float hi, std::uint64_t seed) {
  Sampler s(seed);
  const Bvh bvh(g);
  const BruteForce brute(g);
  std::vector<Ray> rays;
  for (int i = 0; i < 3000; ++i) {
    const int axis = static_cast<int>(s.rng.next_u32() % 3);
    Ray r;
    r.origin = s.in_box(Vec3(lo - 1.f), Vec3(hi + 1.f));
    r.origin[axis] = s.rng.next_float() < 0.5f ? lo : hi;  // exactly on a face plane (and node planes)
    r.direction = s.unit();
    r.direction[axis] = s.rng.next_float() < 0.5f ? 0.f : -0.f;
    if (i % 4 == 0) r.direction[(axis + 1) % 3] = 0.f;  // along a face edge direction too
    rays.push_back(r);
  }
  compare(g, bvh, brute, rays, s);
}

TEST(BvhVsBrute, RaysInFacePlanes) {
  Sampler s(61);
  rays_in_face_planes(closed_meshes(s), -2.f, 2.f, 62);
  Geometry at_zero;
  const Vec3 identity[3] = {{1.f, 0.f, 0.f}, {0.f, 1.f, 0.f}, {0.f, 0.f, 1.f}};
  add_cube_mesh(at_zero, {2.f, 2.f, 2.f}, 2.f, 6, identity, 0);
  rays_in_face_planes(at_zero, 0.f, 4.f, 63);
}

// Build parameters other than the defaults must give the same answers.
TEST(BvhVsBrute, OtherBuildConfigs) {
  for (const BvhConfig config :
       {BvhConfig{2, 1, 1.f, 1.f, 4096}, BvhConfig{64, 32, 0.5f, 2.f, 4096}, BvhConfig{16, 4, 1.f, 1.f, 64}}) {
    Sampler s(7);
    const Geometry g = every_shape_kind(s);
    const Bvh bvh(g, config);
    const BruteForce brute(g);
    check_tree(bvh.tree(), g, config);
    compare(g, bvh, brute, random_rays(g, s, 2000), s);
  }
}

TEST(BvhPacket, GroupQueriesEqualSingleRays) {
  Sampler s(8);
  const Geometry g = spheres_and_triangles(s);
  const Bvh bvh(g);
  std::vector<Ray> rays = random_rays(g, s, 512);
  std::vector<Ray> singles = rays;
  std::vector<Hit> hits(rays.size()), single_hits(rays.size());
  bvh.intersect(std::span<Ray>(rays), std::span<Hit>(hits));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    bvh.intersect(singles[i], single_hits[i]);
    EXPECT_TRUE(same_hit(hits[i], single_hits[i])) << "ray " << i;
    EXPECT_EQ(rays[i].tmax, singles[i].tmax) << "ray " << i;
  }
  std::vector<std::uint8_t> occ(rays.size(), 7);
  const std::vector<Ray> shadow = random_rays(g, s, 512);
  bvh.occluded(std::span<const Ray>(shadow), std::span<std::uint8_t>(occ));
  for (std::size_t i = 0; i < shadow.size(); ++i) EXPECT_EQ(occ[i], bvh.occluded(shadow[i]) ? 1 : 0) << "ray " << i;
}

TEST(BvhEdgeCases, EmptyGeometry) {
  const Geometry g;
  for (const auto& accel : {make_accelerator("bvh", g), make_accelerator("brute", g)}) {
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
}

TEST(BvhEdgeCases, SinglePrimitive) {
  Geometry g;
  g.add(Sphere{{0.f, 0.f, 5.f}, 1.f}, 3);
  const Bvh bvh(g);
  ASSERT_EQ(bvh.tree().nodes.size(), 1u);
  EXPECT_EQ(bvh.tree().leaf_count, 1u);
  Ray ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}};
  Hit hit;
  ASSERT_TRUE(bvh.intersect(ray, hit));
  EXPECT_FLOAT_EQ(hit.t, 4.f);
  EXPECT_EQ(hit.prim_id, 0u);
  EXPECT_TRUE(bvh.occluded(Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}, 4.5f}));
  EXPECT_FALSE(bvh.occluded(Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, 1.f}, 3.5f}));
  EXPECT_FALSE(bvh.occluded(Ray{{0.f, 0.f, 0.f}, 0.f, {0.f, 0.f, -1.f}}));
}

TEST(BvhSah, CostOfHandBuiltTrees) {
  BvhTree one_leaf;
  one_leaf.nodes.push_back(BvhNode{{0.f, 0.f, 0.f}, 0, {1.f, 1.f, 1.f}, 10});
  EXPECT_DOUBLE_EQ(sah_cost(one_leaf), 10.0);  // 10 primitive tests, always
  BvhTree split;
  split.nodes = {BvhNode{{0.f, 0.f, 0.f}, 1, {2.f, 1.f, 1.f}, 0},   // root: area 10
                 BvhNode{{0.f, 0.f, 0.f}, 0, {1.f, 1.f, 1.f}, 4},   // area 6, 4 prims
                 BvhNode{{1.f, 0.f, 0.f}, 4, {2.f, 1.f, 1.f}, 6}};  // area 6, 6 prims
  EXPECT_DOUBLE_EQ(sah_cost(split), 1.0 + 0.6 * 4 + 0.6 * 6);
  EXPECT_DOUBLE_EQ(sah_cost(split, BvhConfig{16, 8, 2.f, 0.5f, 4096}), 2.0 + 0.5 * (0.6 * 4 + 0.6 * 6));
}

TEST(AccelFactory, NamesAndUnknownName) {
  const auto names = accelerator_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "bvh"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "brute"), names.end());
  Geometry g;
  g.add(Sphere{}, 0);
  EXPECT_EQ(make_accelerator("bvh", g)->info().name, "bvh");
  EXPECT_EQ(make_accelerator("brute", g)->info().name, "brute");
  try {
    make_accelerator("nope", g);
    FAIL() << "no exception for an unknown name";
  } catch (const UsageError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("nope"), std::string::npos) << msg;
    EXPECT_NE(msg.find("bvh"), std::string::npos) << msg;
    EXPECT_NE(msg.find("brute"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace raylab
