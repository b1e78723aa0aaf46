// Robustness of every structure the factory builds by name (bvh, bvh2, bvh4, bvh8, bvh16, grid,
// octree, brute and, where built, embree), against the inputs that reach a tracer by accident
// rather than by design. Two families:
//
// - Bad rays: NaN, +-Inf, denormal, tiny and huge components in the origin and the direction,
//   zero directions, NaN and infinite interval ends. Each is sent alone (intersect, occluded and
//   their counted twins) and inside groups of 1 to 17 rays mixed with good ones (the span
//   versions, whose packet kernels run 4, 8 and 16 lanes and fall back to single rays for short
//   runs), so every packet width and remainder sees them. Negative tmin has a test of its own.
// - Degenerate scenes: empty, one primitive, a thousand coincident copies of one triangle or
//   sphere (no split separates them), and scenes scaled to 1e-30 and 1e30 with their rays (and to
//   1e-10 and 1e10, where the shape tests still find hits to compare).
//
// What is right for each ray:
// - A ray with a NaN anywhere, or a direction with an infinite component, or a zero direction,
//   is no ray: it must hit nothing and not be occluded, whatever the arithmetic of a shape test
//   makes of it (the library's promise: traceable_direction in raylab/core/ray.h).
// - Every other ray must get exactly brute force's answer (t, primitive, u, v; Embree may name
//   another primitive at exactly the same t), infinities included: brute force decides what an
//   infinite component means (an infinite origin hits nothing). Good rays in a packet get exactly their own
//   single-ray answer whatever their neighbours are.
// - Except rays that float cannot resolve: a finite direction so short or long that distances
//   across the scene overflow or underflow t (max |d| outside [1e-15, 1e15]), or an origin a
//   thousand scene sizes away (FLT_MAX). For them brute force's answer is rounding noise too
//   (t = -0 accepted, a far primitive's t rounding to a near one's), so they are held only to what
//   does not depend on rounding: no crash, any hit real (its primitive alone hits it there, inside
//   the interval), counted queries and packets equal to single rays.
//
// "No crash" is asserted by running at all: CI runs the suite under ASan and UBSan, and a
// traversal that loops for ever runs into ctest's timeout.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "accel_compare_util.h"
#include "raylab/accel/brute_force.h"
#include "raylab/accel/factory.h"
#include "test_scenes.h"

namespace raylab {
namespace {

using namespace test_scenes;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kDenormMin = std::numeric_limits<float>::denorm_min();
constexpr float kDenorm = 1e-40f;                           // a denormal well above the minimum
constexpr float kTiny = std::numeric_limits<float>::min();  // smallest normal: 1 / it is finite
constexpr float kHuge = std::numeric_limits<float>::max();  // finite, but 2 * it is not

// The longest group sent to the span versions: past 16, the largest packet, so that a group
// splits into a full packet and a remainder.
constexpr int kMaxGroup = 17;

// ---------------------------------------------------------------------------------------------
// What a correct answer is

bool has_nan(const Ray& r) {
  return std::isnan(r.origin.x) || std::isnan(r.origin.y) || std::isnan(r.origin.z) || std::isnan(r.direction.x) ||
         std::isnan(r.direction.y) || std::isnan(r.direction.z) || std::isnan(r.tmin) || std::isnan(r.tmax);
}

// A ray that is no ray (see the top of the file): nothing can be hit along it.
float max_abs(Vec3 v) { return std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z))); }

bool must_miss(const Ray& r) { return has_nan(r) || r.direction == Vec3(0.f) || std::isinf(max_abs(r.direction)); }

// Which rays a structure must answer exactly as brute force does (see the top of the file).
struct Exact {
  float scale;    ///< how far the scene's coordinates reach
  bool own_ties;  ///< Embree, which breaks exact ties in its own traversal order

  Exact(const Geometry& g, const std::string& name)
      : scale(g.size() == 0 ? 1.f : std::max(max_abs(g.bounds().lo), max_abs(g.bounds().hi))),
        own_ties(name == "embree") {}

  bool operator()(const Ray& r) const {
    const float d = max_abs(r.direction);
    if (std::isinf(d)) return true;  // no ray: a miss is the exact answer
    if (std::isinf(max_abs(r.origin))) return true;
    return d >= 1e-15f && d <= 1e15f && max_abs(r.origin) <= 1e3f * scale;
  }
};

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

