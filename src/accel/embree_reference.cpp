#include "raylab/accel/embree_reference.h"
#include "embree_backend.h"

#include "raylab/core/error.h"
#include "raylab/core/float_neighbour.h"
#include "raylab/core/stopwatch.h"

#if defined(RAYLAB_HAVE_EMBREE)
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>
#endif

namespace raylab {

#if defined(RAYLAB_HAVE_EMBREE)
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr unsigned kTriangleGeom = 0;  // geometry ids, fixed so that a hit maps back without a table
constexpr unsigned kUserGeom = 1;

// Embree's memory monitor: a running net sum (frees arrive as negative sizes). Atomic because
// Embree builds in parallel.
bool count_bytes(void* sum, ssize_t bytes, bool) {
  static_cast<std::atomic<long long>*>(sum)->fetch_add(static_cast<long long>(bytes), std::memory_order_relaxed);
  return true;  // never refuse an allocation
}

void throw_if_error(RTCDevice device, const char* what) {
  const RTCError code = rtcGetDeviceError(device);
  if (code != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("embree: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(code)) + ")");
}

// What the user-geometry callbacks need: our shapes, and the global id of user primitive 0.
struct UserShapes {
  const Geometry* geometry = nullptr;
  std::uint32_t first_id = 0;
};

Ray lane_ray(RTCRayN* ray, unsigned n, unsigned i) {
  Ray r;
  r.origin = {RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i)};
  r.direction = {RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)};
  r.tmin = RTCRayN_tnear(ray, n, i);
  r.tmax = RTCRayN_tfar(ray, n, i);
  return r;
}

void user_bounds(const RTCBoundsFunctionArguments* args) {
  const auto& shapes = *static_cast<const UserShapes*>(args->geometryUserPtr);
  const Box3 b = shapes.geometry->bounds(shapes.first_id + args->primID);
  RTCBounds& out = *args->bounds_o;
  out.lower_x = b.lo.x, out.lower_y = b.lo.y, out.lower_z = b.lo.z;
  out.upper_x = b.hi.x, out.upper_y = b.hi.y, out.upper_z = b.hi.z;
}

// Called with 1 lane by rtcIntersect1 and up to 16 by rtcIntersect16: every valid lane is tested.
void user_intersect(const RTCIntersectFunctionNArguments* args) {
  const auto& shapes = *static_cast<const UserShapes*>(args->geometryUserPtr);
  const std::uint32_t id = shapes.first_id + args->primID;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    Ray r = lane_ray(rays, args->N, i);
    Hit h;
    if (!shapes.geometry->intersect(id, WatertightRay(r), r, h)) continue;
    RTCRayN_tfar(rays, args->N, i) = h.t;
    RTCHitN_u(hits, args->N, i) = h.u;
    RTCHitN_v(hits, args->N, i) = h.v;
    RTCHitN_Ng_x(hits, args->N, i) = RTCHitN_Ng_y(hits, args->N, i) = RTCHitN_Ng_z(hits, args->N, i) = 0.f;
    RTCHitN_primID(hits, args->N, i) = args->primID;
    RTCHitN_geomID(hits, args->N, i) = args->geomID;
    RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
  }
}

void user_occluded(const RTCOccludedFunctionNArguments* args) {
  const auto& shapes = *static_cast<const UserShapes*>(args->geometryUserPtr);
  const std::uint32_t id = shapes.first_id + args->primID;
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const Ray r = lane_ray(args->ray, args->N, i);
    if (shapes.geometry->occluded(id, WatertightRay(r), r)) RTCRayN_tfar(args->ray, args->N, i) = -kInf;
  }
}

// Embree's intervals are closed, ours [tmin, tmax): Embree gets the float below tmax.
float embree_tfar(float tmax) { return next_float_down(tmax); }

RTCRay embree_ray(const Ray& r) {
  RTCRay e{};  // time, id and flags 0
  e.org_x = r.origin.x, e.org_y = r.origin.y, e.org_z = r.origin.z, e.tnear = r.tmin;
  e.dir_x = r.direction.x, e.dir_y = r.direction.y, e.dir_z = r.direction.z, e.tfar = embree_tfar(r.tmax);
  e.mask = ~0u;
  return e;
}

