#include "raylab/accel/embree_accel.h"

#include "embree_backend.h"

#include "raylab/accel/brute_force.h"
#include "raylab/core/error.h"
#include "raylab/core/stopwatch.h"

#if defined(RAYLAB_HAVE_EMBREE)
#include <embree3/rtcore.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>
#endif

// Embree 3 behind the Accelerator interface, as the reference tracer of `raylab compare`.
//
// - Triangles are one RTC_GEOMETRY_TYPE_TRIANGLE (vertex order p0, p1, p2, so Embree's u, v are
//   the weights of p1 and p2, exactly our convention); every other primitive, groups included, is
//   one RTC_GEOMETRY_TYPE_USER whose callbacks call Geometry::intersect / occluded.
// - The scene is built with RTC_BUILD_QUALITY_MEDIUM and RTC_SCENE_FLAG_ROBUST. Robust mode makes
//   Embree's triangle test watertight like ours: without it a ray can slip through an edge shared
//   by two triangles, which `compare` would report as a disagreement (1 of 120,000 primary rays on
//   armadillo.off). Measured cost, one thread, primary rays of 400x300 (median of 11 interleaved
//   runs on a loaded machine, so +-10%): bunny 10.05 -> 8.79 Mrays/s, spd:gears 2.97 -> 2.65,
//   armadillo 10.65 -> 9.28, i.e. about 12% for a reference whose answers we trust.
// - Our intervals are [tmin, tmax), and a hit's distance is what our own shape test computes.
//   Embree's triangle distances are not exact and differ by kernel: its robust AVX2 kernel (on an
//   AMD EPYC) puts a triangle lying at z = 2 at t = 2 - 1 ulp for a ray from the origin along z,
//   so at tnear = 2 it misses a hit our test places exactly at 2 (its AVX-512 kernel on a Xeon
//   did not). So Embree searches a slightly wider interval (tnear a little below tmin, tfar a
//   little above tmax), a filter on the triangles keeps a candidate only when our exact test hits
//   that triangle within [tmin, tmax), and the hit returned carries our test's t, u and v. The
//   user callbacks are given the real tmin and tmax through the query context.
// - Edges: both tests are watertight, but they may give a shared edge to different triangles.
//   Where Embree offers the one our test misses, our neighbour may never be offered, and the hit
//   would be lost; the filter notices (our test misses that candidate at every distance) and the
//   query is answered by brute force. Seen on random closed meshes with far origins; rare.
// - Ties: Embree resolves equal distances between its own primitives in traversal order, not by
//   our lower-id rule; the user callbacks do apply the rule against the closest hit so far.
// - Rays Embree cannot take (NaN, infinite or huge components beyond its 1.844e18, tmin < 0) are
//   answered by brute force over the same primitives (embree_traces).
// - Counting: Embree exposes no traversal counts, so intersect_counted / occluded_counted count
//   hits only and leave nodes_visited and prim_tests at 0 (compare shows "n/a").

namespace raylab {

#if defined(RAYLAB_HAVE_EMBREE)
namespace {

// ---------------------------------------------------------------------------------------------
// The device: one per process, shared by every Embree accelerator.

// Net bytes Embree holds on the shared device (its memory monitor reports frees as negative).
std::atomic<long long> g_device_bytes{0};
// Serialises builds and releases, so that the change of g_device_bytes across a build is the
// memory of that build's scene alone.
std::mutex g_build_mutex;
// The first error Embree reported since the last check (guarded by g_error_mutex).
std::mutex g_error_mutex;
std::string g_error;

bool count_bytes(void*, ssize_t bytes, bool) {
  g_device_bytes.fetch_add(static_cast<long long>(bytes), std::memory_order_relaxed);
  return true;  // never refuse an allocation
}

void record_error(void*, RTCError code, const char* what) {
  const std::lock_guard lock(g_error_mutex);
  if (g_error.empty()) g_error = std::string(what ? what : "unknown error") + " (code " + std::to_string(code) + ")";
}

// Throws the recorded error, if any, and clears it.
void throw_if_error(RTCDevice device) {
  const RTCError code = rtcGetDeviceError(device);
  const std::lock_guard lock(g_error_mutex);
  if (code == RTC_ERROR_NONE && g_error.empty()) return;
  const std::string message = g_error.empty() ? "error code " + std::to_string(code) : g_error;
  g_error.clear();
  throw std::runtime_error("embree: " + message);
}

// The device of the process, created on first use. Each accelerator also retains it, so that it
// outlives them whatever the order of destruction at exit.
RTCDevice shared_device() {
  struct Holder {
    RTCDevice device = rtcNewDevice(nullptr);
    Holder() {
      if (!device) throw std::runtime_error("embree: rtcNewDevice failed");
      rtcSetDeviceErrorFunction(device, record_error, nullptr);
      rtcSetDeviceMemoryMonitorFunction(device, count_bytes, nullptr);
    }
    ~Holder() { rtcReleaseDevice(device); }
  };
  static const Holder holder;  // thread-safe initialisation
  return holder.device;
}

// ---------------------------------------------------------------------------------------------
// What the callbacks need.

// The primitives of one scene and how Embree's (geomID, primID) maps back to global ids.
struct SceneIds {
  const Geometry* geometry = nullptr;
  std::vector<std::uint32_t> triangles;  ///< Embree primID of the triangle geometry -> global id
  std::vector<std::uint32_t> others;     ///< user primID -> global id (or group id)
  unsigned triangle_geom = RTC_INVALID_GEOMETRY_ID;