// A closest-hit query's whole result: the answer, the hit record and the ray's tmax after it.
struct Answer {
  bool found = false;
  Hit hit;
  float tmax = 0.f;
};

bool same_answer(const Answer& a, const Answer& b) {
  return a.found == b.found && same_hit(a.hit, b.hit) && same_bits(a.tmax, b.tmax);
}

Answer closest(const Accelerator& accel, Ray ray) {
  Answer a;
  a.found = accel.intersect(ray, a.hit);
  a.tmax = ray.tmax;
  return a;
}

Answer closest_counted(const Accelerator& accel, Ray ray) {
  Answer a;
  TraversalStats stats;
  a.found = accel.intersect_counted(ray, a.hit, stats);
  a.tmax = ray.tmax;
  return a;
}

// Why `got`, a structure's closest hit for `ray`, is wrong (empty when it is right), given brute
// force's `want`. Always: nothing hit along a ray that is no ray; a miss leaves the ray and the
// hit record untouched; a hit lies in [tmin, tmax), shrinks tmax to it, and is real (its
// primitive alone hits there, bit for bit: every structure runs the same shape tests). For rays
// float resolves, also exactly brute force's answer (t, primitive, u, v, tmax: the same shape
// tests and the same lower-id rule for ties), except that Embree may name another primitive at
// exactly the same t (it breaks ties in its own traversal order).
std::string wrong_closest(const Geometry& g, const Ray& ray, const Answer& want, const Answer& got,
                          const Exact& exact) {
  if (must_miss(ray) && want.found) return "brute force hit along a ray that is no ray";
  if (must_miss(ray) && got.found) return "hit along a ray that is no ray";
  if (!got.found && (got.hit.valid() || !same_bits(got.tmax, ray.tmax))) return "a miss changed the ray or the hit";
  if (got.found) {
    if (!same_bits(got.tmax, got.hit.t)) return "tmax not shrunk to the hit";
    if (!(got.hit.t >= ray.tmin && got.hit.t < ray.tmax)) return "hit outside [tmin, tmax)";
    const std::optional<Hit> h = hit_alone(g, got.hit.prim_id, ray);
    if (!h || !same_bits(h->t, got.hit.t)) {
      return "primitive " + std::to_string(got.hit.prim_id) + " alone is not hit at t " + std::to_string(got.hit.t);
    }
  }
  if (!exact(ray)) return "";
  if (want.found != got.found) return want.found ? "missed brute force's hit" : "hit where brute force misses";
  if (same_answer(want, got)) return "";
  if (exact.own_ties && same_bits(want.hit.t, got.hit.t) && want.hit.prim_id != got.hit.prim_id) return "";
  return "t " + std::to_string(got.hit.t) + " (primitive " + std::to_string(got.hit.prim_id) + ") vs brute force's " +
         std::to_string(want.hit.t) + " (primitive " + std::to_string(want.hit.prim_id) + ")";
}

// Why an any-hit answer is wrong: along a ray that is no ray, anything but "not occluded"; along
// a ray float resolves, anything but brute force's answer.
std::string wrong_occluded(const Ray& ray, bool want, bool got, bool exact) {
  if (must_miss(ray) && want) return "brute force occluded along a ray that is no ray";
  if (must_miss(ray) && got) return "occluded along a ray that is no ray";
  if (exact && want != got) return got ? "occluded, brute force not" : "not occluded, brute force is";
  return "";
}

// Counts failures and reports the first few in full (one bad ray tends to fail many ways).
class Failures {
 public:
  explicit Failures(std::string where) : m_where(std::move(where)) {}
  Failures(const Failures&) = delete;
  Failures& operator=(const Failures&) = delete;
  ~Failures() { EXPECT_EQ(m_count, 0) << m_where; }

  void check(const std::string& why, const std::string& query, const Ray& ray) {
    if (why.empty()) return;
    if (++m_count <= 6) ADD_FAILURE() << m_where << ": " << query << ": " << why << " for " << describe(ray);
  }

 private:
  std::string m_where;
  int m_count = 0;
};

// Brute force's answers to `rays`, computed once and held against every structure.
struct Expected {
  std::vector<Answer> closest;
  std::vector<bool> occluded;
};