// One node of Embree's binary tree as the builder's callbacks hand it over (allocated by Embree's
// thread-local allocator, freed with the RTCBVH).
struct BuildNode {
  unsigned count = 0;  // primitives of a leaf; 0 for an interior node
  BuildNode* child[2] = {nullptr, nullptr};
  RTCBounds box[2] = {};
};

void* create_node(RTCThreadLocalAllocator alloc, unsigned children, void*) {
  if (children != 2) return nullptr;  // a binary build was asked for
  return new (rtcThreadLocalAlloc(alloc, sizeof(BuildNode), alignof(BuildNode))) BuildNode{};
}
void set_children(void* node, void** children, unsigned n, void*) {
  for (unsigned i = 0; i < n && i < 2; ++i)
    static_cast<BuildNode*>(node)->child[i] = static_cast<BuildNode*>(children[i]);
}
void set_bounds(void* node, const RTCBounds** bounds, unsigned n, void*) {
  for (unsigned i = 0; i < n && i < 2; ++i) static_cast<BuildNode*>(node)->box[i] = *bounds[i];
}
void* create_leaf(RTCThreadLocalAllocator alloc, const RTCBuildPrimitive*, size_t count, void*) {
  auto* leaf = new (rtcThreadLocalAlloc(alloc, sizeof(BuildNode), alignof(BuildNode))) BuildNode{};
  leaf->count = static_cast<unsigned>(std::max<size_t>(count, 1));
  return leaf;
}

BvhNode flat_node(const RTCBounds& b, unsigned count) {
  BvhNode n{};
  n.lo[0] = b.lower_x, n.lo[1] = b.lower_y, n.lo[2] = b.lower_z;
  n.hi[0] = b.upper_x, n.hi[1] = b.upper_y, n.hi[2] = b.upper_z;
  n.count = count;
  return n;
}

RTCBounds merged(const RTCBounds& a, const RTCBounds& b) {
  RTCBounds m = a;
  m.lower_x = std::min(a.lower_x, b.lower_x), m.lower_y = std::min(a.lower_y, b.lower_y);
  m.lower_z = std::min(a.lower_z, b.lower_z), m.upper_x = std::max(a.upper_x, b.upper_x);
  m.upper_y = std::max(a.upper_y, b.upper_y), m.upper_z = std::max(a.upper_z, b.upper_z);
  return m;
}

}  // namespace

// EmbreeReference's work, in the module (embree_backend.h).
class EmbreeRun final : public EmbreeReferenceBackend {
 public:
  EmbreeRun(const Geometry& geometry, const std::string& isa);
  ~EmbreeRun() override;
  double rebuild() override;
  std::size_t scene_bytes() const override;
  std::size_t user_primitive_count() const override;
  void build_robust() override;
  void intersect1(std::span<const Ray> rays, std::span<Hit> hits, bool robust) const override;
  void occluded1(std::span<const Ray> rays, std::span<std::uint8_t> occluded, bool robust) const override;
  void prepare(std::span<const Ray> rays, bool packets) override;
  void reset_prepared(std::size_t begin, std::size_t end) const override;
  void intersect1_prepared(std::size_t begin, std::size_t end) const override;
  void occluded1_prepared(std::size_t begin, std::size_t end) const override;
  void intersect16_prepared(std::size_t begin, std::size_t end) const override;
  void occluded16_prepared(std::size_t begin, std::size_t end) const override;
  void prepared_hits(std::span<Hit> hits) const override;
  void prepared_occluded(std::span<std::uint8_t> occluded) const override;
  void intersect16(std::span<const Ray> rays, std::span<Hit> hits) const override;
  void occluded16(std::span<const Ray> rays, std::span<std::uint8_t> occluded) const override;
  double binary_sah_cost(const BvhConfig& config) const override;

 private:
  struct State;
  std::unique_ptr<State> m;
};

