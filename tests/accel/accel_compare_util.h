#pragma once
// The accelerator-versus-brute-force comparison shared by the property tests of every structure
// (accel_vs_brute_test.cpp for all of them and every wrap mode, bvh_vs_brute_test.cpp for the
// BVH-only cases): every query must be answered as brute force answers it, up to float ties.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/brute_force.h"
#include "test_scenes.h"

namespace raylab::test_scenes {

inline constexpr float kRelTol = 1e-5f;

inline bool near(float a, float b) { return std::fabs(a - b) <= kRelTol * std::max(std::fabs(a), std::fabs(b)); }

inline bool same_hit(const Hit& a, const Hit& b) {
  return a.t == b.t && a.prim_id == b.prim_id && a.u == b.u && a.v == b.v;
}

// Compares every query of `bvh` with `brute` on `rays`; reports the first few failures in detail.
inline void compare(const Geometry& g, const Accelerator& bvh, const Accelerator& brute, const std::vector<Ray>& rays,
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
    if (st.prim_tests > g.size() || st.hits != (fc ? 1u : 0u)) fail("implausible counts", ray);
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

// Rays lying in the plane of an axis-aligned cube's faces (origin on the plane, direction
// component +0 or -0 across it): slab tests of those faces see 0 * inf or a substituted tiny
// direction, and must not cull them. Planes at +-2, and at 0 where origin * inv_dir is exactly 0.
// Compared with brute force rather than with a fixed answer.
inline void rays_in_face_planes(const Accelerator& bvh, const Geometry& g, float lo, float hi, std::uint64_t seed) {
  Sampler s(seed);
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

}  // namespace raylab::test_scenes