Expected brute_answers(const BruteForce& brute, const std::vector<Ray>& rays) {
  Expected e;
  for (const Ray& r : rays) {
    e.closest.push_back(closest(brute, r));
    e.occluded.push_back(brute.occluded(r));
  }
  return e;
}

// Every single-ray query of `accel` on `rays`; the counted variants, separate kernels, must give
// the uncounted ones' bits.
void check_single_rays(const Accelerator& accel, const Geometry& g, const std::vector<Ray>& rays, const Expected& want,
                       const Exact& exact, Failures& failures) {
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Ray& r = rays[i];
    const Answer got = closest(accel, r);
    failures.check(wrong_closest(g, r, want.closest[i], got, exact), "intersect", r);
    failures.check(same_answer(got, closest_counted(accel, r)) ? "" : "differs from intersect", "intersect_counted", r);
    const bool occluded = accel.occluded(r);
    failures.check(wrong_occluded(r, want.occluded[i], occluded, exact(r)), "occluded", r);
    TraversalStats stats;
    failures.check(accel.occluded_counted(r, stats) == occluded ? "" : "differs from occluded", "occluded_counted", r);
  }
}

// The span versions on rays[first, first + n): every ray gets exactly what the same structure
// answers for it alone, and brute force's answer.
void check_group(const Accelerator& accel, const Geometry& g, const std::vector<Ray>& rays, const Expected& want,
                 std::size_t first, std::size_t n, const Exact& exact, Failures& failures) {
  std::vector<Ray> group(rays.begin() + std::ptrdiff_t(first), rays.begin() + std::ptrdiff_t(first + n));
  std::vector<Hit> hits(n);
  accel.intersect(std::span<Ray>(group), std::span<Hit>(hits));
  std::vector<std::uint8_t> occluded(n, 7);  // neither 0 nor 1: every entry must be written
  accel.occluded(std::span<const Ray>(rays.data() + first, n), std::span<std::uint8_t>(occluded));
  for (std::size_t k = 0; k < n; ++k) {
    const Ray& r = rays[first + k];
    const Answer got{hits[k].valid(), hits[k], group[k].tmax};
    const std::string at = " of " + std::to_string(n) + ", ray " + std::to_string(k);
    failures.check(same_answer(got, closest(accel, r)) ? "" : "differs from the single-ray intersect",
                   "intersect(span)" + at, r);
    failures.check(wrong_closest(g, r, want.closest[first + k], got, exact), "intersect(span)" + at, r);
    const bool single = accel.occluded(r);
    failures.check(occluded[k] == (single ? 1 : 0) ? "" : "differs from the single-ray occluded", "occluded(span)" + at,
                   r);
    failures.check(wrong_occluded(r, want.occluded[first + k], occluded[k] == 1, exact(r)), "occluded(span)" + at, r);
  }
}

// ---------------------------------------------------------------------------------------------
// Bad rays

// Values a single component takes: NaN of both signs (a sign bit decides a packet's octant),
// infinities, denormals (whose reciprocal overflows), the smallest normal (whose reciprocal does
// not), the largest finite and zeros.
constexpr float kComponentValues[] = {kNaN,     -kNaN, INFINITY, -INFINITY, kDenormMin, -kDenormMin, kDenorm,
                                      -kDenorm, kTiny, -kTiny,   kHuge,     -kHuge,     0.f,         -0.f};
// Interval ends. Negative tmin has its own test (NegativeTmin), where it is explained.
constexpr float kTminValues[] = {kNaN, INFINITY, kDenormMin, -kDenormMin, kHuge};
constexpr float kTmaxValues[] = {kNaN, INFINITY, -INFINITY, 0.f, -0.f, kDenormMin, kHuge};

// Whole-vector values: zero directions, every component denormal, infinite, NaN or huge.
const Vec3 kDirectionValues[] = {{0.f, 0.f, 0.f},
                                 {-0.f, -0.f, -0.f},
                                 {0.f, -0.f, 0.f},
                                 {kDenorm, kDenorm, kDenorm},
                                 {-kDenormMin, kDenormMin, 0.f},
                                 {kDenorm, 0.f, 0.f},
                                 {kNaN, kNaN, kNaN},
                                 {INFINITY, INFINITY, INFINITY},
                                 {INFINITY, -INFINITY, 0.f},
                                 {kHuge, kHuge, kHuge}};
