#pragma once
// The accelerator-versus-brute-force comparison shared by the property tests of every structure
// (accel_vs_brute_test.cpp for all of them and every wrap mode, bvh_vs_brute_test.cpp for the
// BVH-only cases): every query must be answered as brute force answers it, up to float ties. Its
// parts (both_hits, the tie rule, describe) serve the other structures' own tests too.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "raylab/accel/accelerator.h"
#include "raylab/accel/brute_force.h"
#include "test_scenes.h"

namespace raylab::test_scenes {

inline constexpr float kRelTol = 1e-5f;

/// Whether `a` and `b` agree within `rel_tol` of the larger.
inline bool near(float a, float b, float rel_tol = kRelTol) {
  return std::fabs(a - b) <= rel_tol * std::max(std::fabs(a), std::fabs(b));
}

inline bool same_hit(const Hit& a, const Hit& b) {
  return a.t == b.t && a.prim_id == b.prim_id && a.u == b.u && a.v == b.v;
}

/// "ray o=(x, y, z) d=(x, y, z) [tmin, tmax)", to 9 digits, for failure messages.
inline std::string describe(const Ray& r) {
  std::ostringstream out;
  out.precision(9);
  out << "ray o=(" << r.origin.x << ", " << r.origin.y << ", " << r.origin.z << ") d=(" << r.direction.x << ", "
      << r.direction.y << ", " << r.direction.z << ") [" << r.tmin << ", " << r.tmax << ")";
  return out.str();
}

/// A closest-hit query on its own copy of the ray (whose tmax then shows what the query shrank it
/// to). The members bind in this order: `const auto [r, h, found] = closest_hit(accel, ray);`
struct ClosestHit {
  Ray ray;
  Hit hit;
  bool found = false;
};

/// Traces `ray` through `accel` (see ClosestHit).
inline ClosestHit closest_hit(const Accelerator& accel, const Ray& ray) {
  ClosestHit c{ray, {}, false};
  c.found = accel.intersect(c.ray, c.hit);
  return c;
}

/// The closest hit of each of `rays` by `reference` (invalid where it finds none).
inline std::vector<Hit> closest_hits(const Accelerator& reference, const std::vector<Ray>& rays) {
  std::vector<Hit> hits;
  for (const Ray& ray : rays) hits.push_back(closest_hit(reference, ray).hit);
  return hits;
}

/// One ray's closest hit by brute force and by another structure, each traced on its own copy of
/// the ray (whose tmax then shows what the query shrank it to). The members bind in this order:
/// `const auto [rb, hb, fb, rv, hv, fv] = both_hits(brute, accel, ray);`
struct BothHits {
  Ray brute_ray;
  Hit brute_hit;
  bool brute_found = false;
  Ray ray;
  Hit hit;
  bool found = false;
};

/// Traces `ray` through `brute` and `accel` (see BothHits).
inline BothHits both_hits(const Accelerator& brute, const Accelerator& accel, const Ray& ray) {
  const ClosestHit b = closest_hit(brute, ray), a = closest_hit(accel, ray);
  return {b.ray, b.hit, b.found, a.ray, a.hit, a.found};
}

/// A closest-hit query with its traversal counts, on its own copy of the ray. The members bind in
/// this order: `const auto [rc, hc, fc, st] = counted_hit(accel, ray);`
struct CountedHit {
  Ray ray;
  Hit hit;
  bool found = false;
  TraversalStats stats;
};

/// Traces `ray` through `accel` with intersect_counted (see CountedHit).
inline CountedHit counted_hit(const Accelerator& accel, const Ray& ray) {
  CountedHit c{ray, {}, false, {}};
  c.found = accel.intersect_counted(c.ray, c.hit, c.stats);
  return c;
}

/// `ray` with a random tmax for an any-hit query: 0.5 to 1.5 times the closest hit's distance `t`
/// when `found`, else infinite or up to 1e5 at even odds.
inline Ray with_random_tmax(const Ray& ray, bool found, float t, Sampler& s) {
  Ray r = ray;
  r.tmax = found ? t * s.uni(0.5f, 1.5f) : (s.rng.next_float() < 0.5f ? kInf : s.uni(0.f, 1e5f));
  return r;
}

/// The hit of primitive `id` of `g` alone on `ray`, if it hits: a structure that answers with
/// another primitive than brute force must have found a tie, which this checks.
inline std::optional<Hit> hit_alone(const Geometry& g, std::uint32_t id, const Ray& ray) {
  Ray alone = ray;
  Hit h;
  if (!g.intersect(id, WatertightRay(alone), alone, h)) return std::nullopt;
  return h;
}

/// The tie rule: primitive `id`, tested alone, hits `ray` within kRelTol of brute force's `t`.
inline bool is_tie(const Geometry& g, std::uint32_t id, const Ray& ray, float t) {
  const std::optional<Hit> h = hit_alone(g, id, ray);
  return h && near(h->t, t);
}

/// The ids of every third primitive of `g`: a subset for structures built over some primitives.
inline std::vector<std::uint32_t> every_third_id(const Geometry& g) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t id = 0; id < g.size(); id += 3) ids.push_back(id);
  return ids;
}