  // Global id of Embree's hit. User hits store the global id itself in primID (a group answers
  // with the id of the primitive inside it, which no local index could name).
  std::uint32_t global_id(unsigned geom, unsigned prim) const { return geom == triangle_geom ? triangles[prim] : prim; }
};

// Per query: Embree hands the context pointer to the callbacks; the first member is Embree's own.
struct QueryContext {
  RTCIntersectContext embree;
  float tmin;                 ///< the caller's tmin (Embree sees a float a little below it)
  float tmax;                 ///< the caller's tmax (Embree sees the float below it)
  std::uint32_t incoming_id;  ///< the caller's closest hit so far, kInvalidId if none
  /// Set by the filter when Embree offered a triangle our test misses at every distance: then
  /// a neighbour across a shared edge may be the one our test hits, which Embree need not offer.
  mutable bool disagreed = false;
};
static_assert(std::is_standard_layout_v<QueryContext>, "the context is recovered from its first member");

const QueryContext& query_of(const RTCIntersectContext* context) {
  return *reinterpret_cast<const QueryContext*>(context);
}

Ray ray_of(RTCRayN* ray, unsigned n) {
  Ray r;
  r.origin = {RTCRayN_org_x(ray, n, 0), RTCRayN_org_y(ray, n, 0), RTCRayN_org_z(ray, n, 0)};
  r.direction = {RTCRayN_dir_x(ray, n, 0), RTCRayN_dir_y(ray, n, 0), RTCRayN_dir_z(ray, n, 0)};
  r.tmin = RTCRayN_tnear(ray, n, 0);
  r.tmax = RTCRayN_tfar(ray, n, 0);
  return r;
}

void user_bounds(const RTCBoundsFunctionArguments* args) {
  const auto& ids = *static_cast<const SceneIds*>(args->geometryUserPtr);
  Box3 b = ids.geometry->bounds(ids.others[args->primID]);
  // Widened by ~8 ulps: a float box can be narrower than its shape (a sphere of radius 1e-4 at
  // 1e4 gets lo == hi), and Embree's traversal does not forgive that as ours does.
  for (int k = 0; k < 3; ++k) {
    const float pad = 1e-6f * std::max(std::fabs(b.lo[k]), std::fabs(b.hi[k]));
    if (!std::isfinite(pad)) continue;  // an empty box stays empty
    b.lo[k] -= pad;
    b.hi[k] += pad;
  }
  RTCBounds& out = *args->bounds_o;
  out.lower_x = b.lo.x, out.lower_y = b.lo.y, out.lower_z = b.lo.z;
  out.upper_x = b.hi.x, out.upper_y = b.hi.y, out.upper_z = b.hi.z;
}

void user_intersect(const RTCIntersectFunctionNArguments* args) {
  if (args->valid[0] == 0) return;  // rtcIntersect1 only: N is 1
  const auto& ids = *static_cast<const SceneIds*>(args->geometryUserPtr);
  const QueryContext& query = query_of(args->context);
  RTCRayN* rn = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hn = RTCRayHitN_HitN(args->rayhit, args->N);
  Ray ray = ray_of(rn, args->N);
  // The closest hit so far: Embree's, else the caller's (then at the caller's real tmax).
  Hit current;
  const unsigned geom = RTCHitN_geomID(hn, args->N, 0);
  if (geom != RTC_INVALID_GEOMETRY_ID) {
    current.t = ray.tmax;
    current.prim_id = ids.global_id(geom, RTCHitN_primID(hn, args->N, 0));
  } else {
    ray.tmax = query.tmax;
    current.t = query.tmax;
    current.prim_id = query.incoming_id;
  }
  ray.tmin = query.tmin;
  if (!ids.geometry->intersect(ids.others[args->primID], WatertightRay(ray), ray, current)) return;
  RTCRayN_tfar(rn, args->N, 0) = current.t;
  RTCHitN_u(hn, args->N, 0) = current.u;
  RTCHitN_v(hn, args->N, 0) = current.v;
  RTCHitN_Ng_x(hn, args->N, 0) = RTCHitN_Ng_y(hn, args->N, 0) = RTCHitN_Ng_z(hn, args->N, 0) = 0.f;
  RTCHitN_primID(hn, args->N, 0) = current.prim_id;
  RTCHitN_geomID(hn, args->N, 0) = args->geomID;
  RTCHitN_instID(hn, args->N, 0, 0) = args->context->instID[0];
}

void user_occluded(const RTCOccludedFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  const auto& ids = *static_cast<const SceneIds*>(args->geometryUserPtr);
  Ray ray = ray_of(args->ray, args->N);
  ray.tmin = query_of(args->context).tmin;
  ray.tmax = query_of(args->context).tmax;
  if (ids.geometry->occluded(ids.others[args->primID], WatertightRay(ray), ray)) {
    RTCRayN_tfar(args->ray, args->N, 0) = -std::numeric_limits<float>::infinity();  // Embree's "occluded"
  }
}

// Our own test of triangle `id` against `ray` (origin and direction) within [tmin, tmax).
bool exact_triangle_hit(const SceneIds& ids, std::uint32_t id, const Ray& ray, float tmin, float tmax, Hit& hit) {
  float t, u, v;
  if (!intersect_triangle(ids.geometry->triangles[id], WatertightRay(ray), tmin, tmax, t, u, v)) return false;
  hit = {t, id, u, v};
  return true;
}

// Keeps Embree's candidate triangle hits that our exact test confirms within the caller's
// [tmin, tmax). A candidate our test misses at every distance is a disagreement about which
// side of an edge the ray passes (Embree's robust test and our tie rule can give a shared edge
// to different triangles, seen with far origins): the query is marked, and answered again by
// brute force, because the neighbour our test would hit may never be offered.
void keep_exact_hits(const RTCFilterFunctionNArguments* args) {
  const auto& ids = *static_cast<const SceneIds*>(args->geometryUserPtr);
  const QueryContext& query = query_of(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const Ray ray = ray_of(args->ray, args->N);
    const std::uint32_t id = ids.triangles[RTCHitN_primID(args->hit, args->N, i)];
    Hit hit;
    if (exact_triangle_hit(ids, id, ray, query.tmin, query.tmax, hit)) continue;
    args->valid[i] = 0;
    constexpr float kInf = std::numeric_limits<float>::infinity();
    if (!exact_triangle_hit(ids, id, ray, -kInf, kInf, hit)) query.disagreed = true;
  }
}

// Embree's interval for the caller's [tmin, tmax): wider by a margin that covers its distances'
// rounding (keep_exact_hits decides at the ends); tnear never negative (Embree asserts it).
float embree_tnear(float tmin) { return std::max(0.f, tmin - std::fabs(tmin) * 0x1p-20f); }
float embree_tfar(float tmax) { return tmax + std::fabs(tmax) * 0x1p-20f; }

// Whether Embree can trace `r`. Its traversal asserts (RayK::valid) origin and direction
// components within +-1.844e18 (its FLT_LARGE) and limits that are not NaN, and its interval is
// [0, inf]: a NaN, infinite or huge component aborted the process in Debian's Embree, which is
// built with assertions, and tmin < 0 was clamped to 0. Such rays are answered by brute force
// over the same primitives instead: rare, and then exactly as every other structure answers.
bool embree_traces(const Ray& r) {
  constexpr float kLarge = 1.844e18f;
  auto within = [](Vec3 v) { return std::fabs(v.x) <= kLarge && std::fabs(v.y) <= kLarge && std::fabs(v.z) <= kLarge; };
  return within(r.origin) && within(r.direction) && r.tmin >= 0.f && r.tmax >= r.tmin;  // false for NaN
}

RTCRay embree_ray(const Ray& r) {
  RTCRay e{};
  e.org_x = r.origin.x, e.org_y = r.origin.y, e.org_z = r.origin.z;
  e.dir_x = r.direction.x, e.dir_y = r.direction.y, e.dir_z = r.direction.z;
  e.tnear = std::isfinite(r.tmin) ? embree_tnear(r.tmin) : r.tmin;
  e.tfar = embree_tfar(r.tmax);
  e.mask = ~0u;
  return e;
}

// ---------------------------------------------------------------------------------------------
// The accelerator.

class EmbreeAccel final : public Accelerator {
 public:
  EmbreeAccel(const Geometry& geometry, std::span<const std::uint32_t> ids);
  ~EmbreeAccel() override;
  EmbreeAccel(const EmbreeAccel&) = delete;
  EmbreeAccel& operator=(const EmbreeAccel&) = delete;