const Vec3 kOriginValues[] = {{kNaN, kNaN, kNaN},
                              {INFINITY, INFINITY, INFINITY},
                              {-INFINITY, 0.f, 0.f},
                              {kDenorm, -kDenormMin, kDenorm},
                              {kHuge, -kHuge, kHuge}};

// Every bad variant of `good`: one component replaced by each value above, then the whole origin
// and the whole direction, the direction made a billion times shorter and longer (not bad at all:
// the same ray with t in other units, which shape tests must not take for a degenerate one), then
// empty and reversed intervals.
std::vector<Ray> bad_variants(const Ray& good) {
  std::vector<Ray> out;
  for (int slot = 0; slot < 6; ++slot) {
    for (const float value : kComponentValues) {
      Ray r = good;
      (slot < 3 ? r.origin : r.direction)[slot % 3] = value;
      out.push_back(r);
    }
  }
  for (const float value : kTminValues) out.push_back(Ray{good.origin, value, good.direction, good.tmax});
  for (const float value : kTmaxValues) out.push_back(Ray{good.origin, good.tmin, good.direction, value});
  for (const Vec3& d : kDirectionValues) out.push_back(Ray{good.origin, good.tmin, d, good.tmax});
  for (const Vec3& o : kOriginValues) out.push_back(Ray{o, good.tmin, good.direction, good.tmax});
  out.push_back(Ray{good.origin, good.tmin * 1e9f, good.direction * 1e-9f, good.tmax * 1e9f});
  out.push_back(Ray{good.origin, good.tmin * 1e-9f, good.direction * 1e9f, good.tmax * 1e-9f});
  out.push_back(Ray{good.origin, 1.f, good.direction, 1.f});  // [1, 1) is empty
  out.push_back(Ray{good.origin, 2.f, good.direction, 1.f});
  return out;
}

// One random bad variant of `good`, keeping the direction's signs (its octant, by which packet
// kernels split a group) three times in four, so that bad rays share packets with good ones.
Ray random_bad_variant(const Ray& good, Sampler& s) {
  const std::vector<Ray> all = bad_variants(good);
  Ray r = all[s.rng.next_u32() % all.size()];
  if (s.rng.next_u32() % 4 != 0) {
    for (int a = 0; a < 3; ++a) r.direction[a] = std::copysign(r.direction[a], good.direction[a]);
  }
  return r;
}

// Groups of 1 to kMaxGroup rays for the span versions, one after another in one vector: rays of
// one octant from near a corner of the scene's box towards points on primitives (far corners
// make coherent packets, which the wide BVH walks on the packet's bounds alone, near ones
// incoherent), each replaced by a bad variant with a share that differs from group to group
// (none, some, half, most, all).
struct Groups {
  std::vector<Ray> rays;
  std::vector<std::pair<std::size_t, std::size_t>> ranges;  // (first, count)
};

Groups mixed_groups(const Geometry& g, Sampler& s, int per_size) {
  Groups out;
  const Box3 box = g.size() > 0 ? g.bounds() : Box3{Vec3(-1.f), Vec3(1.f)};
  const Vec3 extent = box.extent();
  const float bad_share[] = {0.f, 0.2f, 0.5f, 0.9f, 1.f};
  for (int n = 1; n <= kMaxGroup; ++n) {
    for (int k = 0; k < per_size; ++k) {
      const int octant = static_cast<int>(s.rng.next_u32() % 8);
      const float distance = k % 2 == 0 ? 0.1f : 10.f;
      Vec3 corner;
      for (int a = 0; a < 3; ++a) {
        const float margin = distance * extent[a];
        corner[a] = (octant >> a) & 1 ? box.hi[a] + margin : box.lo[a] - margin;
      }
      const float p_bad = bad_share[k % 5];
      out.ranges.emplace_back(out.rays.size(), n);
      for (int i = 0; i < n; ++i) {
        const Vec3 o = corner + s.in_box(Vec3(-0.02f), Vec3(0.02f)) * extent;
        const Vec3 target = g.size() > 0 ? point_on(g, s.rng.next_u32() % g.size(), s) : s.in_box(box.lo, box.hi);
        // Scaled to a largest component of 1, so that t stays in proportion to the scene's size
        // and the direction in the range float resolves, whatever the scene's scale.
        const Vec3 d = target - o;
        const Ray good{o, 0.f, d * (1.f / max_abs(d))};
        out.rays.push_back(s.rng.next_float() < p_bad ? random_bad_variant(good, s) : good);
      }
    }
  }
  return out;
}

