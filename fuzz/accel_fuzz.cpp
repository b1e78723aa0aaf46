// libFuzzer target: every acceleration structure must answer every query as brute force does, on
// scenes and rays made from arbitrary bytes. The parsers' targets look for crashes on bad input;
// this one is differential: a structure that loses a primitive in its cells or boxes, walks a
// ray into the wrong cell, hangs in a build, or reads outside its arrays stops the fuzzer, with
// the scene and the ray in the crash input.
//
// The bytes make a scene of up to kMaxPrimitives triangles and spheres (degenerate, coincident,
// touching and nested ones included, since the fuzzer repeats and zeroes bytes freely) at a
// common scale from 2^-24 to 2^8 per lattice step, and up to kMaxRays rays (zero and negative
// zero direction components included). Every structure is built over it and compared with brute
// force under the rule of tests/accel/accel_compare_util.h, its t tolerance widened by the
// scene's scale (see near()): the same hit or miss, the same t within
// a relative 1e-5, another primitive only where it ties, and any-hit queries that agree.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string_view>
#include <vector>

#include "raylab/accel/brute_force.h"
#include "raylab/accel/factory.h"
#include "raylab/geometry/geometry.h"

namespace {

using namespace raylab;

constexpr std::size_t kMaxPrimitives = 48;
constexpr std::size_t kMaxRays = 32;
constexpr float kRelTol = 1e-5f;
constexpr float kScaleUlps = 4.f;

/// Reads the input front to back; past the end it yields zeros, so every input makes a scene.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}
  bool empty() const { return m_at >= m_size; }
  std::uint8_t byte() { return m_at < m_size ? m_data[m_at++] : 0; }
  std::int16_t int16() {
    const auto lo = byte();
    return static_cast<std::int16_t>(std::uint16_t(lo) | std::uint16_t(byte()) << 8);
  }

 private:
  const std::uint8_t* m_data;
  std::size_t m_size;
  std::size_t m_at = 0;
};

/// A coordinate on the scene's lattice: an int16 times the step, exact in float. A zero is -0
/// where `negative_zero` says so, so that directions can carry either zero.
float lattice(std::int16_t q, float step, bool negative_zero = false) {
  if (q == 0) return negative_zero ? -0.f : 0.f;
  return float(q) * step;
}

Vec3 lattice_point(ByteReader& in, float step) {
  const float x = lattice(in.int16(), step), y = lattice(in.int16(), step);
  return {x, y, lattice(in.int16(), step)};
}

[[noreturn]] void fail(std::string_view accel, std::string_view what, const Ray& ray) {
  std::fprintf(stderr, "accel_fuzz: %.*s: %.*s for ray o=(%.9g, %.9g, %.9g) d=(%.9g, %.9g, %.9g) [%.9g, %.9g)\n",
               int(accel.size()), accel.data(), int(what.size()), what.data(), ray.origin.x, ray.origin.y, ray.origin.z,
               ray.direction.x, ray.direction.y, ray.direction.z, ray.tmin, ray.tmax);
  std::abort();
}

/// Whether `a` and `b`, two distances along `ray` in a scene whose coordinates reach `scale`,
/// agree: within a relative kRelTol, or within kScaleUlps float steps of the scene's coordinates
/// (divided by the direction's length, to be a distance in t). The second bound is for triangles
/// much larger than the distance to their hit: the watertight test's t is a quotient of products
/// of the vertices, so its error follows their magnitude, not the hit's (a fuzz input found a
/// 60,000-unit triangle hit at t = 1/64 whose t was off by 5e-5 relative, while the BVH's box
/// test gave the exact 1/64 and so a neighbour 1e-6 closer).
bool near(float a, float b, const Ray& ray, float scale) {
  const float rel = kRelTol * std::max(std::fabs(a), std::fabs(b));
  const float abs = kScaleUlps * std::numeric_limits<float>::epsilon() * scale / length(ray.direction);
  return std::fabs(a - b) <= std::max(rel, abs);
}

/// Whether primitive `id`, tested alone, hits `ray` at about `t`: the tie that allows a structure
/// to answer with another primitive than brute force.
bool ties(const Geometry& g, std::uint32_t id, const Ray& ray, float t, float scale) {
  Ray alone = ray;
  Hit h;
  return g.intersect(id, WatertightRay(alone), alone, h) && near(h.t, t, ray, scale);
}

/// Compares one structure with brute force on one ray; aborts on a disagreement.
void check_ray(std::string_view name, const Accelerator& accel, const Accelerator& brute, const Geometry& g,
               const Ray& ray, float scale) {
  Ray rb = ray, rv = ray;
  Hit hb, hv;
  const bool fb = brute.intersect(rb, hb), fv = accel.intersect(rv, hv);
  if (fb != fv) fail(name, fb ? "missed a hit" : "found a phantom hit", ray);
  if (fb) {
    if (!near(hb.t, hv.t, ray, scale)) fail(name, "t differs from brute force", ray);
    if (hb.prim_id != hv.prim_id && !ties(g, hv.prim_id, ray, hb.t, scale))
      fail(name, "another primitive, no tie", ray);
  }
  // Any-hit: the whole ray, the stretch before half the hit (nothing there) and up to twice it.
  if (accel.occluded(ray) != fb) fail(name, "occluded disagrees with the closest hit", ray);
  if (fb && hb.t > 0.f) {
    Ray before = ray, through = ray;
    before.tmax = 0.5f * hb.t;
    through.tmax = 2.f * hb.t;
    if (before.tmax > ray.tmin && accel.occluded(before)) fail(name, "occluded before the closest hit", before);
    if (!accel.occluded(through)) fail(name, "not occluded through the closest hit", through);
  }
}

}  // namespace

/// Builds a scene and rays from `data`, every structure over the scene, and compares them all with
/// brute force; returns libFuzzer's 0 or aborts on a disagreement.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  const std::size_t primitives = 1 + in.byte() % kMaxPrimitives;
  const float step = std::ldexp(1.f, int(in.byte() % 33) - 24);
  Geometry g;
  for (std::size_t i = 0; i < primitives; ++i) {
    if (in.byte() % 4 == 3) {
      const Vec3 c = lattice_point(in, step);
      const float radius = float(1 + (std::uint16_t(in.int16()) & 0x7fff)) * step;
      g.add(Sphere{c, radius}, 0);
    } else {
      const Vec3 p0 = lattice_point(in, step), p1 = lattice_point(in, step);
      g.add(Triangle{p0, p1, lattice_point(in, step)}, 0);
    }
  }
  std::vector<Ray> rays;
  while (!in.empty() && rays.size() < kMaxRays) {
    const std::uint8_t signs = in.byte();
    const Vec3 o = lattice_point(in, step);
    Vec3 d;
    for (int a = 0; a < 3; ++a) d[a] = lattice(in.int16(), 1.f, (signs >> a) & 1);
    if (d.x == 0.f && d.y == 0.f && d.z == 0.f) continue;
    rays.push_back(Ray{o, 0.f, d});
  }
  const BruteForce brute(g);
  const Box3 bounds = g.bounds();
  const float scene_scale = std::max(max_component(abs(bounds.lo)), max_component(abs(bounds.hi)));
  for (const std::string_view name : accelerator_names()) {
    if (name == "brute" || name == "embree") continue;  // the reference; Embree has its own rules
    const std::unique_ptr<Accelerator> accel = make_accelerator(name, g);
    for (const Ray& ray : rays) {
      check_ray(name, *accel, brute, g, ray, std::max(scene_scale, max_component(abs(ray.origin))));
    }
  }
  return 0;
}