struct EmbreeRun::State {
  const Geometry* geometry = nullptr;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  RTCScene robust = nullptr;
  std::atomic<long long> allocated{0};
  long long scene_bytes = 0;
  std::vector<Triangle> vertices;  // the triangles plus one spare: Embree loads each vertex as 16 bytes
  std::vector<unsigned> indices;
  UserShapes user;
  std::size_t user_count = 0;
  std::vector<RTCRayHit> prepared;  // prepare(): the records as converted
  std::vector<RTCRayHit> work;      // what the prepared traces consume
  struct alignas(64) Valid16 {      // Embree may load a packet's mask as one 64-byte vector
    int lane[16];
  };
  std::vector<RTCRayHit16> prepared16;  // prepare(rays, true): packets of 16 consecutive rays
  std::vector<RTCRayHit16> work16;
  std::vector<Valid16> valid16;

  RTCScene build(RTCSceneFlags flags) const {
    RTCScene s = rtcNewScene(device);
    rtcSetSceneFlags(s, flags);
    rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_MEDIUM);
    const std::size_t triangles = geometry->triangles.size();
    if (triangles > 0) {
      RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
      rtcSetGeometryBuildQuality(g, RTC_BUILD_QUALITY_MEDIUM);
      rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices.data(), 0, 3 * sizeof(float),
                                 3 * triangles);
      rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices.data(), 0, 3 * sizeof(unsigned),
                                 triangles);
      rtcCommitGeometry(g);
      rtcAttachGeometryByID(s, g, kTriangleGeom);
      rtcReleaseGeometry(g);
    }
    if (user_count > 0) {
      RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
      rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(user_count));
      rtcSetGeometryUserData(g, const_cast<UserShapes*>(&user));
      rtcSetGeometryBoundsFunction(g, user_bounds, nullptr);
      rtcSetGeometryIntersectFunction(g, user_intersect);
      rtcSetGeometryOccludedFunction(g, user_occluded);
      rtcCommitGeometry(g);
      rtcAttachGeometryByID(s, g, kUserGeom);
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(s);
    throw_if_error(device, "building the scene");
    return s;
  }

  // Our Hit for Embree's answer.
  Hit hit_of(unsigned geom, unsigned prim, float t, float u, float v) const {
    Hit h;
    if (geom == RTC_INVALID_GEOMETRY_ID) return h;
    h.t = t;
    h.prim_id = geom == kTriangleGeom ? prim : user.first_id + prim;
    h.u = u;
    h.v = v;
    return h;
  }
};

EmbreeRun::EmbreeRun(const Geometry& geometry, const std::string& isa) : m(std::make_unique<State>()) {
  static_assert(sizeof(Triangle) == 9 * sizeof(float), "the shared vertex buffer needs packed triangles");
  if (!geometry.groups.empty()) throw std::runtime_error("EmbreeReference: groups are not supported");
  m->geometry = &geometry;
  m->vertices.reserve(geometry.triangles.size() + 1);
  m->vertices.assign(geometry.triangles.begin(), geometry.triangles.end());
  m->vertices.emplace_back();
  m->indices.resize(geometry.triangles.size() * 3);
  for (std::size_t i = 0; i < m->indices.size(); ++i) m->indices[i] = static_cast<unsigned>(i);
  m->user.geometry = &geometry;
  m->user.first_id = static_cast<std::uint32_t>(geometry.triangles.size());
  m->user_count = geometry.size() - geometry.triangles.size();
  const std::string config = isa.empty() ? std::string() : "isa=" + isa;
  m->device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
  if (!m->device) throw std::runtime_error("embree: rtcNewDevice failed (configuration '" + config + "')");
  rtcSetDeviceMemoryMonitorFunction(m->device, count_bytes, &m->allocated);
  rebuild();
}

EmbreeRun::~EmbreeRun() {
  if (m->scene) rtcReleaseScene(m->scene);
  if (m->robust) rtcReleaseScene(m->robust);
  rtcReleaseDevice(m->device);
}