// random_rays (inside and outside the box, axis-parallel, aimed at primitives), then a bad
// variant of every eighth one.
std::vector<Ray> rays_for(const Geometry& g, Sampler& s, int count) {
  std::vector<Ray> rays = random_rays(g, s, count);
  for (int i = 0; i < count; i += 8) rays.push_back(random_bad_variant(rays[std::size_t(i)], s));
  return rays;
}

// ---------------------------------------------------------------------------------------------
// The fixture: one structure per factory name.

std::vector<std::string> factory_names() {
  std::vector<std::string> names;
  for (const std::string_view n : accelerator_names()) names.emplace_back(n);
  return names;
}

// Hits among `rays` by brute force on `g`: a check must have some to say anything about them.
int brute_hits(const Geometry& g, const std::vector<Ray>& rays) {
  const BruteForce brute(g);
  int hits = 0;
  for (const Ray& r : rays) hits += closest(brute, r).found ? 1 : 0;
  return hits;
}

class RobustAccel : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<Accelerator> make(const Geometry& g) const { return make_accelerator(GetParam(), g); }

  // Single rays and groups on `g`, for the structure under test.
  void check_scene(const Geometry& g, const std::vector<Ray>& single, const Groups& groups,
                   const std::string& where) const {
    const auto accel = make(g);
    const BruteForce brute(g);
    // Structures may pad their bounds, never cut them.
    const Box3 b = accel->bounds(), gb = g.bounds();
    EXPECT_TRUE(g.size() == 0 || (b.contains(gb.lo) && b.contains(gb.hi))) << where;
    EXPECT_EQ(accel->info().primitive_count, g.size()) << where;
    const Exact exact(g, GetParam());
    {
      Failures failures(where + ", single rays");
      check_single_rays(*accel, g, single, brute_answers(brute, single), exact, failures);
    }
    {
      Failures failures(where + ", groups");
      const Expected want = brute_answers(brute, groups.rays);
      for (const auto& [first, n] : groups.ranges) check_group(*accel, g, groups.rays, want, first, n, exact, failures);
    }
  }

  // Groups of bad rays mixed with good ones on `g` (mixed_groups, 20 of each size), of which at
  // least a fifth hit, so that a wrong answer shows.
  void check_mixed_groups(const Geometry& g, Sampler& s, const std::string& where) const {
    const Groups groups = mixed_groups(g, s, 20);
    ASSERT_GT(brute_hits(g, groups.rays), int(groups.rays.size()) / 5);
    check_scene(g, {}, groups, where);
  }
};

// Every shape kind, so that each primitive test (triangles inline and in blocks, spheres, the
// others through Geometry) meets every bad ray.
TEST_P(RobustAccel, BadRaysAlone) {
  Sampler s(71);
  const Geometry g = every_shape_kind(s);
  std::vector<Ray> rays;
  const std::vector<Ray> good = random_rays(g, s, 48);
  for (const Ray& r : good) {
    rays.push_back(r);
    for (const Ray& bad : bad_variants(r)) rays.push_back(bad);
  }
  // Bad variants of rays that hit are the ones where a wrong answer shows.
  ASSERT_GT(brute_hits(g, good), 12);
  check_scene(g, rays, Groups{}, "every shape kind");
}

TEST_P(RobustAccel, BadRaysMixedWithGoodOnesInGroups) {
  Sampler s(72);
  const Geometry g = every_shape_kind(s);
  check_mixed_groups(g, s, "every shape kind");
}

// Triangles alone: the wide BVH's leaves then test them in SIMD blocks and ray-parallel across a
// packet (at least four rays sharing the watertight test's axes), paths other shapes skip.
TEST_P(RobustAccel, BadRaysInGroupsOnTrianglesOnly) {
  Sampler s(73);
  const Geometry g = dense_soup(s);
  check_mixed_groups(g, s, "dense triangle soup");
}