  Box3 bounds() const override { return m_bounds; }
  bool intersect(Ray& ray, Hit& hit) const override;
  bool occluded(const Ray& ray) const override;
  bool intersect_counted(Ray& ray, Hit& hit, TraversalStats& stats) const override {
    const bool found = intersect(ray, hit);
    stats.hits += found ? 1 : 0;
    return found;
  }
  bool occluded_counted(const Ray& ray, TraversalStats& stats) const override {
    const bool found = occluded(ray);
    stats.hits += found ? 1 : 0;
    return found;
  }
  using Accelerator::intersect;
  using Accelerator::occluded;
  AccelInfo info() const override;

 private:
  void build();

  SceneIds m_ids;            // the callbacks point here: the object must not move (it is never copied)
  BruteForce m_untraceable;  // answers the rays Embree cannot take (embree_traces)
  RTCDevice m_device = nullptr;
  RTCScene m_scene = nullptr;
  Box3 m_bounds;
  double m_build_seconds = 0.0;
  long long m_embree_bytes = 0;
};

EmbreeAccel::EmbreeAccel(const Geometry& geometry, std::span<const std::uint32_t> ids) : m_untraceable(geometry, ids) {
  const auto start = std::chrono::steady_clock::now();
  m_ids.geometry = &geometry;
  for (std::uint32_t id : ids) {
    m_bounds.extend(geometry.bounds(id));
    const bool triangle = id < kGroupIdBase && geometry.resolve(id).kind == ShapeKind::kTriangle;
    (triangle ? m_ids.triangles : m_ids.others).push_back(id);
  }
  m_device = shared_device();
  rtcRetainDevice(m_device);
  {
    const std::lock_guard lock(g_build_mutex);
    const long long before = g_device_bytes.load();
    try {
      build();
    } catch (...) {
      if (m_scene) rtcReleaseScene(m_scene);
      rtcReleaseDevice(m_device);
      throw;
    }
    m_embree_bytes = g_device_bytes.load() - before;
  }
  m_build_seconds = seconds_since(start);
}

void EmbreeAccel::build() {
  m_scene = rtcNewScene(m_device);
  rtcSetSceneFlags(m_scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_MEDIUM);
  const Geometry& g = *m_ids.geometry;
  if (!m_ids.triangles.empty()) {
    const std::size_t n = m_ids.triangles.size();
    RTCGeometry geom = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_MEDIUM);
    // Embree-owned buffers (padded for its 16-byte vertex loads): three vertices per triangle.
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
    if (!vertices || !indices) {
      rtcReleaseGeometry(geom);
      throw_if_error(m_device);
      throw std::runtime_error("embree: cannot allocate the triangle buffers");
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Triangle& t = g.triangles[m_ids.triangles[i]];
      const Vec3 p[3] = {t.p0, t.p1, t.p2};
      for (int k = 0; k < 3; ++k) {
        vertices[9 * i + 3 * k] = p[k].x, vertices[9 * i + 3 * k + 1] = p[k].y, vertices[9 * i + 3 * k + 2] = p[k].z;
        indices[3 * i + k] = static_cast<unsigned>(3 * i + k);
      }
    }
    rtcSetGeometryUserData(geom, &m_ids);
    rtcSetGeometryIntersectFilterFunction(geom, keep_exact_hits);
    rtcSetGeometryOccludedFilterFunction(geom, keep_exact_hits);
    rtcCommitGeometry(geom);
    m_ids.triangle_geom = rtcAttachGeometry(m_scene, geom);
    rtcReleaseGeometry(geom);
  }
  if (!m_ids.others.empty()) {
    RTCGeometry geom = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(m_ids.others.size()));
    rtcSetGeometryUserData(geom, &m_ids);
    rtcSetGeometryBoundsFunction(geom, user_bounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, user_intersect);
    rtcSetGeometryOccludedFunction(geom, user_occluded);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(m_scene, geom);
    rtcReleaseGeometry(geom);
  }
  // Isolated: a thread waiting inside Embree's parallel build must not pick up an outer task that
  // could start another build and block on g_build_mutex, which this thread holds.
  tbb::this_task_arena::isolate([&] { rtcCommitScene(m_scene); });
  throw_if_error(m_device);
}