double EmbreeRun::rebuild() {
  if (m->scene) rtcReleaseScene(m->scene);
  m->scene = nullptr;
  const long long before = m->allocated.load();  // after the release: only this build counts
  const auto start = std::chrono::steady_clock::now();
  m->scene = m->build(RTC_SCENE_FLAG_NONE);
  const double seconds = seconds_since(start);
  m->scene_bytes = m->allocated.load() - before;
  return seconds;
}

std::size_t EmbreeRun::scene_bytes() const { return static_cast<std::size_t>(std::max(0ll, m->scene_bytes)); }

std::size_t EmbreeRun::user_primitive_count() const { return m->user_count; }

void EmbreeRun::build_robust() {
  if (!m->robust) m->robust = m->build(RTC_SCENE_FLAG_ROBUST);
}

void EmbreeRun::intersect1(std::span<const Ray> rays, std::span<Hit> hits, bool robust) const {
  RTCScene scene = robust ? m->robust : m->scene;
  if (!scene) throw std::logic_error("EmbreeReference: build_robust() was not called");
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    RTCRayHit rh;
    rh.ray = embree_ray(rays[i]);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    hits[i] = m->hit_of(rh.hit.geomID, rh.hit.primID, rh.ray.tfar, rh.hit.u, rh.hit.v);
  }
}

void EmbreeRun::occluded1(std::span<const Ray> rays, std::span<std::uint8_t> occluded, bool robust) const {
  RTCScene scene = robust ? m->robust : m->scene;
  if (!scene) throw std::logic_error("EmbreeReference: build_robust() was not called");
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    RTCRay r = embree_ray(rays[i]);
    rtcOccluded1(scene, &context, &r);
    occluded[i] = r.tfar == -kInf ? 1 : 0;
  }
}

namespace {

// Loads up to 16 rays into an Embree SoA packet; returns the valid mask (-1 valid, 0 not).
template <class Packet>
void load_packet(std::span<const Ray> rays, Packet& p, int (&valid)[16]) {
  for (int k = 0; k < 16; ++k) {
    const bool on = static_cast<std::size_t>(k) < rays.size();
    valid[k] = on ? -1 : 0;
    const Ray r = on ? rays[k] : Ray{};
    p.org_x[k] = r.origin.x, p.org_y[k] = r.origin.y, p.org_z[k] = r.origin.z, p.tnear[k] = r.tmin;
    p.dir_x[k] = r.direction.x, p.dir_y[k] = r.direction.y, p.dir_z[k] = r.direction.z;
    p.tfar[k] = embree_tfar(r.tmax);
    p.time[k] = 0.f, p.mask[k] = ~0u, p.id[k] = 0, p.flags[k] = 0;
  }
}

// Marks every lane of a packet as not hit yet, as rtcIntersect16 requires.
void clear_hits(RTCRayHit16& rh) {
  for (int k = 0; k < 16; ++k) rh.hit.geomID[k] = rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
}

// Calls `trace(context, b, n, valid, packet)` for each run of up to 16 rays [b, b + n) loaded
// into a fresh Embree packet of type Packet (`rays_of(packet)` is its ray part) with the valid
// mask, under one coherent context: the rays of a packet come from neighbouring pixels.
template <class Packet, class RaysOf, class Trace>
void for_each_packet16(std::span<const Ray> rays, RaysOf rays_of, Trace trace) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  for (std::size_t b = 0; b < rays.size(); b += 16) {
    const std::size_t n = std::min<std::size_t>(16, rays.size() - b);
    Packet packet;
    alignas(64) int valid[16];  // Embree may load the mask as one 64-byte vector
    load_packet(rays.subspan(b, n), rays_of(packet), valid);
    trace(context, b, n, valid, packet);
  }
}

}  // namespace