// tmin < 0 asks for hits behind the origin too: [tmin, tmax) is the whole contract, a promise
// wider than Embree's (its rays must start at tnear >= 0; raylab's Embree adapter answers such
// rays by brute force). Every structure keeps it: the slab tests widen a negative exit distance
// away from zero (widen_exit, src/accel/traversal_common.h), so a primitive lying in the exit face
// of a box behind the origin is not culled, which t * kSlabWiden alone did to about one ray in
// six on the closed meshes.
TEST_P(RobustAccel, NegativeTmin) {
  for (const NamedScene& scene : {kScenes[4], kScenes[5]}) {  // every shape kind, closed meshes
    Sampler s(scene.seed + 90);
    const Geometry g = scene.make(s);
    std::vector<Ray> rays = random_rays(g, s, 600);
    for (Ray& r : rays) r.tmin = s.rng.next_float() < 0.5f ? -INFINITY : -s.uni(0.f, 30.f);
    check_scene(g, rays, mixed_groups(g, s, 2), scene.name + std::string(", tmin < 0"));
  }
}

// A direction with an infinite component and finite others is no ray (traceable_direction):
// every distance along it rounds to t = +-0, behind the origin as well as ahead, so no answer
// means anything, and Embree takes such rays as invalid. Every structure misses them, in every
// query (closest, any, counted, packets mixed with good rays, all hits). The same rays with the
// infinite component made 1 pass through the scene (a control), so a structure that walked them
// to the primitive tests would find hits there.
TEST_P(RobustAccel, InfiniteDirectionComponents) {
  for (const NamedScene& scene : {kScenes[4], kScenes[5]}) {  // every shape kind, closed meshes
    Sampler s(scene.seed + 95);
    const Geometry g = scene.make(s);
    std::vector<Ray> rays = random_rays(g, s, 600), finite;
    for (Ray& r : rays) {
      const int axis = static_cast<int>(s.rng.next_u32() % 3);
      const bool negative = s.rng.next_float() < 0.5f;
      // Some along the axis alone.
      if (s.rng.next_u32() % 4 == 0) r.direction[(axis + 1) % 3] = r.direction[(axis + 2) % 3] = 0.f;
      r.direction[axis] = negative ? -1.f : 1.f;
      finite.push_back(r);
      r.direction[axis] = negative ? -INFINITY : INFINITY;
    }
    EXPECT_GT(brute_hits(g, finite), 50) << scene.name;
    EXPECT_EQ(brute_hits(g, rays), 0) << scene.name;
    // Groups of 1 to 17 in which they alternate with their finite controls.
    Groups groups;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      groups.rays.push_back(rays[i]);
      groups.rays.push_back(finite[i]);
    }
    for (std::size_t first = 0, n = 1; first + n <= groups.rays.size(); first += n, n = n % kMaxGroup + 1) {
      groups.ranges.emplace_back(first, n);
    }
    check_scene(g, rays, groups, scene.name + std::string(", infinite direction components"));
    const auto accel = make(g);
    std::vector<Hit> all;
    for (const Ray& r : rays) accel->all_hits(r, all);
    EXPECT_TRUE(all.empty()) << scene.name << ": all_hits found " << all.size() << " hits along rays that are no rays";
  }
}

// ---------------------------------------------------------------------------------------------
// Degenerate scenes

TEST_P(RobustAccel, EmptyScene) {
  const Geometry g;
  const auto accel = make(g);
  EXPECT_TRUE(accel->bounds().empty());
  Sampler s(80);
  std::vector<Ray> rays;
  for (const Ray& good : {Ray{Vec3(0.f), 0.f, {0.f, 0.f, 1.f}}, Ray{{1.f, 2.f, 3.f}, 0.f, {-1.f, 0.5f, 0.25f}}}) {
    rays.push_back(good);
    for (const Ray& bad : bad_variants(good)) rays.push_back(bad);
  }
  // Brute force over nothing misses everything, so this asserts that every query misses.
  check_scene(g, rays, mixed_groups(g, s, 3), "empty scene");
}

TEST_P(RobustAccel, OnePrimitive) {
  Geometry triangle, sphere;
  triangle.add(Triangle{{-1.f, -1.f, 2.f}, {1.f, -0.5f, 2.5f}, {0.f, 1.f, 3.f}}, 0);
  sphere.add(Sphere{{0.5f, -0.25f, 3.f}, 0.75f}, 0);
  for (const Geometry* g : {&triangle, &sphere}) {
    Sampler s(81);
    const std::vector<Ray> rays = rays_for(*g, s, 400);
    EXPECT_GT(brute_hits(*g, rays), 40);
    check_scene(*g, rays, mixed_groups(*g, s, 4), g == &triangle ? "one triangle" : "one sphere");
  }
}