/// What is wrong with a structure's closest hit for `ray` (`found`, `hit`, and the ray as the
/// query left it, `after`) against brute force's (`expected_found`, `expected`): a missed or
/// phantom hit, tmax not shrunk to the hit, another t (beyond kRelTol), another primitive
/// without a tie, or a miss that changed the ray or the hit. Empty when they agree.
inline std::string closest_hit_disagreement(const Geometry& g, const Ray& ray, bool expected_found, const Hit& expected,
                                            bool found, const Hit& hit, const Ray& after) {
  if (found != expected_found) return found ? "phantom hit" : "missed hit";
  if (!found) return after.tmax != ray.tmax || hit.valid() ? "a miss changed the ray or the hit" : "";
  if (after.tmax != hit.t) return "tmax not shrunk to the hit";
  if (!near(expected.t, hit.t)) return "t differs: " + std::to_string(expected.t) + " vs " + std::to_string(hit.t);
  if (expected.prim_id != hit.prim_id && !is_tie(g, hit.prim_id, ray, expected.t)) {
    return "primitive " + std::to_string(hit.prim_id) + " instead of " + std::to_string(expected.prim_id);
  }
  return "";
}

// Compares every query of `bvh` with `brute` on `rays`; reports the first few failures in detail.
inline void compare(const Geometry& g, const Accelerator& bvh, const Accelerator& brute, const std::vector<Ray>& rays,
                    Sampler& s) {
  int failures = 0, hits = 0;
  auto fail = [&](const std::string& what, const Ray& r) {
    if (++failures <= 5) ADD_FAILURE() << what << " for " << describe(r);
  };
  TraversalStats bvh_stats;
  int counted = 0;
  for (const Ray& ray : rays) {
    const auto [rb, hb, fb, rv, hv, fv] = both_hits(brute, bvh, ray);
    if (fb && rb.tmax != hb.t) fail("brute force did not shrink tmax to the hit", ray);
    if (const std::string wrong = closest_hit_disagreement(g, ray, fb, hb, fv, hv, rv); !wrong.empty()) {
      fail(wrong, ray);
      if (fb != fv) continue;
    }
    if (fb) ++hits;

    // Counted versions: the same answer, bit for bit, plus plausible counts.
    const auto [rc, hc, fc, st] = counted_hit(bvh, ray);
    if (fc != fv || !same_hit(hc, hv)) fail("intersect_counted differs from intersect", ray);
    if (st.prim_tests > g.size() || st.hits != (fc ? 1u : 0u)) fail("implausible counts", ray);
    bvh_stats += st;
    if (++counted % 8 == 0) {  // brute force is slow; a sample of rays checks its counts
      const auto [rbc, hbc, fbc, sb] = counted_hit(brute, ray);
      if (sb.prim_tests != g.size() || sb.hits != (fb ? 1u : 0u) || !same_hit(hbc, hb)) {
        fail("brute intersect_counted", ray);
      }
    }

    // Any-hit with a random tmax: occluded iff the closest hit lies before tmax.
    const Ray ro = with_random_tmax(ray, fb, hb.t, s);
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
    r.direction[axis] = signed_zero(s);
    if (i % 4 == 0) r.direction[(axis + 1) % 3] = 0.f;  // along a face edge direction too
    rays.push_back(r);
  }
  compare(g, bvh, brute, rays, s);
}

}  // namespace raylab::test_scenes