void EmbreeRun::prepare(std::span<const Ray> rays, bool packets) {
  m->prepared.clear(), m->work.clear(), m->prepared16.clear(), m->work16.clear(), m->valid16.clear();
  if (packets) {
    for (std::size_t b = 0; b < rays.size(); b += 16) {
      RTCRayHit16& rh = m->prepared16.emplace_back();
      State::Valid16& valid = m->valid16.emplace_back();
      load_packet(rays.subspan(b, std::min<std::size_t>(16, rays.size() - b)), rh.ray, valid.lane);
      clear_hits(rh);
    }
    m->work16 = m->prepared16;
    return;
  }
  m->prepared.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    m->prepared[i].ray = embree_ray(rays[i]);
    m->prepared[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
    m->prepared[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  m->work = m->prepared;
}

void EmbreeRun::reset_prepared(std::size_t begin, std::size_t end) const {
  if (!m->prepared16.empty()) {
    std::copy(m->prepared16.begin() + static_cast<std::ptrdiff_t>(begin / 16),
              m->prepared16.begin() + static_cast<std::ptrdiff_t>((end + 15) / 16),
              m->work16.begin() + static_cast<std::ptrdiff_t>(begin / 16));
    return;
  }
  std::copy(m->prepared.begin() + static_cast<std::ptrdiff_t>(begin),
            m->prepared.begin() + static_cast<std::ptrdiff_t>(end),
            m->work.begin() + static_cast<std::ptrdiff_t>(begin));
}

void EmbreeRun::intersect1_prepared(std::size_t begin, std::size_t end) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (std::size_t i = begin; i < end; ++i) rtcIntersect1(m->scene, &context, &m->work[i]);
}

void EmbreeRun::occluded1_prepared(std::size_t begin, std::size_t end) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (std::size_t i = begin; i < end; ++i) rtcOccluded1(m->scene, &context, &m->work[i].ray);
}

void EmbreeRun::intersect16_prepared(std::size_t begin, std::size_t end) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  for (std::size_t p = begin / 16; p < (end + 15) / 16; ++p) {
    rtcIntersect16(m->valid16[p].lane, m->scene, &context, &m->work16[p]);
  }
}

void EmbreeRun::occluded16_prepared(std::size_t begin, std::size_t end) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  for (std::size_t p = begin / 16; p < (end + 15) / 16; ++p) {
    rtcOccluded16(m->valid16[p].lane, m->scene, &context, &m->work16[p].ray);
  }
}

void EmbreeRun::prepared_hits(std::span<Hit> hits) const {
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (!m->work16.empty()) {
      const RTCRayHit16& rh = m->work16[i / 16];
      const std::size_t k = i % 16;
      hits[i] = m->hit_of(rh.hit.geomID[k], rh.hit.primID[k], rh.ray.tfar[k], rh.hit.u[k], rh.hit.v[k]);
      continue;
    }
    const RTCRayHit& rh = m->work[i];
    hits[i] = m->hit_of(rh.hit.geomID, rh.hit.primID, rh.ray.tfar, rh.hit.u, rh.hit.v);
  }
}

void EmbreeRun::prepared_occluded(std::span<std::uint8_t> occluded) const {
  for (std::size_t i = 0; i < occluded.size(); ++i) {
    const float tfar = m->work16.empty() ? m->work[i].ray.tfar : m->work16[i / 16].ray.tfar[i % 16];
    occluded[i] = tfar == -kInf ? 1 : 0;
  }
}

void EmbreeRun::intersect16(std::span<const Ray> rays, std::span<Hit> hits) const {
  for_each_packet16<RTCRayHit16>(
      rays, [](RTCRayHit16& rh) -> RTCRay16& { return rh.ray; },
      [&](RTCIntersectContext& context, std::size_t b, std::size_t n, int(&valid)[16], RTCRayHit16& rh) {
        clear_hits(rh);
        rtcIntersect16(valid, m->scene, &context, &rh);
        for (std::size_t k = 0; k < n; ++k) {
          hits[b + k] = m->hit_of(rh.hit.geomID[k], rh.hit.primID[k], rh.ray.tfar[k], rh.hit.u[k], rh.hit.v[k]);
        }
      });
}