// A thousand copies of one primitive: no split can separate them, so builders must stop on
// something else than leaf size, and every hit is an exact tie, which the lower-id rule gives to
// the first copy whatever order a structure visits them in (check_scene holds every structure but
// Embree to brute force's primitive). Each copy spans the whole scene, which makes the grid's
// build quadratic: about 3 s for the triangles and 1.5 s for the spheres, in Release.
TEST_P(RobustAccel, CoincidentPrimitives) {
  const Triangle tri{{-1.f, -1.f, 5.f}, {1.f, 0.f, 5.5f}, {0.f, 1.f, 4.5f}};
  const Sphere ball{{0.f, 0.f, 5.f}, 0.5f};
  Geometry triangles, spheres;
  for (int i = 0; i < 1000; ++i) {
    triangles.add(tri, 0);
    spheres.add(ball, 0);
  }
  const std::pair<const Geometry*, const char*> scenes[] = {{&triangles, "1000 coincident triangles"},
                                                            {&spheres, "1000 coincident spheres"}};
  for (const auto& [g, name] : scenes) {
    Sampler s(82);
    const std::vector<Ray> rays = rays_for(*g, s, 300);
    EXPECT_GT(brute_hits(*g, rays), 30) << name;
    check_scene(*g, rays, mixed_groups(*g, s, 2), name);
  }
}

// The scene with every coordinate multiplied by `scale`, and the rays made for it with their
// origins and intervals scaled (directions kept, so t scales too).
void scale_scene(const Geometry& g, const std::vector<Ray>& rays, float scale, Geometry& g_out,
                 std::vector<Ray>& rays_out) {
  for (const Triangle& t : g.triangles) g_out.add(Triangle{t.p0 * scale, t.p1 * scale, t.p2 * scale}, 0);
  for (const Sphere& sp : g.spheres) g_out.add(Sphere{sp.center * scale, sp.radius * scale}, 1);
  for (const Ray& r : rays) rays_out.push_back(Ray{r.origin * scale, r.tmin * scale, r.direction, r.tmax * scale});
}

// Triangles and spheres scaled to 1e-30 and 1e30: the structures' boxes, cells and slab
// distances then live near the ends of float's range. Float's shape tests do not reach that far
// (the triangle test's edge functions are products of two coordinates and its distance of three,
// the sphere test squares them: at 1e30 they overflow, at 1e-30 they vanish), so brute force
// finds next to nothing there, and the check is that no structure crashes or finds anything
// brute force does not. Scales of 1e-10 and 1e10, within the shape tests' reach, check that
// the structures still find what brute force finds.
TEST_P(RobustAccel, ScaledScenes) {
  for (const float scale : {1e-30f, 1e-10f, 1e10f, 1e30f}) {
    Sampler s(83);
    Geometry unit;
    for (int i = 0; i < 150; ++i) unit.add(random_triangle(s, s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.3f, 3.f)), 0);
    for (int i = 0; i < 100; ++i) unit.add(Sphere{s.in_box(Vec3(-10.f), Vec3(10.f)), s.uni(0.2f, 2.f)}, 1);
    Geometry g;
    std::vector<Ray> rays;
    scale_scene(unit, random_rays(unit, s, 800), scale, g, rays);
    const std::size_t good = rays.size();
    // Within the shape tests' reach, a quarter of the rays must hit for the comparison to mean much.
    const bool reached = scale > 1e-20f && scale < 1e20f;
    EXPECT_TRUE(!reached || brute_hits(g, rays) > int(good) / 4) << scale;
    for (std::size_t i = 0; i < good; i += 8) rays.push_back(random_bad_variant(rays[i], s));
    std::ostringstream where;
    where << "scaled by " << scale;
    check_scene(g, rays, mixed_groups(g, s, 4), where.str());
  }
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) { return info.param; }

INSTANTIATE_TEST_SUITE_P(Robust, RobustAccel, ::testing::ValuesIn(factory_names()), param_name);

}  // namespace
}  // namespace raylab