EmbreeAccel::~EmbreeAccel() {
  {
    const std::lock_guard lock(g_build_mutex);  // keeps the byte count of a concurrent build clean
    rtcReleaseScene(m_scene);
  }
  rtcReleaseDevice(m_device);
}

bool EmbreeAccel::intersect(Ray& ray, Hit& hit) const {
  if (!embree_traces(ray)) return m_untraceable.intersect(ray, hit);
  QueryContext query;
  rtcInitIntersectContext(&query.embree);
  query.tmin = ray.tmin;
  query.tmax = ray.tmax;
  query.incoming_id = hit.prim_id;
  RTCRayHit rh;
  rh.ray = embree_ray(ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(m_scene, &query.embree, &rh);
  if (query.disagreed) return m_untraceable.intersect(ray, hit);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  if (rh.hit.geomID == m_ids.triangle_geom) {
    // The distance and barycentrics of our own test (which the filter has confirmed).
    if (!exact_triangle_hit(m_ids, m_ids.triangles[rh.hit.primID], ray, ray.tmin, ray.tmax, hit)) return false;
  } else {
    hit.t = rh.ray.tfar;
    hit.prim_id = m_ids.global_id(rh.hit.geomID, rh.hit.primID);
    hit.u = rh.hit.u;
    hit.v = rh.hit.v;
  }
  ray.tmax = hit.t;
  return true;
}

bool EmbreeAccel::occluded(const Ray& ray) const {
  if (!embree_traces(ray)) return m_untraceable.occluded(ray);
  QueryContext query;
  rtcInitIntersectContext(&query.embree);
  query.tmin = ray.tmin;
  query.tmax = ray.tmax;
  query.incoming_id = kInvalidId;
  RTCRay r = embree_ray(ray);
  rtcOccluded1(m_scene, &query.embree, &r);
  if (r.tfar == -std::numeric_limits<float>::infinity()) return true;
  return query.disagreed ? m_untraceable.occluded(ray) : false;
}

AccelInfo EmbreeAccel::info() const {
  AccelInfo info;
  info.name = "embree";
  info.build_seconds = m_build_seconds;
  // What Embree allocated for the scene (BVH, buffers) plus the id maps kept here (the fallback's too).
  info.memory_bytes = static_cast<std::size_t>(std::max(0ll, m_embree_bytes)) + sizeof(*this) +
                      (m_ids.triangles.capacity() + m_ids.others.capacity()) * sizeof(std::uint32_t) +
                      m_untraceable.info().memory_bytes - sizeof(BruteForce);
  info.primitive_count = m_ids.triangles.size() + m_ids.others.size();
  return info;
}

}  // namespace

std::unique_ptr<Accelerator> make_embree_accelerator_here(const Geometry& geometry,
                                                          std::span<const std::uint32_t> ids) {
  return std::make_unique<EmbreeAccel>(geometry, ids);
}

#endif

}  // namespace raylab