void EmbreeRun::occluded16(std::span<const Ray> rays, std::span<std::uint8_t> occluded) const {
  for_each_packet16<RTCRay16>(
      rays, [](RTCRay16& r) -> RTCRay16& { return r; },
      [&](RTCIntersectContext& context, std::size_t b, std::size_t n, int(&valid)[16], RTCRay16& r) {
        rtcOccluded16(valid, m->scene, &context, &r);
        for (std::size_t k = 0; k < n; ++k) occluded[b + k] = r.tfar[k] == -kInf ? 1 : 0;
      });
}

double EmbreeRun::binary_sah_cost(const BvhConfig& config) const {
  const Geometry& g = *m->geometry;
  std::vector<RTCBuildPrimitive> prims;
  prims.reserve(g.size());
  for (std::uint32_t id = 0; id < g.size(); ++id) {
    const Box3 b = g.bounds(id);
    if (!(b.lo.x <= b.hi.x && b.lo.y <= b.hi.y && b.lo.z <= b.hi.z)) continue;  // empty: neither tree holds it
    prims.push_back({b.lo.x, b.lo.y, b.lo.z, 0u, b.hi.x, b.hi.y, b.hi.z, id});
  }
  if (prims.empty()) return 0.0;
  RTCBVH bvh = rtcNewBVH(m->device);
  RTCBuildArguments args = rtcDefaultBuildArguments();
  args.buildQuality = RTC_BUILD_QUALITY_MEDIUM;
  args.maxBranchingFactor = 2;
  args.maxDepth = 64;
  args.minLeafSize = 1;
  args.maxLeafSize =
      static_cast<unsigned>(std::clamp(config.max_leaf_size, 1, static_cast<int>(RTC_BUILD_MAX_PRIMITIVES_PER_LEAF)));
  // Leaves priced per started block as sah_cost prices them (Embree takes a power of two).
  args.sahBlockSize = std::bit_floor(static_cast<unsigned>(std::max(config.leaf_block_size, 1)));
  args.traversalCost = config.traversal_cost;
  args.intersectionCost = config.intersection_cost;
  args.bvh = bvh;
  args.primitives = prims.data();
  args.primitiveCount = prims.size();
  args.primitiveArrayCapacity = prims.size();
  args.createNode = create_node;
  args.setNodeChildren = set_children;
  args.setNodeBounds = set_bounds;
  args.createLeaf = create_leaf;
  auto* root = static_cast<BuildNode*>(rtcBuildBVH(&args));
  if (!root) {
    rtcReleaseBVH(bvh);
    throw_if_error(m->device, "rtcBuildBVH");
    throw std::runtime_error("embree: rtcBuildBVH returned no tree");
  }
  // Flatten into our tree type, each node with the box its parent gave it (the root's: the union
  // of its children, or of all primitives when the root is a leaf), and price it our way.
  RTCBounds root_box = {prims[0].lower_x, prims[0].lower_y, prims[0].lower_z, 0.f,
                        prims[0].upper_x, prims[0].upper_y, prims[0].upper_z, 0.f};
  if (root->count == 0) {
    root_box = merged(root->box[0], root->box[1]);
  } else {
    for (const RTCBuildPrimitive& p : prims) {
      root_box = merged(root_box, {p.lower_x, p.lower_y, p.lower_z, 0.f, p.upper_x, p.upper_y, p.upper_z, 0.f});
    }
  }
  BvhTree tree;
  std::vector<std::pair<const BuildNode*, RTCBounds>> stack{{root, root_box}};
  while (!stack.empty()) {
    const auto [node, box] = stack.back();
    stack.pop_back();
    tree.nodes.push_back(flat_node(box, node->count));
    if (node->count != 0) continue;
    for (int k = 0; k < 2; ++k) {
      if (node->child[k]) stack.emplace_back(node->child[k], node->box[k]);
    }
  }
  rtcReleaseBVH(bvh);
  return sah_cost(tree, config);
}

EmbreeReferenceBackend* make_embree_reference_here(const Geometry& geometry, const std::string& isa) {
  return new EmbreeRun(geometry, isa);
}

#endif

}  // namespace raylab
